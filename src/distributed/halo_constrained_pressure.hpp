// The constrained projection (method.projection = "constrained", projection/ConstrainedPressure.hpp)
// on one rank of a decomposed run: the pressure solved inside f(t, y) at every stage,
//
//   du/dt = a* - G p,   L p = D (a* + alpha u) - Q      (alpha = beta U / h),
//
// over the rank's particles and its halo. After HaloRhs::eval(t, y, ydot) has put a* in the
// velocity block of the rank's ydot:
//   1. w = a* + alpha u of the rank's particles (under a body force with walls, less g), handed to
//      the halo copies by their owners (HaloRhs::halo_values): D w at a particle reads w at its
//      neighbours, and the evaluator computes no derivatives for the copies;
//   2. D w - Q (divergence_minus_motion) for the rank's particles, the copies' velocities being
//      those the evaluator took from their owners (plus, under the body-force split, div g and the
//      Neumann flux of g), and the PPE rows of C&R eq. 19 with global numbers solved by hypre
//      (HaloPoisson, dt = 1), warm-started from the last f's solution;
//   3. p at the scene's level over all ranks (zero mean or zero minimum), handed to the copies, and
//      ydot -= G p (C&R eq. 11, wall points at P_src + rho g . d).
// The start (project_velocity) is one approximate projection u <- u - G phi, L phi = D u, as in one
// process. With method.density_correction = "pozorski_wawrenczuk" the correction is the velocity of
// projection/correction/density_relaxation.hpp added to dr/dt, its Newton direction over the ranks
// (rank_correction_span, as the step-wise correction's). The orthogonal projection is one process's
// (refused on ranks by check_distributable).
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "core/scene.hpp"
#include "distributed/halo_poisson.hpp"
#include "distributed/halo_rhs.hpp"
#include "distributed/rank_particles.hpp"
#include "parallel/communicator.hpp"
#include "projection/body_force_split.hpp"
#include "projection/correction/density_relaxation.hpp"

namespace arksph::distributed {

class HaloConstrainedPressure {
 public:
  // flow_rate: U / h of the whole model (projection/ConstrainedPressure.hpp flow_rate), which sets
  // alpha = beta U / h and the correction's kappa = gamma U / h.
  HaloConstrainedPressure(const Scene& scene, const parallel::Communicator& comm, HaloRhs& f,
                          const RankParticles& owned, std::int64_t pinned_id, double flow_rate);
  // Collective. After f.eval(t, y, ydot): subtracts G p from the velocity block of the rank's ydot.
  distributed_ppe::HypreSolveReport constrain(const double* y, double* ydot);
  // Collective. u <- u - G phi with L phi = D u, the fields refreshed here (the start of a run).
  distributed_ppe::HypreSolveReport project_velocity(double t, double* y);
  // The pressure of the last constrain, the rank's particles.
  const std::vector<double>& pressure() const { return p_; }
  void particles_moved();

 private:
  const parallel::Communicator& comm_;
  HaloRhs& f_;
  const RankParticles& owned_;
  BodyForceSplit split_;
  double relaxation_;
  bool zero_min_level_;
  HaloPoisson poisson_;
  std::vector<double> solution_;  // the pinned system's solution of the last f: the next warm start
  std::vector<double> p_;
  std::unique_ptr<DensityRelaxation> density_;  // the P-W correction inside f, or null
};

}  // namespace arksph::distributed
