// The particle regularisation parts (method.regularisation, method.density_diffusion) term by term:
//   - the shifting velocity on a lattice compressed by a sine: zero on the regular lattice, and on
//     the compressed one pointing down the number-density gradient with the size -A h U grad C;
//   - the extra stress of the transport velocity and the delta-SPH flux are pair-antisymmetric:
//     total momentum and total mass are conserved to round-off on a periodic box;
//   - delta-SPH leaves a hydrostatic density alone, on a disordered lattice too;
//   - with both on, delta-SPH, the pressure gradient, continuity and viscosity summed inside the
//     shifting's pair loop give the bits of the terms applied one by one; with the IMEX split the
//     viscosity stays outside it;
//   - the scheme and density-mode checks.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <sstream>

#include "core/errors.hpp"
#include "integrate/viscous_split.hpp"
#include "io/scene_reader.hpp"
#include "rhs/terms.hpp"
#include "run/setup.hpp"

using namespace arksph;

namespace {
const char* kBox = R"toml(
[scene]
name = "regularisation"
[domain]
min = [0.0, 0.0]
max = [1.0, 1.0]
[boundary]
left = { kind = "periodic" }
right = { kind = "periodic" }
bottom = { kind = "periodic" }
top = { kind = "periodic" }
[fluid]
spacing = 0.05
viscosity = 0.01
[initial]
velocity = ["sin(2*pi*y)", "0.5*cos(2*pi*x)"]
[method]
scheme = "wcsph"
sound_speed = 10
[time]
end = 0.01
)toml";

Scene box(std::vector<std::string> sets) {
  std::ostringstream warnings;
  return read_scene_text(kBox, "<test>", sets, warnings);
}

// The fields of one evaluation at t = 0, with the pairs stored (a field refresh).
struct Evaluated {
  Model model;
  std::vector<double> y;
  explicit Evaluated(const Scene& scene) : model(build_model(scene)) {
    const StateLayout& L = model.rhs->layout();
    y.resize(L.size());
    model.rhs->initial_state(y.data());
  }
  const FluidFields& eval() {
    model.rhs->eval(0.0, y.data(), nullptr);
    return model.rhs->fields();
  }
};

// The term named `name` of the scene applied alone to a copy of `fields` (derivatives zeroed first).
FluidFields apply_alone(const Scene& scene, double sound_speed, const FluidFields& fields, const std::string& name) {
  FluidFields f = fields;
  std::fill(f.dudt.begin(), f.dudt.end(), 0.0);
  std::fill(f.dvdt.begin(), f.dvdt.end(), 0.0);
  std::fill(f.drhodt.begin(), f.drhodt.end(), 0.0);
  for (const auto& term : terms_from_scene(scene, sound_speed))
    if (term->name() == name) {
      f.shift_u.assign(f.n_real, 0.0);
      f.shift_v.assign(f.n_real, 0.0);
      term->apply(f);
      return f;
    }
  FAIL("no term " << name);
  return f;
}
}  // namespace

