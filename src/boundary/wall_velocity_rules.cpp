// The registered wall-velocity rules: one line each.
#include "boundary/wall_velocity_rules.hpp"

#include "boundary/WallVelocity_Linear_Basa2008.hpp"
#include "boundary/WallVelocity_Quadratic_Basa2008.hpp"

namespace arksph {

namespace {
template <class Rule>
std::unique_ptr<WallVelocityRule> make(const Scene& scene, double dx) {
  return std::make_unique<Rule>(scene, dx);
}
}  // namespace

const Registry<WallVelocityFactory>& wall_velocity_rules() {
  static const Registry<WallVelocityFactory> r("wall_velocity", "boundary.wall_velocity", {
      {"mirror", "ghost velocity 2w - u of its source particle (Szewc et al. 2012 §6)"},
      {"linear", "near-wall shear extrapolated linearly into the wall, 2D (Basa et al. 2008 §6.1.2)", make<LinearWallVelocity>},
      {"quadratic", "quadratic extrapolation through the two nearest fluid rows, 2D (Basa et al. 2008 §6.1.2)", make<QuadraticWallVelocity>},
  });
  return r;
}

}  // namespace arksph
