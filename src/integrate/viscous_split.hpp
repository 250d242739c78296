// The additive split of the particle ODE for time.imex: f = f_E + f_I with f_I the viscous
// acceleration (velocity block only) and f_E everything else (positions' rate, pressure, body
// force, continuity, energy). Implicit viscosity removes the explicit viscous step limit
// 0.125 h^2 / nu (Szewc et al. 2012 eq. 36).
//
// ARKStep asks for f_E, f_I and J at overlapping states; one full RHS evaluation serves all three
// at a given state. During a stage solve only the velocities change, so f_I there is one pass of
// the viscous terms over the frozen fields (RhsEvaluator::viscous_acceleration), and J is
// re-probed only when the frozen part of the state (positions, densities, energies) has changed.
//
// SplitCache holds that caching over a SplitSource: one process's evaluator, or a rank's evaluation
// over its halo in a decomposed run (distributed/halo_rhs.hpp). J = df_I/dy comes in two forms:
// ViscousSplit assembles it for KLU (one process); KrylovViscousSplit applies it as an operator for
// the Krylov solve of the stages (ImexKrylov), over any source (the ranks' form, which one process
// can run too: the tests compare it with the assembled J).
#pragma once
#include <functional>
#include <memory>
#include <vector>

#include "core/scene.hpp"
#include "integrate/dependency_pattern.hpp"
#include "integrate/imex_integrator.hpp"
#include "integrate/viscous_jacobian.hpp"
#include "rhs/evaluator.hpp"

namespace arksph {

// The evaluation a split caches: f of the particles this process integrates.
class SplitSource {
 public:
  virtual ~SplitSource() = default;
  virtual StateLayout layout() const = 0;  // of the state integrated here
  // The whole f (f_E with RhsOptions::imex_split), then f_I of that evaluation.
  virtual void eval(double t, const double* y, double* ydot) = 0;
  virtual void implicit_part(double* ydot_i) = 0;
  // f_I's acceleration for the velocities (u, v) of this process's particles at the frozen fields
  // of the last eval (v, av unused in 1D).
  virtual void viscous_acceleration(const double* u, const double* v, double* au, double* av) = 0;
  // Changes when the source builds its particle set anew (a rank's halo exchange): an evaluation
  // cached before then does not serve.
  virtual long builds() const { return 0; }
  // Whether `local` holds on every process (collective over ranks).
  virtual bool everywhere(bool local) const { return local; }
  // The evaluator of the last eval: its points are this process's particles first, then (on a
  // rank) the copies of other ranks' particles.
  virtual RhsEvaluator& evaluator() = 0;
};

// One process's evaluator as a split's source, switched to the split evaluation
// (RhsOptions::imex_split).
std::unique_ptr<SplitSource> evaluator_source(RhsEvaluator& rhs);

class SplitCache {
 public:
  explicit SplitCache(std::unique_ptr<SplitSource> f) : f_(std::move(f)) {}
  void explicit_rhs(double t, const double* y, double* ydot);
  void implicit_rhs(double t, const double* y, double* ydot);
  // A constraint on f_E that must see the whole acceleration (the constrained projection): called
  // after each full evaluation as constraint(y, f_E, au_I, av_I) with f_I's acceleration.
  using Constraint = std::function<void(const double* y, double* fe, const double* au, const double* av)>;
  void set_constraint(Constraint c) {
    constraint_ = std::move(c);
    valid_ = false;
  }
  // Drops the cached evaluation (the particles were re-ordered, migrated or dealt anew).
  void forget() { valid_ = false; }

 protected:
  // Whether y matches ref on every row outside the velocity block.
  bool frozen_equal(const double* y, const std::vector<double>& ref) const;
  // Whether the cached evaluation holds the frozen fields of y (on every process).
  bool cached(const double* y) const {
    return f_->everywhere(valid_ && builds_ == f_->builds() && frozen_equal(y, y_));
  }
  void evaluate_at(double t, const double* y);
  SplitSource& source() { return *f_; }

 private:
  std::unique_ptr<SplitSource> f_;
  Constraint constraint_;
  std::vector<double> y_, fe_, fi_;  // the state of the last full evaluation, its f_E and f_I
  double t_ = 0;
  bool valid_ = false;
  long builds_ = -1;  // SplitSource::builds at that evaluation
  std::vector<double> au_, av_;
};

// One process: the evaluator's split, and J = df_I/dy assembled for KLU.
class ViscousSplit : public SplitCache {
 public:
  // Switches rhs to the split evaluation (RhsOptions::imex_split).
  ViscousSplit(const Scene& scene, RhsEvaluator& rhs);
  const SparseCsr& jacobian(double t, const double* y);
  ImexFunctions functions();
  const ViscousJacobian& jacobian_builder() const { return jac_; }
  // Drops every cached evaluation and the Jacobian pattern (the particles were re-ordered).
  void forget() {
    SplitCache::forget();
    jac_last_ = nullptr;
    jac_y_.clear();
    jac_.invalidate();
  }

 private:
  RhsEvaluator& rhs_;
  ViscousJacobian jac_;
  std::vector<double> jac_y_;  // the state J was probed at (frozen rows matter)
  const SparseCsr* jac_last_ = nullptr;
};

// J as an operator (2D), for ImexFunctions::krylov:
//   J v   the viscous acceleration of the velocities of v minus that of zero velocities (the affine
//         part: wall velocities), at the frozen fields of the stage (f_I is affine in the
//         velocities once positions, densities and kernel corrections are frozen); a rank's halo
//         copies take their owners' entries of v (SplitSource::viscous_acceleration);
//   diag  d_a = d(a_visc,a)/du_a, probed by a distance-1 colouring of the evaluator's points over
//         the dependency radius R_dep (viscous_jacobian.hpp): with colour c set to 1 and every
//         other velocity 0, particle a of colour c has no other point of colour c within R_dep,
//         so its acceleration minus the affine part is its diagonal entry. The probes are the
//         process's own (no communication): a halo copy's probe value need not be its owner's,
//         since only the process's own rows are kept.
class KrylovViscousSplit : public SplitCache {
 public:
  // axes: the periodic axes of the evaluator's positions (none on a rank, whose halo copies carry
  // the periodic images).
  KrylovViscousSplit(const Scene& scene, std::unique_ptr<SplitSource> source, PeriodicAxes axes);
  void linearize(double t, const double* y);
  void times(const double* v, double* Jv);
  void diagonal(double* d);
  ImexFunctions functions();

 private:
  PeriodicAxes axes_;
  double radius_ = 0;                      // R_dep
  std::vector<double> bu_, bv_, au_, av_;  // the affine part at the last linearize; scratch
  std::vector<double> pu_, pv_, qu_, qv_;  // the diagonal's probes (every point of the evaluator)
};

}  // namespace arksph
