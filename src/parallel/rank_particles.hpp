// The particles one rank of a decomposed run owns, as ParticleFields records (so that
// migration and the halo move them whole), and their part of the ODE state.
//
// Fields of a record, for dimension d:
//   [0, d)     position as the right-hand side sees it: the state's position brought into the box
//              along the periodic axes at the last halo exchange, and moved with the state since
//              (the halo's f, distributed/halo_rhs.hpp); migration wraps it (migration.hpp)
//   [d, 2d)    position in the state vector (never wrapped: the state is that of a one-process run)
//   [2d, 3d)   velocity
//   then the density (when it is a state variable), the specific energy (likewise), and the
//   constants mass, reference density rho0 and phase.
// The rank's state vector is the usual layout (core/particles.hpp StateLayout) over its particles.
#pragma once
#include <cstdint>
#include <vector>

#include "core/particles.hpp"
#include "parallel/particle_fields.hpp"
#include "parallel/rcb.hpp"

namespace arksph::parallel {

struct RankFieldIndex {
  int dim = 2;
  bool density = false, energy = false;
  int seen(int k) const { return k; }
  int state_pos(int k) const { return dim + k; }
  int vel(int k) const { return 2 * dim + k; }
  int rho() const { return 3 * dim; }
  int e() const { return 3 * dim + (density ? 1 : 0); }
  int mass() const { return 3 * dim + (density ? 1 : 0) + (energy ? 1 : 0); }
  int rho0() const { return mass() + 1; }
  int phase() const { return mass() + 2; }
  int count() const { return mass() + 3; }
  // The fields of the state's blocks in layout order (block b at b * n): the positions (the seen
  // ones with `seen`, else the state's), the velocities, then the density and the energy.
  std::vector<int> state_blocks(bool seen) const {
    std::vector<int> b;
    for (int k = 0; k < dim; ++k) b.push_back(seen ? this->seen(k) : state_pos(k));
    for (int k = 0; k < dim; ++k) b.push_back(vel(k));
    if (density) b.push_back(rho());
    if (energy) b.push_back(e());
    return b;
  }
};

class RankParticles {
 public:
  // The particles of `all` (a whole model's particle set, state y in `layout`) whose position
  // `decomposition` gives to `rank`, in the order of `all`.
  RankParticles(const ParticleSet& all, const StateLayout& layout, const double* y,
                const Decomposition& decomposition, int rank);

  std::size_t size() const { return p_.size(); }
  const RankFieldIndex& index() const { return ix_; }
  ParticleFields& fields() { return p_; }
  const ParticleFields& fields() const { return p_; }
  // The layout of this rank's state vector.
  StateLayout layout() const;
  const std::vector<std::int64_t>& ids() const { return ids_; }

  // This rank's state vector from the fields.
  std::vector<double> state() const;
  // The state fields (state positions, velocities, density, energy) from y (this rank's layout).
  void load(const double* y);
  // The seen positions: the state's wrapped into the box along the periodic axes (at a halo
  // exchange and before a migration).
  void wrap_seen(const Domain& domain);
  // After a migration: the ids follow the records.
  void refresh_ids();
  // The particles re-ordered by cell of side `side` (row-major from `lo`, core/particle_order.hpp)
  // of their seen positions, as one process re-sorts its particles (method.reorder_every), so that
  // neighbours are close in memory: at a deal and after each migration, before the integrator
  // takes the state. Deterministic: the same particles in the same order give the same result.
  void sort_by_cell(const double* lo, double side);

 private:
  RankFieldIndex ix_;
  std::vector<int> blocks_;  // ix_.state_blocks(false)
  ParticleFields p_;
  std::vector<std::int64_t> ids_;
};

}  // namespace arksph::parallel
