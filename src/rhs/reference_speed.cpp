#include "rhs/reference_speed.hpp"

#include <algorithm>
#include <cmath>

#include "core/expression.hpp"

namespace arksph {

double reference_speed(const Scene& scene, double max_initial_speed) {
  const double u_ref = largest_wall_speed(scene, max_initial_speed);
  double length = 0, force = 0;
  for (int k = 0; k < scene.dimension; ++k) {
    length = std::max(length, scene.max[k] - scene.min[k]);
    Expression e(scene.body_force.at(k), {"x", "y", "t"});
    force = std::max(force, std::abs(e.eval(0.5 * (scene.min[0] + scene.max[0]),
                                            0.5 * (scene.min[1] + scene.max[1]), 0.0)));
  }
  return std::max(u_ref, std::sqrt(force * length));
}

double reference_speed(const Scene& scene) { return reference_speed(scene, largest_initial_speed(scene)); }

}  // namespace arksph