// Lattice points x0 displaced by xi = eps sin(2 pi x0): the number density is C = 1 / (1 + xi'), so
// grad C = 4 pi^2 eps sin(2 pi x0) to first order in eps, and du = -A h U grad C (A = 2, U = 1 the
// largest initial speed, h = 0.1). Tolerance: 25 % of the amplitude, for the anti-clumping factor
// of Lind's eq. 10 (it weights near neighbours up by up to R = 0.2) and the kernel's discretisation
// error on 20 x 20 points; the regular lattice gives zero to round-off (1e-12 of the amplitude).
TEST_CASE("shifting: zero on the lattice, -A h U grad C on a compressed one") {
  const double eps = 0.004, A = 2.0, h = 0.1, U = 1.0;
  const double amplitude = A * h * U * 4 * M_PI * M_PI * eps;
  {
    const Scene scene = box({"method.regularisation=\"shifting\"", "method.shifting_coefficient=2"});
    Evaluated e(scene);
    const FluidFields& f = e.eval();
    double worst = 0;
    for (std::size_t a = 0; a < f.n_real; ++a) worst = std::max({worst, std::abs(f.shift_u[a]), std::abs(f.shift_v[a])});
    CHECK(worst <= 1e-12 * amplitude);
  }
  const Scene scene = box({"method.regularisation=\"shifting\"", "method.shifting_coefficient=2",
                           "initial.offset=[\"0.004*sin(2*pi*x)\", \"0\"]"});
  Evaluated e(scene);
  const FluidFields& f = e.eval();
  double worst = 0, worst_v = 0;
  for (std::size_t a = 0; a < f.n_real; ++a) {
    // x0 from x = x0 + eps sin(2 pi x0), to first order
    const double x0 = f.x[a] - eps * std::sin(2 * M_PI * f.x[a]);
    const double expected = -amplitude * std::sin(2 * M_PI * x0);
    worst = std::max(worst, std::abs(f.shift_u[a] - expected));
    worst_v = std::max(worst_v, std::abs(f.shift_v[a]));
  }
  MESSAGE("max |du - du_expected| = ", worst, " of amplitude ", amplitude);
  CHECK(worst <= 0.25 * amplitude);
  CHECK(worst_v <= 1e-12 * amplitude);
}

// The step limit of shifting (rhs/regularisation/shifting_stability.hpp) rests on the fastest decay rate of the
// linearised shifting velocity over the lattice's Fourier modes. Brute force on the real term: power
// iteration on the map from a displacement field d to the shift velocity of the displaced lattice,
// (du(r0 + eps d) - du(r0 - eps d)) / (2 eps), whose largest eigenvalue in magnitude is that rate (the
// map is symmetric negative semi-definite about the lattice, where du = 0). The Rayleigh quotient
// after 150 iterations must be within 1 % of the rate behind Term::max_step (1.5 / rate). The fastest
// mode runs along an axis at k = 1.335 / dx (Wendland, h = 2 dx, R = 0.2); the 14 x 14 periodic
// lattice carries k = 2 pi 3 / (14 dx) = 1.346 / dx, whose rate is 0.1 % below it, and its few
// modes let the iteration converge (0.2 % measured). A rate off by a factor (a missed V0 or h, or the
// anti-clumping factor's derivative, 13 % of the rate) is outside. No saturation (limit 0), so the
// map is linear; eps = 1e-7 dx keeps the finite difference at round-off level.
TEST_CASE("shifting: the step limit's rate is the fastest decay of the shifting velocity") {
  const Scene scene = box({"method.regularisation=\"shifting\"", "method.shifting_limit=0", "fluid.spacing=0.07",
                           "domain.max=[0.98, 0.98]"});
  Evaluated e(scene);
  const StateLayout& L = e.model.rhs->layout();
  const double rate_of_limit = 1.5 / e.model.rhs->max_step();
  REQUIRE(std::isfinite(rate_of_limit));
  const std::vector<double> y0 = e.y;
  const double eps = 1e-7 * scene.spacing;
  auto shift_of = [&](const std::vector<double>& d, double sign) {
    for (std::size_t i = 0; i < 2 * L.n; ++i) e.y[i] = y0[i] + sign * eps * d[i];
    const FluidFields& f = e.eval();
    std::vector<double> s(2 * L.n);
    for (std::size_t a = 0; a < L.n; ++a) {
      s[a] = f.shift_u[a];
      s[L.n + a] = f.shift_v[a];
    }
    return s;
  };
  std::vector<double> d(2 * L.n);
  for (std::size_t i = 0; i < d.size(); ++i) d[i] = std::sin(12.9898 * i + 0.3) + 0.5 * std::cos(78.233 * i);
  double rayleigh = 0;
  for (int it = 0; it < 150; ++it) {
    double norm = 0;
    for (double x : d) norm += x * x;
    for (double& x : d) x /= std::sqrt(norm);
    const std::vector<double> plus = shift_of(d, 1), minus = shift_of(d, -1);
    std::vector<double> jd(d.size());
    rayleigh = 0;
    for (std::size_t i = 0; i < d.size(); ++i) {
      jd[i] = (plus[i] - minus[i]) / (2 * eps);
      rayleigh -= d[i] * jd[i];
    }
    d = jd;
  }
  MESSAGE("fastest decay rate: power iteration ", rayleigh, ", behind the step limit ", rate_of_limit);
  CHECK(std::abs(rayleigh / rate_of_limit - 1) <= 0.01);
}

