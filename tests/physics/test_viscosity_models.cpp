// The viscous models of Basa et al. 2008 (A direct, B two_pass, C violeau, D cleary, E morris),
// Monaghan's form and any other registered model: nu lap u of a known field on a walled lattice, no
// force for uniform flow, Galilean invariance, and momentum conservation of the symmetric ones. The
// tests loop over registered_names("viscosity_model").
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "run/setup.hpp"
#include "io/names.hpp"
#include "io/scene_reader.hpp"
#include "rhs/term_registry.hpp"
#include "rhs/terms.hpp"
#include "test_support.hpp"

using namespace arksph;

namespace {

// A channel periodic in x with no-slip (mirror) walls at y = 0 and y = 1, 20 x 20 particles, the
// Poiseuille case's kernel (quintic spline) at h = 1.5 dx. u = (sin(pi y), 0) is odd
// about both walls, so the mirrored ghosts continue it exactly: nu lap u = -nu pi^2 sin(pi y) holds
// for every particle, wall rows included. Density and pressure stay uniform (p = 0), so du/dt is the
// viscous term alone.
const std::string kViscosityChannel = R"toml(
[scene]
name = "viscous_lattice"
[domain]
min = [0.0, 0.0]
max = [1.0, 1.0]
[boundary]
left = { kind = "periodic" }
right = { kind = "periodic" }
bottom = { kind = "wall" }
top = { kind = "wall" }
[fluid]
spacing = 0.05
viscosity = 0.5
[initial]
velocity = ["sin(pi*y)", "0"]
[method]
scheme = "wcsph"
kernel = "quintic_spline"
h_over_dx = 1.5
sound_speed = 10
[time]
end = 1
)toml";

struct LatticeError {
  double max_rel = 0;  // max |du/dt - nu lap u| / (nu pi^2) over all particles
  double max_v = 0;    // max |dv/dt| / (nu pi^2)
  double wall_rows = 0, interior = 0;  // the same max, split into the two rows next to each wall and the rest
};

LatticeError channel_error(const std::vector<std::string>& sets) {
  std::ostringstream warnings;
  Scene scene = read_scene_text(kViscosityChannel, "test", sets, warnings);
  Model model = build_model(scene);
  std::vector<double> y(model.rhs->layout().size()), ydot(y.size());
  model.rhs->initial_state(y.data());
  model.rhs->eval(0.0, y.data(), ydot.data());
  const auto& L = model.rhs->layout();
  const double pi = std::numbers::pi, scale = scene.viscosity * pi * pi;
  LatticeError e;
  for (std::size_t a = 0; a < L.n; ++a) {
    const double ya = y[L.pos(1) + a];
    const double err = std::abs(ydot[L.vel(0) + a] + scale * std::sin(pi * ya)) / scale;
    e.max_rel = std::max(e.max_rel, err);
    e.max_v = std::max(e.max_v, std::abs(ydot[L.vel(1) + a]) / scale);
    const bool near_wall = ya < 2 * scene.spacing || ya > 1 - 2 * scene.spacing;
    (near_wall ? e.wall_rows : e.interior) = std::max(near_wall ? e.wall_rows : e.interior, err);
  }
  return e;
}

// Per registered model, the settings it is checked with on the channel lattice and the tolerance
// on nu lap u: the measured discretisation error (printed with MESSAGE; morris 0.0065, violeau =
// monaghan = cleary(xi = 4) 0.044, two_pass 0.026, direct with Shepard 0.017) with ~30 % headroom,
// well below the O(1) error of a wrong sign or factor. The check covers the wall rows, so a ghost
// layer too thin for a model shows. A model registered without an entry here is held to
// kDefaultLaplacianTol, the loosest bound of the listed consistent models: a new model is tested
// from its registration on, and its own measured error belongs in the table.
struct LaplacianCase {
  std::vector<std::string> extra;
  double tol;
};
constexpr double kDefaultLaplacianTol = 0.057;
const std::map<std::string, std::vector<LaplacianCase>> kLaplacianCases = {
    {"morris", {{{}, 0.0085}}},
    {"monaghan", {{{}, 0.057}}},
    {"violeau", {{{}, 0.057}}},
    {"cleary", {{{"method.cleary_xi=4"}, 0.057}}},  // xi = 4 is the exact 2D constant (see Viscosity_Cleary1998.cpp)
    {"two_pass", {{{}, 0.034}}},
    // Model A needs a kernel correction for zero-order consistency (Basa §5.1; uncorrected: below).
    {"direct", {{{"method.kernel_correction=shepard"}, 0.022}, {{"method.kernel_correction=bonet_lok"}, 0.022}}},
};

// Settings that make each model zero-order consistent (a constant field has no Laplacian): the
// uncorrected direct model A is not (Basa §5.1).
std::vector<std::string> consistent_settings(const std::string& model) {
  std::vector<std::string> sets = {"method.viscosity_model=" + model};
  if (model == "direct") sets.push_back("method.kernel_correction=shepard");
  return sets;
}

// Models whose pair forces are not equal and opposite, so that momentum is not conserved exactly.
const std::set<std::string> kAsymmetricModels = {"direct"};  // Basa eq. 27: not symmetric in a, b

