// The automatic rule of the regularisation family (registered in rhs/term_registries.cpp).
#include "boundary/walled_flow.hpp"
#include "core/registry.hpp"
#include "core/scene.hpp"

namespace arksph {

// method.regularisation = "auto". Particle shifting for every scheme: on the Taylor-Green vortex
// (Re = 100, 50 x 50, t = 1) it brings the relative L1 velocity error from 0.42 to 0.003 (isph,
// constrained projection), 0.51 to 0.05 (isph-gpps) and 0.73 to 0.003 (wcsph, with delta-SPH), and
// it keeps the walled spin-down's density error at a fiftieth (docs/methods/regularisation.md).
// Where the P-W correction already holds the particles at the reference density in a walled flow,
// Adami's transport velocity: it dissipates less than shifting and imposes no step limit. Cavity at
// Re = 1000, 60 x 60, t = 60, with the quadratic wall velocity that comes with it: Ghia r.m.s.
// 0.026 / 0.038 in 8,041 steps, against shifting's 0.055 / 0.077 in 42,600 (cases/cavity_re1000).
AutomaticRule automatic_regularisation() {
  return {"transport_velocity for isph with the P-W correction in a walled flow, else shifting",
          [](const Scene& s, const SelectedParts& parts) {
            return std::string(corrected_walled_flow(s, parts) ? "transport_velocity" : "shifting");
          }};
}

}  // namespace arksph
