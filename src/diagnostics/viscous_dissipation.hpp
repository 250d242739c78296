// The viscous dissipation of the energy budget (diagnostics/energy_budget.hpp),
//   W_visc(t) = - int_0^t P(s) ds,   P = sum_a m_a u_a . a_visc,a,
// by the trapezoid rule over the accepted steps of a run: after a step from t_n to t_{n+1},
//   W += (t_{n+1} - t_n) (P_n + P_{n+1}) / 2,
// P taken at the state the step ends in (after any wall reflection). At a fixed step dt the error
// of W_visc(t) is -(dt^2 / 12) (P'(t) - P'(0)) + O(dt^4) (the trapezoid rule's), second order
// whatever the order of the integrator. W_visc >= 0 when the viscous terms only dissipate; a moving wall's work through the
// viscous terms enters with the opposite sign.
#pragma once

namespace arksph {

class ViscousDissipation {
 public:
  // `earlier`: the dissipation up to the start of this run (a restart's checkpoint; 0 from t = 0).
  explicit ViscousDissipation(double earlier = 0) : total_(earlier) {}
  // The power at the start of the run, at time t.
  void start(double t, double power) {
    t_ = t;
    power_ = power;
  }
  // After an accepted step to t, with the power at its end state.
  void step(double t, double power) {
    total_ -= 0.5 * (t - t_) * (power_ + power);
    t_ = t;
    power_ = power;
  }
  double total() const { return total_; }
  double power() const { return power_; }  // P at the last step's end (or the start)

 private:
  double total_ = 0;
  double t_ = 0, power_ = 0;
};

}  // namespace arksph
