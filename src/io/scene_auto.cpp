#include "io/scene_auto.hpp"

namespace arksph {

void resolve_auto_values(Scene& s) {
  // The constrained projection has the integrator's temporal order and, with shifting, the
  // smallest errors measured on the Taylor-Green vortex (docs/methods/regularisation.md); C&R's
  // projection after each step where a key needs it.
  if (s.projection == "auto") {
    const bool needs_cummins_rudman = s.density_correction != "none" || s.projection_points != "step" ||
                                      s.ppe_operator != "approximate";
    s.projection = s.scheme == "isph" && !needs_cummins_rudman ? "constrained" : "cummins_rudman";
  }
  // Particle shifting for every scheme: it keeps the particles regular inside f(t, y).
  if (s.regularisation == "auto") s.regularisation = "shifting";
  // delta-SPH damps WCSPH's pressure noise; it acts on the continuity equation only.
  if (s.density_diffusion == "auto")
    s.density_diffusion = s.scheme == "wcsph" && s.density_mode == "continuity" ? "delta_sph" : "none";
}

}  // namespace arksph
