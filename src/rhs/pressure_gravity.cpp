#include "rhs/pressure_gravity.hpp"

#include "core/errors.hpp"
#include "core/expression.hpp"
#include "core/scheme.hpp"

namespace arksph {

std::vector<double> PressureGravity::head(std::size_t n, const double* x, const double* y) const {
  std::vector<double> h(n);
  for (std::size_t a = 0; a < n; ++a) h[a] = g[0] * x[a] + (y ? g[1] * y[a] : 0.0);
  return h;
}

namespace {
// The body force's components the pressure can take: constant ones along walled axes. None with a
// free surface (fluid.region): there p = 0 but P = p - rho0 g . r varies along the surface, and the
// symmetric gradient of C&R eq. 11 turns P_a sum_b m_b grad W_ab, which a cut kernel support leaves
// non-zero, into a force on the surface particles.
PressureGravity walled_constant_force(const Scene& scene) {
  PressureGravity out;
  if (!scheme_traits(scene.scheme).projection || !scene.fluid_region.empty()) return out;
  for (const PhaseSpec& phase : scene.phases)
    if (phase.density != scene.density) return out;
  for (int k = 0; k < scene.dimension; ++k)
    if (!Expression(scene.body_force.at(static_cast<std::size_t>(k)), {"x", "y", "t"}).is_constant()) return out;
  for (int k = 0; k < scene.dimension; ++k) {
    if (scene.sides[2 * k].kind != SideKind::wall) continue;  // a periodic axis: g drives a flow
    out.g[k] = Expression(scene.body_force.at(static_cast<std::size_t>(k)), {"x", "y", "t"}).eval(0, 0, 0);
    if (out.g[k] != 0.0) out.active = true;
  }
  out.rho0 = scene.density;
  return out;
}
}  // namespace

const Option<BodyForcePressure>& body_force_pressures() {
  static const Option<BodyForcePressure> o("method.body_force_pressure", {
      {"modified", BodyForcePressure::modified}, {"split", BodyForcePressure::split}});
  return o;
}

bool modified_pressure_applies(const Scene& scene) { return walled_constant_force(scene).active; }

PressureGravity pressure_gravity(const Scene& scene) {
  if (scene.body_force_pressure.value() != BodyForcePressure::modified) return {};
  const PressureGravity out = walled_constant_force(scene);
  if (!out.active)
    throw InputError(scene.source + ": method.body_force_pressure = \"modified\" needs a projection scheme, one fluid "
                     "density, no free surface (fluid.region) and a constant fluid.body_force along a walled axis: "
                     "use \"split\"");
  return out;
}

std::vector<std::string> momentum_body_force(const Scene& scene) {
  std::vector<std::string> force = scene.body_force;
  const PressureGravity taken = pressure_gravity(scene);
  for (int k = 0; k < 2 && k < static_cast<int>(force.size()); ++k)
    if (taken.g[k] != 0.0) force[static_cast<std::size_t>(k)] = "0";
  return force;
}

}  // namespace arksph