// The shifting part carries the velocity along the shifted path: du/dt gains (du . grad) u. With
// u = (sin 2 pi y, 0.5 cos 2 pi x) and du along x only (the compressed lattice above), the gain of
// dv/dt is du_x dv/dx = -pi du_x sin(2 pi x). Tolerance 10 % of the largest gain: the SPH gradient's
// error on 20 x 20 points with h = 2 dx.
TEST_CASE("shifting: the carried velocity gains (du . grad) u") {
  const Scene scene = box({"method.regularisation=\"shifting\"", "initial.offset=[\"0.004*sin(2*pi*x)\", \"0\"]"});
  Evaluated e(scene);
  const FluidFields& fields = e.eval();
  const FluidFields f = apply_alone(scene, e.model.sound_speed, fields, "regularisation:shifting");
  double worst = 0, largest = 0;
  for (std::size_t a = 0; a < f.n_real; ++a) {
    const double expected = -M_PI * std::sin(2 * M_PI * f.x[a]) * f.shift_u[a];
    worst = std::max(worst, std::abs(f.dvdt[a] - expected));
    largest = std::max(largest, std::abs(expected));
  }
  REQUIRE(largest > 0);
  MESSAGE("max |dv/dt - du_x dv/dx| = ", worst, " of ", largest);
  CHECK(worst <= 0.1 * largest);
}

// Pair-antisymmetric sums: total momentum (transport velocity's extra stress) and total volume rate
// sum_a V_a drho_a/dt (delta-SPH, with and without a body force) vanish to round-off. Tolerance
// 1e-12 of the sum of magnitudes: a one-sided or mis-signed pair term gives O(1) there.
TEST_CASE("transport velocity and delta-SPH: momentum and mass conserved pair by pair") {
  const std::string disorder = "initial.offset=[\"0.005*sin(37*x + 11*y)\", \"0.005*cos(23*x - 7*y)\"]";
  {
    const Scene scene = box({"method.regularisation=\"transport_velocity\"", disorder});
    Evaluated e(scene);
    const FluidFields f = apply_alone(scene, e.model.sound_speed, e.eval(), "regularisation:transport_velocity");
    double px = 0, py = 0, mag = 0;
    for (std::size_t a = 0; a < f.n_real; ++a) {
      px += f.m[a] * f.dudt[a];
      py += f.m[a] * f.dvdt[a];
      mag += f.m[a] * (std::abs(f.dudt[a]) + std::abs(f.dvdt[a]));
    }
    REQUIRE(mag > 0);
    MESSAGE("transport velocity: total force ", px, ", ", py, " of ", mag);
    CHECK(std::abs(px) <= 1e-12 * mag);
    CHECK(std::abs(py) <= 1e-12 * mag);
  }
  for (const std::string force : {"fluid.body_force=[\"0\", \"0\"]", "fluid.body_force=[\"0\", \"-1\"]"}) {
    const Scene scene = box({"method.density_diffusion=\"delta_sph\"", disorder, force});
    Evaluated e(scene);
    const StateLayout& L = e.model.rhs->layout();
    for (std::size_t a = 0; a < L.n; ++a)  // a density field with structure
      e.y[L.rho() + a] = 1.0 + 0.01 * std::sin(2 * M_PI * e.y[L.pos(0) + a]) * std::cos(2 * M_PI * e.y[L.pos(1) + a]);
    const FluidFields f = apply_alone(scene, e.model.sound_speed, e.eval(), "density_diffusion:delta_sph");
    double total = 0, mag = 0;
    for (std::size_t a = 0; a < f.n_real; ++a) {
      total += f.vol[a] * f.drhodt[a];
      mag += f.vol[a] * std::abs(f.drhodt[a]);
    }
    REQUIRE(mag > 0);
    MESSAGE(force, ": sum V drho/dt = ", total, " of ", mag);
    CHECK(std::abs(total) <= 1e-12 * mag);
  }
}

