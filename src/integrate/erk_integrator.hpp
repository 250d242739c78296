// RAII wrapper of SUNDIALS 6.4 ERKStep: explicit Runge-Kutta with a Butcher table chosen by name.
//
// SUNDIALS 6.4.1 bug (fixed in 6.7.0): ERKStep treats every table whose last node is c_s = 1 as
// "first same as last" and reuses the last stage's RHS as f(y_{n+1}), which is wrong unless the
// last row of A equals b. That lowers the order (ARK324 measures 2.0). Installing a post-process
// step function, even one that does nothing, forces ERKStep to recompute f(y_{n+1}). We install it
// exactly for the affected tables (c_s = 1 and A[s-1] != b): one extra RHS per step.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include <sundials/sundials_context.h>
#include <sundials/sundials_nvector.h>

#include "integrate/time_integrator.hpp"

namespace arksph {

using RhsFunction = std::function<void(double t, const double* y, double* ydot)>;
// Returns the largest stable step at state y (adaptive mode only).
using StabilityFunction = std::function<double(double t, const double* y)>;

struct ErkOptions {
  std::string table = "ARKODE_HEUN_EULER_2_1_2";
  double fixed_dt = 0;  // > 0: fixed step; 0: adaptive
  double rtol = 1e-4, atol = 1e-8;
  long max_steps = 100000000;
  StabilityFunction stability;  // adaptive mode: h <= stability(t, y)
  double initial_dt = 0;        // adaptive mode: first step (ERKStep does not apply the stability fn to it)
  bool apply_fsal_workaround = true;
  // Applied to every accepted step, y modified in place (ISPH projection). Installing it also
  // cures the FSAL bug, since ERKStep then recomputes f(y_{n+1}).
  std::function<void(double t, double* y)> postprocess;
  // Applied to every stage z_i, i >= 2, at t_n + c_i h before f(z_i) is evaluated
  // (ERKStepSetPostprocessStageFn): the ISPH "projection after each stage" variant.
  std::function<void(double t, double* y)> postprocess_stage;
};

// Table names accepted by ErkIntegrator: SUNDIALS' built-in ERK tables plus ARKSPH_FORWARD_EULER_1_1.
std::vector<std::string> erk_table_names();
// True when the table triggers the 6.4.1 FSAL bug (c_s = 1 but not first-same-as-last).
bool erk_table_has_fsal_bug(const std::string& name);
// True when the table has an embedding (adaptive stepping possible).
bool erk_table_has_embedding(const std::string& name);
int erk_table_order(const std::string& name);

class ErkIntegrator final : public TimeIntegrator {
 public:
  ErkIntegrator(RhsFunction f, const std::vector<double>& y0, double t0, const ErkOptions& opt);
  ~ErkIntegrator();
  ErkIntegrator(const ErkIntegrator&) = delete;
  ErkIntegrator& operator=(const ErkIntegrator&) = delete;

  // Advances to tout exactly (stop time). Returns the reached time; throws NumericalFailure on error.
  double evolve_to(double tout) override;
  // One internal step, not past tstop.
  double step(double tstop) override;
  double* state() override;
  // Re-initialises the method at (t, state()) after the state was changed outside ARKODE.
  void reset(double t) override;
  std::size_t size() const override { return n_; }
  ErkStats stats() const override;
  bool workaround_installed() const override { return workaround_; }
  // Checkpoints (io/checkpoint.hpp): re-initialises at (t, state()) as a new integrator created
  // there would start (first step h in adaptive mode; the fixed step otherwise), so that a run
  // restarted from the checkpoint continues bit for bit.
  void restart_at(double t, double h) override;
  double next_step() const override;  // the step size ERKStep will attempt next

 private:
  static int rhs_cb(double t, N_Vector y, N_Vector ydot, void* self);
  static int stab_cb(N_Vector y, double t, double* hstab, void* self);
  RhsFunction f_;
  StabilityFunction stab_;
  std::function<void(double, double*)> post_;
  std::function<void(double, double*)> post_stage_;
  SUNContext ctx_ = nullptr;
  N_Vector y_ = nullptr;
  void* mem_ = nullptr;
  std::size_t n_;
  double t_;
  double fixed_dt_ = 0;
  double current_h_ = 0;  // fixed-step mode: the step currently set in ERKStep (the last one may be shorter)
  bool workaround_ = false;
  std::string last_message_;  // last ARKODE warning or error
};

}  // namespace arksph
