// One rank's ParticleDomain (projection/particle_domain.hpp) in a decomposed run: the rank's own
// particles (the state it integrates), the fields of HaloRhs's evaluator over them and their halo,
// and the collectives over every rank. With it the projection after a step, the constrained
// projection and the grid projection of projection/ run on ranks as written:
//   - refresh: HaloRhs::eval(t, y, nullptr), the halo copies taking the state's positions and
//     velocities from their owners; a failure on one rank (a blown-up neighbour grid) fails on
//     all, with its message, since the others would otherwise wait in the solve's collectives;
//   - level: the minimum or the mean over every rank's particles;
//   - with_halo: the own values followed by the halo copies', from their owners (one all-to-all);
//   - cell_combine: the grid's cell sums and maxima all-reduced, so that every rank solves the whole
//     grid problem (the grid is replicated: its memory and the all-reduce of 8 numbers a cell do not
//     shrink with the rank count);
//   - poisson: HaloPoisson (distributed_ppe/halo_poisson.hpp), the PPE's rows with global numbers
//     solved by hypre, one particle (a global id fixed for the run) pinned to P = 0, as one process pins its
//     particle 0. With unequal particle volumes the Neumann system is only approximately consistent
//     and the pinned particle shows in the solution at the level of the inconsistency
//     (docs/parallel.md); one process's particle 0 changes with its re-sorts.
// What runs on one process only (refused on several ranks by check_distributable): the orthogonal
// projection, the density correction's KINSOL solver, and the exact operator (C&R eq. 18).
#pragma once
#include <cstdint>

#include "distributed/halo_rhs.hpp"
#include "parallel/communicator.hpp"
#include "parallel/rank_particles.hpp"
#include "projection/particle_domain.hpp"

namespace arksph::distributed {

class HaloDomain : public ParticleDomain {
 public:
  // pinned_id: the global id of the particle whose pressure is pinned to 0 for the whole run.
  HaloDomain(const parallel::Communicator& comm, HaloRhs& f, parallel::RankParticles& owned, std::int64_t pinned_id)
      : comm_(comm), f_(f), owned_(owned), pinned_id_(pinned_id) {}
  StateLayout layout() const override { return owned_.layout(); }
  void refresh(double t, const double* y) override;
  const FluidFields& fields() const override { return f_.evaluator().fields(); }
  const double* point_velocity(const double*, int k) const override {
    return f_.evaluated_state() + f_.evaluator().layout().vel(k);
  }
  void set_slip_origin(bool on, double t0) override { f_.set_slip_origin(on, t0); }
  double level(const std::vector<double>& p, bool zero_min) const override;
  double largest(double x) const override { return comm_.max(x); }
  void sum_in_place(std::vector<double>& v) const override { comm_.sum_in_place(v); }
  std::vector<double> with_halo(const std::vector<double>& own) const override;
  std::pair<std::vector<double>, std::vector<double>> with_halo(const std::vector<double>& a,
                                                                const std::vector<double>& b) const override;
  CellCombine cell_combine() const override;
  CorrectionSpan correction_span() const override;
  std::unique_ptr<ParticlePoisson> poisson(const Scene& scene, bool exact_operator) override;

 private:
  const parallel::Communicator& comm_;
  HaloRhs& f_;
  parallel::RankParticles& owned_;
  std::int64_t pinned_id_;
};

}  // namespace arksph::distributed
