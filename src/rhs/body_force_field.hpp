// The body force g(x, y, t) of the scene (fluid.body_force) as the wall treatment needs it: the
// hydrostatic pressure step of a wall ghost (rhs/ghost_field.hpp), the Neumann data of the
// projection's pressure equation and the body-force part of its source (projection/ppe_assembly.hpp).
// Components that are constants are evaluated once; the others per call (not thread-safe).
#pragma once
#include <string>
#include <vector>

#include "core/expression.hpp"
#include "core/scene.hpp"

namespace arksph {

class BodyForceField {
 public:
  BodyForceField(const std::vector<std::string>& expr, int dim);
  // The same with the walled axes of the scene (walled_at).
  BodyForceField(const std::vector<std::string>& expr, const Scene& scene);
  // Every component is the constant 0: the wall treatment is that of a scene without body force.
  bool zero() const { return zero_; }
  // No component depends on x or y (it may depend on t): div g = 0.
  bool uniform() const { return uniform_; }
  // g at (x, y) and time t; g[1] = 0 in 1D.
  void at(double x, double y, double t, double g[2]) const;
  // The components along the axes bounded by walls, the others 0. A mean pressure gradient can
  // balance g only along such an axis (along a periodic one the pressure is periodic: g drives a
  // flow, as in a channel).
  void walled_at(double x, double y, double t, double g[2]) const {
    at(x, y, t, g);
    for (int k = 0; k < 2; ++k)
      if (!walled_[k]) g[k] = 0.0;
  }
  void set_walled_axes(bool x_walls, bool y_walls) { walled_[0] = x_walls, walled_[1] = y_walls; }

 private:
  int dim_;
  std::vector<Expression> expr_;
  std::vector<bool> constant_;
  std::vector<double> value_;
  bool zero_ = true, uniform_ = true;
  bool walled_[2] = {true, true};
};

}  // namespace arksph