// A hydrostatic density rho0 (1 - g y / c^2) (linearised Tait) on a disordered lattice, away from the
// walls: delta-SPH's flux is zero to round-off (1e-9 of the flux the same density gets without the
// body force, where the disorder makes the second difference of a linear field non-zero).
TEST_CASE("delta-SPH: a hydrostatic density has no diffusive flux") {
  const auto flux = [](bool gravity) {
    const Scene scene = box({"method.density_diffusion=\"delta_sph\"", "boundary.bottom={kind=\"wall\"}",
                             "boundary.top={kind=\"wall\"}", "initial.velocity=[\"0\", \"0\"]",
                             "initial.offset=[\"0.005*sin(37*x + 11*y)\", \"0.005*cos(23*x - 7*y)\"]",
                             gravity ? "fluid.body_force=[\"0\", \"-1\"]" : "fluid.body_force=[\"0\", \"0\"]"});
    Evaluated e(scene);
    const StateLayout& L = e.model.rhs->layout();
    const double c = e.model.sound_speed;
    for (std::size_t a = 0; a < L.n; ++a) e.y[L.rho() + a] = 1.0 * (1.0 + 1.0 * (0.5 - e.y[L.pos(1) + a]) / (c * c));
    const FluidFields f = apply_alone(scene, c, e.eval(), "density_diffusion:delta_sph");
    double worst = 0;
    for (std::size_t a = 0; a < f.n_real; ++a)
      if (f.y[a] > 0.3 && f.y[a] < 0.7) worst = std::max(worst, std::abs(f.drhodt[a]));  // two supports from the walls
    return worst;
  };
  const double with_gravity = flux(true), without = flux(false);
  MESSAGE("interior |drho/dt|: ", with_gravity, " with the hydrostatic part removed, ", without, " without");
  REQUIRE(without > 0);
  CHECK(with_gravity <= 1e-9 * without);
}

