#include "rhs/density/initial_density.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "core/errors.hpp"
#include "core/expression.hpp"
#include "core/param_builder.hpp"
#include "core/scheme.hpp"
#include "rhs/body_force_field.hpp"
#include "rhs/term_registry.hpp"

namespace arksph {

namespace {
// initial.pressure's default: no pressure field given.
const std::string kNoInitialPressure = "0";
}  // namespace

const std::vector<Param>& initial_density_params() {
  static const std::vector<Param> params = {
      flag("initial.hydrostatic", false).schemes({"wcsph"})
          .doc("wcsph: start from the density that the Tait equation gives for the hydrostatic pressure "
               "rho0 g . (r - r_top) of a uniform body force (rho0 g (H - y) under g = (0, -g)), "
               "with the particle masses scaled by rho / rho0 (each volume m / rho its lattice cell)")
          .to(&Scene::initial_hydrostatic),
      text("initial.pressure", kNoInitialPressure).schemes({"wcsph"}).unit("Pa")
          .doc("wcsph: pressure p(x, y) at t = 0, an expression; the initial density is the Tait "
               "equation's for it (added to initial.hydrostatic's, the masses scaled by rho / rho0), so a "
               "flow that carries pressure starts without pressure waves")
          .to(&Scene::initial_pressure),
  };
  return params;
}

namespace {

// rho0 (g . r - low) for the uniform body force. `low` is the level of the fluid's top: the minimum
// of g . r over the box, or with fluid.region (a free surface) over the particles, half a spacing
// beyond the topmost (a flat surface at the top of the fluid; below a surface that is not flat the
// profile is the one of its highest point).
struct HydrostaticPressure {
  double g[2] = {0, 0};
  double low = 0;
  HydrostaticPressure(const Scene& scene, const ParticleSet& p, const std::string& where) {
    if (!scene.phases.empty()) throw InputError(where + "one phase only (the hydrostatic profile of layers is not built)");
    const BodyForceField force(scene.body_force, scene.dimension);
    if (!force.uniform()) throw InputError(where + "needs a body force uniform in space (fluid.body_force uses x or y)");
    force.at(0.0, 0.0, 0.0, g);
    // The lowest g . r over the box, at the corner the force points away from (the top under gravity).
    for (int k = 0; k < scene.dimension; ++k) low += g[k] * (g[k] > 0 ? scene.min[k] : scene.max[k]);
    if (scene.fluid_region.empty() || p.n == 0) return;
    low = std::numeric_limits<double>::infinity();
    for (std::size_t a = 0; a < p.n; ++a) {
      double gr = 0;
      for (int k = 0; k < scene.dimension; ++k) gr += g[k] * p.init_pos[k][a];
      low = std::min(low, gr);
    }
    for (int k = 0; k < scene.dimension; ++k) low -= 0.5 * scene.spacing * std::abs(g[k]);
  }
  double at(double rho0, const double* r, int dim) const {
    double gr = 0;
    for (int k = 0; k < dim; ++k) gr += g[k] * r[k];
    return std::max(0.0, rho0 * (gr - low));
  }
};

}  // namespace

void apply_initial_density(const Scene& scene, double sound_speed, ParticleSet& p) {
  // The projection schemes keep rho0 (the scene reader warns that the keys are unused there).
  const bool given = scene.initial_pressure != kNoInitialPressure;
  if ((!scene.initial_hydrostatic && !given) || !scheme_traits(scene.scheme).weakly_compressible) return;
  const std::string key = scene.initial_hydrostatic ? "initial.hydrostatic" : "initial.pressure";
  if (!equations_of_state().at(scene.equation_of_state).traits.tait)
    throw InputError(scene.source + ": " + key + ": needs method.equation_of_state = \"tait\"");
  std::optional<HydrostaticPressure> hydrostatic;
  if (scene.initial_hydrostatic) hydrostatic.emplace(scene, p, scene.source + ": initial.hydrostatic: ");
  const Expression pressure = [&] {
    try {
      return Expression(scene.initial_pressure, {"x", "y"});
    } catch (const InputError& e) {
      throw InputError(scene.source + ": initial.pressure: " + e.what());
    }
  }();

  const double gamma = scene.tait_gamma;
  const bool density_state = density_modes().at(scene.density_mode).traits.adds_state("density");
  if (density_state) p.init_rho = p.rho0;
  for (std::size_t a = 0; a < p.n; ++a) {
    const double r[2] = {p.init_pos[0][a], scene.dimension > 1 ? p.init_pos[1][a] : 0.0};
    const double rho0 = p.rho0[a];
    double p0 = given ? pressure.eval(r[0], r[1]) : 0.0;
    if (hydrostatic) p0 += hydrostatic->at(rho0, r, scene.dimension);
    const double base = 1.0 + gamma * p0 / (sound_speed * sound_speed * rho0);
    if (!std::isfinite(p0) || !(base > 0))
      throw InputError(scene.source + ": initial.pressure: " + message_number(p0) + " at the particle at (" +
                       message_number(r[0]) + ", " + message_number(r[1]) +
                       ") is not finite or below the Tait equation's floor -rho0 c^2 / gamma = " +
                       message_number(-rho0 * sound_speed * sound_speed / gamma));
    const double rho = rho0 * std::pow(base, 1.0 / gamma);
    if (density_state) p.init_rho[a] = rho;
    p.mass[a] *= rho / rho0;
  }
}

}  // namespace arksph
