// The registered wall-velocity rules: one line each.
#include "boundary/wall_velocity_rules.hpp"

namespace arksph {

const Registry<Selected>& wall_velocity_rules() {
  static const Registry<Selected> r("wall_velocity", "boundary.wall_velocity", {
      {"mirror", "ghost velocity 2w - u of its source particle (Szewc et al. 2012 §6)"},
      {"linear", "near-wall shear extrapolated linearly into the wall, 2D (Basa et al. 2008 §6.1.2)"},
      {"quadratic", "quadratic extrapolation through the two nearest fluid rows, 2D (Basa et al. 2008 §6.1.2)"},
  });
  return r;
}

}  // namespace arksph
