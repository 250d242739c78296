// The registered wall-velocity rules: one line each.
#include "boundary/wall_velocity_rules.hpp"

#include "boundary/WallVelocity_Linear_Basa2008.hpp"
#include "boundary/WallVelocity_Quadratic_Basa2008.hpp"
#include "boundary/walled_flow.hpp"

namespace arksph {

namespace {
template <class Rule>
std::unique_ptr<WallVelocityRule> make(const Scene& scene, double dx) {
  return std::make_unique<Rule>(scene, dx);
}

// boundary.wall_velocity = "auto". Mirrored ghosts (Szewc's walls), except beside the transport
// velocity of isph with the P-W correction (a regularisation with the trait quadratic_walls): there
// the walls' dissipation is the larger error left, and Basa's quadratic extrapolation takes it out
// (cavity at Re = 1000: Ghia v r.m.s. 0.040 against 0.056 mirrored, kinetic energy at t = 60 0.037
// against 0.034).
std::string automatic_wall_velocity(const Scene& s, const SelectedParts& parts) {
  return corrected_walled_flow(s, parts) && parts.traits("regularisation").quadratic_walls && s.dimension == 2
             ? "quadratic"
             : "mirror";
}
}  // namespace

const Registry<WallVelocityFactory>& wall_velocity_rules() {
  static const Registry<WallVelocityFactory> r("wall_velocity", "boundary.wall_velocity", {
      {"mirror", "ghost velocity 2w - u of its source particle (Szewc et al. 2012 §6)"},
      {"linear", "near-wall shear extrapolated linearly into the wall, 2D (Basa et al. 2008 §6.1.2)", make<LinearWallVelocity>},
      {"quadratic", "quadratic extrapolation through the two nearest fluid rows, 2D (Basa et al. 2008 §6.1.2)", make<QuadraticWallVelocity>},
  }, {}, {"quadratic beside the transport velocity that isph with the P-W correction takes in a walled flow, else mirror",
          automatic_wall_velocity});
  return r;
}

}  // namespace arksph
