// One process's ParticleDomain (particle_domain.hpp): every particle of the model, the evaluator's
// fields, no halo, reductions over the process's own values; the PPE assembled as a sparse matrix
// (ppe_assembly.hpp) and solved by the solver method.ppe_solver names (poisson/poisson_solver.hpp).
#pragma once
#include <memory>
#include <string>

#include "projection/particle_domain.hpp"
#include "projection/ppe_assembly.hpp"
#include "rhs/evaluator.hpp"

namespace arksph {

class LocalPoisson : public ParticlePoisson {
 public:
  // solver: a method.ppe_solver name; exact_operator: C&R eq. 18 (KLU only) in place of eq. 19.
  LocalPoisson(const std::string& solver, double tolerance, bool exact_operator);
  SolveReport solve(const FluidFields& f, const std::vector<double>& source, double dt, std::vector<double>& p) override;
  std::string name() const override { return solver_->name(); }
  void set_given(DirichletRows given) override { given_ = std::move(given); }
  void reset() override { solver_ = make_poisson_solver(solver_->name(), tolerance_); }
  double assembly_seconds() const override { return assembly_seconds_; }

 private:
  double tolerance_;
  bool exact_operator_;
  std::unique_ptr<PoissonSolver> solver_;
  PoissonSystem system_;  // the last equation, kept for its storage
  DirichletRows given_;
  double assembly_seconds_ = 0;
};

class LocalDomain : public ParticleDomain {
 public:
  // With a pressure inside f (scene.pressure_in_f()) the evaluator keeps its pair list at every f.
  LocalDomain(const Scene& scene, RhsEvaluator& rhs);
  StateLayout layout() const override { return rhs_.layout(); }
  void refresh(double t, const double* y) override { rhs_.eval(t, y, nullptr); }
  const FluidFields& fields() const override { return rhs_.fields(); }
  const double* point_velocity(const double* y, int k) const override { return y + rhs_.layout().vel(k); }
  void set_slip_origin(bool on, double t0) override { rhs_.set_slip_origin(on, t0); }
  double level(const std::vector<double>& p, bool zero_min) const override;
  double largest(double x) const override { return x; }
  void sum_in_place(std::vector<double>&) const override {}
  std::vector<double> with_halo(const std::vector<double>& own) const override { return own; }
  std::pair<std::vector<double>, std::vector<double>> with_halo(const std::vector<double>& a,
                                                                const std::vector<double>& b) const override {
    return {a, b};
  }
  CellCombine cell_combine() const override { return {}; }
  CorrectionSpan correction_span() const override { return local_span(rhs_.fields()); }
  std::unique_ptr<ParticlePoisson> poisson(const Scene& scene, bool exact_operator) override;
  RhsEvaluator& evaluator() { return rhs_; }

 private:
  RhsEvaluator& rhs_;
};

}  // namespace arksph
