// SUNDIALS 6.4 ERKStep: explicit Runge-Kutta with a Butcher table chosen by name. Stepping, restart,
// counters and callback exceptions are those of ArkodeIntegrator (arkode_integrator.hpp).
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

#include "integrate/arkode_integrator.hpp"
#include "integrate/step_options.hpp"

namespace arksph {

struct ErkOptions : StepOptions {
  std::string table = "ARKODE_HEUN_EULER_2_1_2";
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

// The coefficients of a table: stage s of the step reads z_s = y + h sum_j A[s][j] k_j at
// t + c[s] h, the step y + h sum_s b[s] k_s; d is the embedding's weights (empty without one).
struct ErkTable {
  int stages = 0, order = 0, embedded_order = 0;
  std::vector<std::vector<double>> A;
  std::vector<double> b, c, d;
};
// The table of that name (InputError for an unknown name).
ErkTable erk_table(const std::string& name);

class ErkIntegrator final : public ArkodeIntegrator {
 public:
  ErkIntegrator(RhsFunction f, const std::vector<double>& y0, double t0, const ErkOptions& opt);
  bool workaround_installed() const override { return workaround_; }

 private:
  static int rhs_cb(double t, N_Vector y, N_Vector ydot, void* user_data) noexcept;
  void reinit(double t) override;
  StepStats module_stats() const override;
  RhsFunction f_;
  std::function<void(double, double*)> post_;
  std::function<void(double, double*)> post_stage_;
  bool workaround_ = false;
};

}  // namespace arksph
