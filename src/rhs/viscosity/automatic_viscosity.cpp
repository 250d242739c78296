// The automatic rule of the viscosity family (registered in rhs/term_registries.cpp).
#include "core/registry.hpp"
#include "core/scene.hpp"

namespace arksph {

// method.viscosity_model = "auto". Morris et al.'s form (model E) in a fluid that fills its box,
// the setting of the papers' cases. With a free surface (fluid.region), the pair form of Monaghan
// (Szewc eq. 24): Colagrossi, Antuono, Souto-Iglesias & Le Touze (Phys. Rev. E 84, 2011) show that
// Morris' sum over a support the surface cuts does not dissipate what the stress-free surface
// should, while the radial pair form (u_ab . r_ab) grad W_ab does. The standing wave of
// cases/standing_wave (WCSPH, defaults, t = 16): amplitude decay 0.56 (dx = 0.05) and 0.48 (0.025)
// of Lamb's 2 nu k^2 with Morris' form, 0.99 and 0.91 with the pair form; the dam break's front is
// within 0.026 a of Morris' up to the impact.
AutomaticRule automatic_viscosity_model() {
  return {"monaghan with a free surface (fluid.region), else morris", [](const Scene& s, const SelectedParts&) {
            return std::string(s.fluid_region.empty() ? "morris" : "monaghan");
          }};
}

}  // namespace arksph
