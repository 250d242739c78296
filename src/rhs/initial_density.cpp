#include "rhs/hydrostatic_start.hpp"

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"
#include "core/param_builder.hpp"
#include "core/scheme.hpp"
#include "rhs/body_force_field.hpp"
#include "rhs/term_registry.hpp"

namespace arksph {

const std::vector<Param>& hydrostatic_start_params() {
  static const std::vector<Param> params = {
      flag("initial.hydrostatic", false).schemes({"wcsph"})
          .doc("wcsph: start from the density that the Tait equation gives for the hydrostatic pressure "
               "rho0 g . (r - r_top) of a uniform body force (rho0 g (H - y) under g = (0, -g)); "
               "continuity: initial density, summation: particle masses")
          .to(&Scene::initial_hydrostatic),
  };
  return params;
}

void apply_hydrostatic_start(const Scene& scene, double sound_speed, ParticleSet& p) {
  // The projection schemes keep rho0 (the scene reader warns that the key is unused there).
  if (!scene.initial_hydrostatic || !scheme_traits(scene.scheme).weakly_compressible) return;
  const std::string where = scene.source + ": initial.hydrostatic: ";
  if (scene.equation_of_state != "tait") throw InputError(where + "needs method.equation_of_state = \"tait\"");
  if (!scene.phases.empty()) throw InputError(where + "one phase only (the hydrostatic profile of layers is not built)");
  const BodyForceField force(scene.body_force, scene.dimension);
  if (!force.uniform()) throw InputError(where + "needs a body force uniform in space (fluid.body_force uses x or y)");
  double g[2];
  force.at(0.0, 0.0, 0.0, g);
  // The lowest g . r over the box, at the corner the force points away from (the top under gravity).
  double low = 0;
  for (int k = 0; k < scene.dimension; ++k) low += g[k] * (g[k] > 0 ? scene.min[k] : scene.max[k]);
  const double gamma = scene.tait_gamma;
  const bool density_state = density_modes().at(scene.density_mode).traits.adds_state("density");
  if (density_state) p.init_rho = p.rho0;
  for (std::size_t a = 0; a < p.n; ++a) {
    double gr = 0;
    for (int k = 0; k < scene.dimension; ++k) gr += g[k] * p.init_pos[k][a];
    const double rho0 = p.rho0[a];
    const double ph = std::max(0.0, rho0 * (gr - low));
    const double rho = rho0 * std::pow(1.0 + gamma * ph / (sound_speed * sound_speed * rho0), 1.0 / gamma);
    if (density_state) p.init_rho[a] = rho;
    else p.mass[a] *= rho / rho0;
  }
}

}  // namespace arksph
