// Halo exchange: each rank receives copies of the particles that lie within a cut-off distance of
// its box, so that every owned particle finds all its neighbours among owned + halo particles.
//
// Rule: rank q receives particle i (owned by rank r) with the period shift s (s_a in {-L_a, 0, L_a}
// on a periodic axis a, 0 on the others) whenever |x_i + s - box_q| < cutoff (Euclidean distance to
// the box, 0 inside), except s = 0 with r = q (its own particle). The copy's position is x_i + s, so
// it lies next to q's box, where the owned particles see it without any minimum-image test. The rule
// includes r = q with s != 0: a rank whose box spans a periodic axis (one box across the domain,
// always the case on one rank) receives its own particles as periodic images through the halo. The
// halo therefore handles every periodic side; the periodic images of boundary/ghosts are not to be
// combined with it (wall ghosts are a separate matter, docs/parallel.md).
//
// cutoff = support radius + skin: the halo stays valid while no particle has moved more than
// skin / 2 (as the Verlet candidates), and in between `update` refreshes the copies' fields from the
// recorded send lists, with the same shifts, without recomputing any geometry. The cut-off must be
// smaller than every periodic length (one image per side).
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "parallel/communicator.hpp"
#include "parallel/particle_fields.hpp"
#include "parallel/rcb.hpp"

namespace arksph::parallel {

class HaloExchange {
 public:
  // Collective. Computes the send lists from `owned` (normally just after migrate) and replaces
  // `halo` with the received copies: all fields, ids and shifted positions, ordered by source rank,
  // then by the source's particle index, then by shift.
  void exchange(const Communicator& comm, const Decomposition& decomposition, const ParticleFields& owned,
                double cutoff, ParticleFields& halo);
  // The same rule with rank q's box given as boxes[q] (the same list on every rank) instead of its
  // block of the decomposition: a run whose particles have left their blocks since the last
  // migration passes each rank's block grown around its particles (distributed/halo_rhs.hpp).
  void exchange(const Communicator& comm, const Domain& domain, const std::vector<Box>& boxes,
                const ParticleFields& owned, double cutoff, ParticleFields& halo);
  // Collective. Sends the current values of `fields` (indices into ParticleFields::field) of the same
  // particles, with the same shifts added to the coordinates among them, into the same halo slots.
  // `owned` must hold the particles of the last exchange at the same indices (no migration since).
  // One MPI_Alltoallv with the counts of the last exchange (no exchange of counts).
  void update(const Communicator& comm, const ParticleFields& owned, const std::vector<int>& fields,
              ParticleFields& halo) const;
  // The same, and `local` sent to every rank along with the values: returns the largest `local`
  // over the ranks (every rank the same value) without a collective of its own. A decomposed run
  // sends its largest displacement since the exchange this way (distributed/halo_rhs.hpp).
  double update_max(const Communicator& comm, const ParticleFields& owned, const std::vector<int>& fields,
                    ParticleFields& halo, double local) const;

  std::size_t sent() const;  // copies sent by this rank (own periodic images included)
  std::size_t received() const { return received_; }
  const std::vector<std::size_t>& received_per_rank() const { return received_per_rank_; }

 private:
  struct Entry {
    std::uint32_t index;  // particle of `owned`
    std::uint32_t shift;  // index into shifts_
  };
  std::vector<std::vector<Entry>> send_;  // per destination rank
  std::vector<std::array<double, 3>> shifts_;
  std::vector<std::size_t> received_per_rank_;
  std::size_t received_ = 0;
};

}  // namespace arksph::parallel
