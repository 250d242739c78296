#include "boundary/walled_flow.hpp"

#include "core/flow_speed.hpp"
#include "core/param_builder.hpp"
#include "core/scheme.hpp"

namespace arksph {

bool corrected_walled_flow(const Scene& s, const SelectedParts& parts) {
  bool wall = false;
  for (int i = 0; i < 2 * s.dimension; ++i) wall |= s.sides[i].kind == SideKind::wall;
  return wall && scheme_traits(s.scheme).particle_poisson() && !s.pressure_in_f() &&
         parts.traits("density_correction").corrects_density && flow_speed(s) > 0;
}

namespace {
// boundary.free_slip_divergence = "auto". The cavity (Re = 1000) needs the free-slip images for
// isph-gpps (the run blows up by t ~ 0.8 without them) and for wcsph, where the no-slip divergence
// at the lid corners gives a negative density by t ~ 0.07 (Re = 100: the same). isph with C&R eq. 17
// does not read them; walls at rest under wcsph keep the no-slip images (Poiseuille, Basa's setting),
// except below a free surface: in the dam break (a column a x 2a, 40 x 80 particles, up to its
// impact on the far wall) the floor's no-slip images behind the surge's tip, their tangential
// velocity reversed, put a false compression of order 2 U into the tip's continuity equation; the
// floor particles at the tip then reach 2-3 times the front speed with pressures of -40 to +50
// rho g a. With the free-slip images the largest speed is the tip's (within 7 %) and the pressure
// stays within [-0.7, 1.9] rho g a. isph below a free surface reads them through the difference
// divergence (method.ppe_divergence's rule) for the same reason: with the no-slip images the
// tip's source reads a compression, its pressure lifts the tip off the floor and the surge sprays
// ahead (the a/20 dam break's front 0.3-0.5 a ahead of wcsph's by the impact, 0.02 a with them).
std::string automatic_free_slip_divergence(const Scene& s) {
  bool wall = false, moving = false;
  for (int i = 0; i < 2 * s.dimension; ++i) {
    if (s.sides[i].kind != SideKind::wall) continue;
    wall = true;
    moving |= s.sides[i].velocity[0] != 0 || s.sides[i].velocity[1] != 0;
  }
  const SchemeTraits& scheme = scheme_traits(s.scheme);
  const bool surface = !s.fluid_region.empty();
  return wall && (scheme.grid || surface || (scheme.weakly_compressible && moving)) ? "true" : "false";
}
}  // namespace

Param free_slip_divergence_param() {
  return flag("boundary.free_slip_divergence", false)
      .doc("free-slip images for the velocity divergence only (Szewc et al. 2012 §6); auto: true with walls for isph-gpps, when the fluid has a free surface (fluid.region), and for wcsph when a wall moves; else false")
      .automatic(automatic_free_slip_divergence)
      .to(&Scene::free_slip_divergence);
}

}  // namespace arksph