// The velocity rates (du/dt, dv/dt) of the doubly periodic Taylor-Green box with the initial
// velocity (u, v); the lattice has uniform density, so the pressure term is zero and the rates are
// the viscous term alone.
std::vector<double> periodic_velocity_rates(std::vector<std::string> sets, const std::string& u, const std::string& v) {
  std::ostringstream warnings;
  sets.push_back("initial.velocity=[\"" + u + "\", \"" + v + "\"]");
  const Scene scene = read_scene_text(testing::kTaylorGreenBox + "[time]\nend = 0.05\n", "test", sets, warnings);
  Model model = build_model(scene);
  std::vector<double> y(model.rhs->layout().size()), ydot(y.size());
  model.rhs->initial_state(y.data());
  model.rhs->eval(0.0, y.data(), ydot.data());
  const StateLayout& L = model.rhs->layout();
  return {ydot.begin() + static_cast<std::ptrdiff_t>(L.vel(0)), ydot.begin() + static_cast<std::ptrdiff_t>(L.vel(0) + 2 * L.n)};
}

double max_abs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

}  // namespace

TEST_CASE("viscosity models: nu lap u of u = (sin(pi y), 0) in a walled channel lattice") {
  for (const auto& [model, cases] : kLaplacianCases) {
    CAPTURE(model);
    CHECK(is_registered("viscosity_model", model));  // a renamed model leaves a stale entry
  }
  for (const std::string& model : registered_names("viscosity_model")) {
    CAPTURE(model);
    const auto it = kLaplacianCases.find(model);
    const std::vector<LaplacianCase> fallback = {{{}, kDefaultLaplacianTol}};
    if (it == kLaplacianCases.end()) MESSAGE(model << ": no entry in kLaplacianCases, held to the default bound");
    for (const LaplacianCase& c : it == kLaplacianCases.end() ? fallback : it->second) {
      std::vector<std::string> sets = {"method.viscosity_model=" + model};
      sets.insert(sets.end(), c.extra.begin(), c.extra.end());
      const LatticeError e = channel_error(sets);
      MESSAGE(model << (c.extra.empty() ? "" : " " + c.extra[0]) << ": max rel error " << e.max_rel
                    << " (wall rows " << e.wall_rows << ", interior " << e.interior << "), max |dv/dt| " << e.max_v);
      CHECK(e.max_rel < c.tol);
      CHECK(e.max_v < c.tol);
    }
  }
  // The uncorrected direct model A is not zero-order consistent on a lattice (Basa §5.1): its error
  // (0.27, an offset proportional to u_a / h^2) does not vanish with resolution; pinned between 0.1
  // and 0.35, and the Shepard form (eq. 23) above must remove it.
  const LatticeError a = channel_error({"method.viscosity_model=direct"});
  MESSAGE("direct, uncorrected: max rel error " << a.max_rel);
  CHECK(a.max_rel > 0.1);
  CHECK(a.max_rel < 0.35);
}

// Every registered model (zero-order consistent form): a uniform flow has no viscous force, and a
// uniform velocity added to the Taylor-Green field leaves the viscous force unchanged (Galilean
// invariance), on the doubly periodic lattice. Tolerance 1e-12 relative to the viscous scale
// nu |U| / dx^2 resp. to the largest rate of the Taylor-Green field: round-off of sums of ~50 terms
// (the pair forms give exact zeros; the corrected direct form cancels terms of size |U| / h^2). A
// model that uses u_b instead of u_a - u_b gives O(1), as the uncorrected direct model does.
TEST_CASE("viscosity models: every model gives no force for uniform flow and is Galilean invariant") {
  const std::string tg_u = "sin(2*pi*x)*cos(2*pi*y)", tg_v = "-cos(2*pi*x)*sin(2*pi*y)";
  const double nu = 0.01, dx = 0.0625, U = 0.5;  // the box's viscosity and spacing; |(0.3, -0.4)|
  for (const std::string& model : registered_names("viscosity_model")) {
    CAPTURE(model);
    const auto sets = consistent_settings(model);
    const double uniform = max_abs(periodic_velocity_rates(sets, "0.3", "-0.4")) / (nu * U / (dx * dx));
    const std::vector<double> plain = periodic_velocity_rates(sets, tg_u, tg_v);
    const std::vector<double> moved = periodic_velocity_rates(sets, tg_u + " + 0.3", tg_v + " - 0.4");
    REQUIRE(plain.size() == moved.size());
    double diff = 0;
    for (std::size_t i = 0; i < plain.size(); ++i) diff = std::max(diff, std::abs(moved[i] - plain[i]));
    const double scale = max_abs(plain);
    MESSAGE(model << ": uniform flow " << uniform << ", Galilean mismatch " << diff / scale);
    CHECK(scale > 0.1 * nu);  // the Taylor-Green field has a viscous force (-8 pi^2 nu u exactly)
    CHECK(uniform < 1e-12);
    CHECK(diff / scale < 1e-12);
  }
  // The check can fail: the uncorrected direct model sees the uniform velocity.
  const double direct = max_abs(periodic_velocity_rates({"method.viscosity_model=direct"}, "0.3", "-0.4"));
  MESSAGE("direct, uncorrected: uniform flow " << direct / (nu * U / (dx * dx)));
  CHECK(direct / (nu * U / (dx * dx)) > 1e-3);
}