// The evaluator lets shifting add delta-SPH, the pressure gradient, continuity and viscosity in its
// own pair loop (Term::take_over) and skips those terms; the same operations in the same order, so
// the derivatives must equal bit for bit those of the force terms applied one after another (a term
// counted twice or not at all changes the derivatives by O(1) of its own contribution, measured here
// to be non-zero).
TEST_CASE("terms inside the shifting's pair loop: the bits of the terms one by one") {
  const Scene scene = box({"method.regularisation=\"shifting\"", "method.density_diffusion=\"delta_sph\"",
                           "initial.offset=[\"0.005*sin(37*x + 11*y)\", \"0.005*cos(23*x - 7*y)\"]"});
  Evaluated e(scene);
  const StateLayout& L = e.model.rhs->layout();
  for (std::size_t a = 0; a < L.n; ++a)  // a density field with structure
    e.y[L.rho() + a] = 1.0 + 0.01 * std::sin(2 * M_PI * e.y[L.pos(0) + a]) * std::cos(2 * M_PI * e.y[L.pos(1) + a]);
  const FluidFields& swept = e.eval();
  const std::vector<std::string> taken = {"density_diffusion:delta_sph", "pressure_gradient:colagrossi",
                                          "continuity:szewc19", "viscosity:morris"};
  const std::vector<std::string> names = e.model.rhs->term_names();
  for (const std::string& name : taken) CHECK(std::find(names.begin(), names.end(), name) != names.end());
  FluidFields f = swept;
  for (auto* v : {&f.dudt, &f.dvdt, &f.drhodt, &f.shift_u, &f.shift_v}) std::fill(v->begin(), v->end(), 0.0);
  std::map<std::string, double> size;  // the largest change of a derivative by each taken-over term
  for (const auto& term : terms_from_scene(scene, e.model.sound_speed)) {
    if (term->stage() != Term::Stage::force) continue;
    const std::vector<double> du = f.dudt, drho = f.drhodt;
    term->apply(f);
    double& s = size[term->name()];
    for (std::size_t a = 0; a < f.n_real; ++a)
      s = std::max({s, std::abs(f.dudt[a] - du[a]), std::abs(f.drhodt[a] - drho[a])});
  }
  for (const std::string& name : taken) {
    CAPTURE(name);
    REQUIRE(size[name] > 0);
  }
  const auto same = [](const std::vector<double>& x, const std::vector<double>& y) {
    return x.size() == y.size() && std::memcmp(x.data(), y.data(), x.size() * sizeof(double)) == 0;
  };
  CHECK(same(f.drhodt, swept.drhodt));
  CHECK(same(f.dudt, swept.dudt));
  CHECK(same(f.dvdt, swept.dvdt));
  CHECK(same(f.shift_u, swept.shift_u));
}

// With the IMEX split (time.imex) the viscosity is of the implicit partition: the shifting, which
// takes it over otherwise, gives it back, so f_E + f_I is the whole f. Tolerance 1e-12 relative to the
// largest derivative: the split adds the viscous sums to the rest in another order (a few roundings);
// a viscosity counted twice or not at all is off by its own size, required non-zero here.
TEST_CASE("IMEX split with shifting: f_E + f_I is the whole f, the viscosity counted once") {
  const Scene scene = box({"method.regularisation=\"shifting\"", "method.density_diffusion=\"delta_sph\"",
                           "initial.offset=[\"0.005*sin(37*x + 11*y)\", \"0.005*cos(23*x - 7*y)\"]"});
  Model whole = build_model(scene), parts = build_model(scene);
  const StateLayout& L = whole.rhs->layout();
  std::vector<double> y(L.size()), f(L.size()), fe(L.size()), fi(L.size());
  whole.rhs->initial_state(y.data());
  whole.rhs->eval(0.0, y.data(), f.data());
  ViscousSplit split(scene, *parts.rhs);
  parts.rhs->eval(0.0, y.data(), fe.data());
  parts.rhs->implicit_part(fi.data());
  double scale = 0, viscous = 0, worst = 0;
  for (std::size_t i = 0; i < L.size(); ++i) {
    scale = std::max(scale, std::abs(f[i]));
    viscous = std::max(viscous, std::abs(fi[i]));
    worst = std::max(worst, std::abs(fe[i] + fi[i] - f[i]));
  }
  MESSAGE("largest |f| ", scale, ", |f_I| ", viscous, ", |f_E + f_I - f| ", worst);
  REQUIRE(viscous > 1e-6 * scale);
  CHECK(worst <= 1e-12 * scale);
}

TEST_CASE("regularisation keys: delta-SPH needs wcsph and the continuity equation") {
  CHECK_THROWS_AS(box({"method.density_diffusion=\"delta_sph\"", "method.scheme=\"isph\""}), InputError);
  const Scene summation = box({"method.density_diffusion=\"delta_sph\"", "method.density_mode=\"summation\""});
  CHECK_THROWS_AS(build_model(summation), InputError);
  CHECK_NOTHROW(box({"method.regularisation=\"shifting\"", "method.scheme=\"isph\""}));
  CHECK_NOTHROW(box({"method.regularisation=\"transport_velocity\"", "method.scheme=\"isph-gpps\""}));
}
