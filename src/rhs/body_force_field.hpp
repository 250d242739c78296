// The body force g(x, y, t) of the scene (fluid.body_force) as the wall treatment needs it: the
// hydrostatic pressure step of a wall ghost (rhs/ghost_field.hpp), the Neumann data of the
// projection's pressure equation and the body-force part of its source (projection/wall_neumann.hpp).
// Components that are constants are evaluated once; the others per call (not thread-safe).
#pragma once
#include <string>
#include <vector>

#include "core/expression.hpp"

namespace arksph {

class BodyForceField {
 public:
  BodyForceField(const std::vector<std::string>& expr, int dim);
  // Every component is the constant 0: the wall treatment is that of a scene without body force.
  bool zero() const { return zero_; }
  // No component depends on x or y (it may depend on t): div g = 0.
  bool uniform() const { return uniform_; }
  // g at (x, y) and time t; g[1] = 0 in 1D.
  void at(double x, double y, double t, double g[2]) const;

 private:
  int dim_;
  std::vector<Expression> expr_;
  std::vector<bool> constant_;
  std::vector<double> value_;
  bool zero_ = true, uniform_ = true;
};

}  // namespace arksph
