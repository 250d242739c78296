// The IMEX split of time.imex (integrate/viscous_split.hpp: SplitCache) on one rank of a decomposed
// run: f_E and f_I of the rank's particles from its HaloRhs (with RhsOptions::imex_split), whether a
// cached evaluation serves agreed by the ranks (each evaluation is collective), and J = df_I/dy as
// an operator for ImexIntegrator's Krylov solve (ImexKrylov), where one process assembles J for KLU:
//   J v   the viscous acceleration of the velocities of v minus that of zero velocities (the affine
//         part: wall velocities), at the frozen fields of the stage (f_I is affine in the
//         velocities once positions, densities and kernel corrections are frozen); the halo
//         copies take their owners' entries of v (one all-to-all per product);
//   diag  d_a = d(a_visc,a)/du_a, probed by a distance-1 colouring of the rank's particles and halo
//         copies over the dependency radius R_dep (integrate/viscous_jacobian.hpp): with colour c
//         set to 1 and every other velocity 0, particle a of colour c has no other particle of
//         colour c within R_dep, so its acceleration minus the affine part is its diagonal entry.
//         The probes are the rank's own (no communication): a halo copy's probe value need not be
//         its owner's, since only the rank's own rows are kept.
#pragma once
#include <vector>

#include "core/scene.hpp"
#include "distributed/halo_rhs.hpp"
#include "distributed/rank_particles.hpp"
#include "integrate/imex_integrator.hpp"
#include "integrate/viscous_split.hpp"
#include "parallel/communicator.hpp"

namespace arksph::distributed {

class HaloViscousSplit : public SplitCache {
 public:
  // Switches f to the split evaluation.
  HaloViscousSplit(const Scene& scene, HaloRhs& f, const RankParticles& mine, const parallel::Communicator& comm);
  void linearize(double t, const double* y);
  void times(const double* v, double* Jv);
  void diagonal(double* d);
  ImexFunctions functions();

 private:
  HaloRhs& f_;
  const RankParticles& mine_;
  double radius_ = 0;  // R_dep
  std::vector<double> bu_, bv_, au_, av_;  // the affine part at the last linearize; scratch
  std::vector<double> pu_, pv_, qu_, qv_;  // the diagonal's probes (own particles and halo)
};

}  // namespace arksph::distributed
