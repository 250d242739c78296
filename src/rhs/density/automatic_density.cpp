// The automatic rules of the density families (registered in rhs/term_registries.cpp).
#include "core/registry.hpp"
#include "core/scene.hpp"
#include "core/scheme.hpp"

namespace arksph {

// method.density_mode = "auto". wcsph with phases: the summation density (Szewc eq. 21); with the
// continuity equation the Rayleigh-Taylor case blows up at t ~ 0.85. One phase, and the projection
// schemes (whose density is not in the state): continuity (Szewc eq. 19), the setting of the cavity
// and Poiseuille cases.
AutomaticRule automatic_density_mode() {
  return {"summation for wcsph with a [[phase]], else continuity", [](const Scene& s, const SelectedParts&) {
            return std::string(scheme_traits(s.scheme).weakly_compressible && !s.phases.empty() ? "summation"
                                                                                                : "continuity");
          }};
}

// method.density_diffusion = "auto". delta-SPH damps WCSPH's pressure noise where the density is a
// state (the continuity equation); nothing to diffuse otherwise.
AutomaticRule automatic_density_diffusion() {
  return {"delta_sph for wcsph with the continuity equation, else none", [](const Scene& s, const SelectedParts& parts) {
            return std::string(scheme_traits(s.scheme).weakly_compressible &&
                                       parts.traits("density_mode").adds_state("density")
                                   ? "delta_sph"
                                   : "none");
          }};
}

}  // namespace arksph
