#include "core/flow_speed.hpp"

#include <algorithm>
#include <cmath>

#include "core/expression.hpp"

namespace arksph {

double largest_wall_speed(const Scene& scene, double u_ref) {
  for (int s = 0; s < 2 * scene.dimension; ++s)
    u_ref = std::max(u_ref, std::hypot(scene.sides[s].velocity[0], scene.sides[s].velocity[1]));
  return u_ref;
}

double largest_initial_speed(const Scene& scene) {
  const bool two_d = scene.dimension == 2;
  Expression eu(scene.initial_velocity.at(0), {"x", "y"});
  Expression ev(two_d ? scene.initial_velocity.at(1) : std::string("0"), {"x", "y"});
  Expression fluid(scene.fluid_region.empty() ? std::string("1") : scene.fluid_region, {"x", "y"});
  const double dx = scene.spacing;
  const long nx = std::max(1L, std::lround((scene.max[0] - scene.min[0]) / dx));
  const long ny = two_d ? std::max(1L, std::lround((scene.max[1] - scene.min[1]) / dx)) : 1;
  double u_max = 0;
  for (long j = 0; j < ny; ++j)
    for (long i = 0; i < nx; ++i) {
      const double x = scene.min[0] + (i + 0.5) * dx, y = two_d ? scene.min[1] + (j + 0.5) * dx : 0.0;
      if (fluid.eval(x, y) == 0.0) continue;  // an empty lattice point (fluid.region)
      u_max = std::max(u_max, std::hypot(eu.eval(x, y), ev.eval(x, y)));
    }
  return u_max;
}

double flow_speed(const Scene& scene) { return largest_wall_speed(scene, largest_initial_speed(scene)); }

}  // namespace arksph
