// The IMEX split of time.imex (integrate/viscous_split.hpp) on one rank of a decomposed run: f_E
// and f_I of the rank's particles from its HaloRhs (with RhsOptions::imex_split), and J = df_I/dy
// as an operator for ImexIntegrator's Krylov solve (ImexKrylov), where one process assembles J for
// KLU:
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
// As on one process, one full evaluation serves f_E, f_I and J at a state, and f_I at a state that
// differs from it in the velocities only is one pass of the viscous terms. Whether a cached
// evaluation serves is agreed by the ranks (each evaluation is collective).
#pragma once
#include <cstdint>
#include <functional>
#include <vector>

#include "core/scene.hpp"
#include "distributed/halo_rhs.hpp"
#include "distributed/rank_particles.hpp"
#include "integrate/imex_integrator.hpp"
#include "parallel/communicator.hpp"

namespace arksph::distributed {

class HaloViscousSplit {
 public:
  // Switches f to the split evaluation.
  HaloViscousSplit(const Scene& scene, HaloRhs& f, const RankParticles& mine, const parallel::Communicator& comm);
  void explicit_rhs(double t, const double* y, double* ydot);
  void implicit_rhs(double t, const double* y, double* ydot);
  void linearize(double t, const double* y);
  void times(const double* v, double* Jv);
  void diagonal(double* d);
  ImexFunctions functions();
  // A constraint on f_E that must see the whole acceleration (the constrained projection over the
  // ranks), as ViscousSplit::set_constraint: called after each full evaluation with the rank's f_E
  // and f_I's acceleration of the rank's particles. Collective, like the evaluation.
  using Constraint = std::function<void(const double* y, double* fe, const double* au, const double* av)>;
  void set_constraint(Constraint c) {
    constraint_ = std::move(c);
    valid_ = false;
  }
  // Drops the cached evaluation (the particles migrated or were dealt anew).
  void forget() { valid_ = false; }

 private:
  bool everywhere(bool local) const { return -comm_.max(-static_cast<std::int64_t>(local)) > 0; }
  bool frozen_equal(const double* y) const;
  bool cached(const double* y) const;  // collective
  void evaluate_at(double t, const double* y);
  HaloRhs& f_;
  Constraint constraint_;
  const RankParticles& mine_;
  const parallel::Communicator& comm_;
  double radius_ = 0;  // R_dep
  std::vector<double> y_, fe_, fi_;  // the state of the last full evaluation, its f_E and f_I
  double t_ = 0;
  bool valid_ = false;
  long builds_ = -1;  // HaloRhs::builds at that evaluation
  std::vector<double> bu_, bv_, au_, av_;  // the affine part at the last linearize; scratch
  std::vector<double> pu_, pv_, qu_, qv_, ru_, rv_;  // the diagonal's probes (own particles and halo)
};

}  // namespace arksph::distributed