TEST_CASE("viscosity models: cleary scales with xi (pair weight 2 xi nu / rho, Basa eq. 34)") {
  // Model D with xi is model C times xi / 4 for uniform mu and rho: the ratio of the accelerations
  // of the same particle is xi / 4 to round-off (1e-12: two sums of ~28 terms).
  auto accel = [](const std::vector<std::string>& sets) {
    std::ostringstream w;
    Scene scene = read_scene_text(kViscosityChannel, "test", sets, w);
    Model model = build_model(scene);
    std::vector<double> y(model.rhs->layout().size()), ydot(y.size());
    model.rhs->initial_state(y.data());
    model.rhs->eval(0.0, y.data(), ydot.data());
    return ydot[model.rhs->layout().vel(0) + 7];
  };
  const double c = accel({"method.viscosity_model=violeau"});
  const double d = accel({"method.viscosity_model=cleary"});  // default xi = 4.24 (Basa)
  CHECK(std::abs(d / c - 4.24 / 4.0) < 1e-12);
  // Cleary's own constant stays reachable through the key.
  const double cleary = accel({"method.viscosity_model=cleary", "method.cleary_xi=4.96333"});
  CHECK(std::abs(cleary / c - 4.96333 / 4.0) < 1e-12);
}

TEST_CASE("viscosity models: two_pass doubles the ghost depth (Basa §5.2)") {
  std::ostringstream w;
  const Model one = build_model(read_scene_text(kViscosityChannel, "test", {"method.viscosity_model=morris"}, w));
  const Model two = build_model(read_scene_text(kViscosityChannel, "test", {"method.viscosity_model=two_pass"}, w));
  const double R = one.rhs->kernel().radius();
  CHECK(one.rhs->ghost_depth() == doctest::Approx(R));
  CHECK(two.rhs->ghost_depth() == doctest::Approx(2.0 * R));
}

// The IMEX split puts exactly the viscous terms into the implicit partition (Term::can_be_implicit),
// whatever the model, and only the models of stencil depth 2 ask for ghost velocity gradients; the
// term instances agree with their registered traits.
TEST_CASE("viscosity models: the viscous terms, and only they, can be implicit") {
  std::ostringstream w;
  for (const std::string& m : registered_names("viscosity_model")) {
    CAPTURE(m);
    const Scene scene = read_scene_text(kViscosityChannel, "test", {"method.viscosity_model=" + m}, w);
    const auto& traits = viscosity_models().at(m).traits;
    const auto terms = terms_from_scene(scene, 10.0);
    int implicit = 0;
    for (const auto& t : terms) {
      CAPTURE(t->name());
      const bool viscous = t->name().rfind("viscosity:", 0) == 0;
      CHECK(t->can_be_implicit() == viscous);
      CHECK(t->needs_ghost_velocity_gradients() == (viscous && traits.stencil_depth > 1));
      if (viscous) CHECK(t->can_be_implicit() == traits.can_be_implicit);
      implicit += t->can_be_implicit() ? 1 : 0;
    }
    CHECK(implicit == 1);
  }
}

namespace {
// As the momentum test of test_wcsph.cpp: total rate sum_a m_a du_a/dt against the scale
// sum_a m_a |du_a/dt| on a jittered, doubly periodic lattice with random velocities and densities.
// Opposite pair forces make the ratio round-off; 1e-13 allows for ~10^4 terms of either sign.
double momentum_ratio(const std::vector<std::string>& sets, double* scale_out = nullptr) {
  std::ostringstream warnings;
  const Scene scene = read_scene_text(testing::kTaylorGreenBox + "[time]\nend = 0.05\n", "test", sets, warnings);
  const testing::MomentumRate m = testing::momentum_rate(scene, 7);
  if (scale_out) *scale_out = m.scale;
  return std::max(std::abs(m.px), std::abs(m.py)) / m.scale;
}
}  // namespace

TEST_CASE("viscosity models: the symmetric models conserve linear momentum to round-off") {
  for (const std::string& m : registered_names("viscosity_model")) {
    if (kAsymmetricModels.count(m)) continue;
    for (const std::string dm : {"continuity", "summation"}) {
      double scale = 0;
      const double ratio = momentum_ratio({"method.viscosity_model=" + m, "method.density_mode=" + dm}, &scale);
      MESSAGE(m << " (" << dm << "): |sum m a| / sum m |a| = " << ratio);
      CHECK(scale > 1e-3);  // the forces are not trivially zero
      CHECK(ratio < 1e-13);
    }
  }
  // The asymmetric ones: the same measure is far from round-off (so the check can fail).
  for (const std::string& m : kAsymmetricModels) {
    CAPTURE(m);
    CHECK(is_registered("viscosity_model", m));
    CHECK(momentum_ratio({"method.viscosity_model=" + m}) > 1e-8);
  }
}
