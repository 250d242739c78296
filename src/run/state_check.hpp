// Checks the state after every step: NaN/Inf, blow-up (speed beyond a bound) and particles escaping
// through a wall. Throws NumericalFailure naming the time, the particle id and the quantity.
#pragma once
#include "run/setup.hpp"

namespace arksph {

class StateChecker {
 public:
  StateChecker(const Scene& scene, const Model& model);
  void check(double t, const double* y) const;
  double speed_limit() const { return speed_limit_; }

 private:
  const Scene& scene_;
  const Model& model_;
  double speed_limit_, margin_;
};

}  // namespace arksph
