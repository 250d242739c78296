// The interface of the run loop to its time integrator: ERKStep (explicit, erk_integrator.hpp) or
// ARKStep IMEX with the viscous term implicit (imex_integrator.hpp). Both advance one ODE state
// vector y in the layout of rhs/evaluator.hpp.
#pragma once
#include <cstddef>

namespace arksph {

// The counters of a time integrator (ERKStep or ARKStep), cumulative over the run.
struct StepStats {
  long steps = 0, rhs_evals = 0, attempts = 0, error_test_fails = 0;
  double last_step = 0;
  // IMEX only (zero for ERKStep): implicit RHS evaluations, Newton iterations and failures,
  // linear-solver setups (Newton matrix M = I - gamma J and its KLU factorisation), Jacobian
  // evaluations and KLU symbolic analyses.
  long implicit_rhs_evals = 0, newton_iters = 0, newton_fails = 0, linear_setups = 0, jacobian_evals = 0,
       symbolic_analyses = 0, linear_iters = 0;  // linear_iters: Krylov iterations (imex_krylov.cpp)
};

class TimeIntegrator {
 public:
  virtual ~TimeIntegrator() = default;
  // Advances to tout exactly (stop time). Returns the reached time; throws NumericalFailure on error.
  virtual double evolve_to(double tout) = 0;
  // One internal step, not past tstop.
  virtual double step(double tstop) = 0;
  virtual double* state() = 0;
  // Re-initialises the method at (t, state()) after the state was changed outside ARKODE.
  virtual void reset(double t) = 0;
  virtual std::size_t size() const = 0;
  virtual StepStats stats() const = 0;
  // True when the SUNDIALS 6.4.1 FSAL workaround is installed (ERKStep only).
  virtual bool workaround_installed() const { return false; }
  // Re-initialises at (t, state()) as a new integrator created there would start (checkpoints).
  virtual void restart_at(double t, double h) = 0;
  virtual double next_step() const = 0;  // the step size the integrator will attempt next
  // Counters of the run before a restart, added to stats().
  void set_counter_offset(const StepStats& offset) { offset_ = offset; }

 protected:
  StepStats offset_{};
};

}  // namespace arksph
