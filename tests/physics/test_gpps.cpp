// The grid-projected Poisson solver (Szewc et al. 2012 §4.2): the grid equation against an analytic
// solution (second order under refinement, variable density), the factorisation reused while the
// density field holds, and the projection of a particle velocity field onto (approximately)
// divergence-free fields.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "run/setup.hpp"
#include "io/scene_reader.hpp"
#include "projection/grid/grid_poisson.hpp"
#include "projection/grid/grid_transfer.hpp"
#include "projection/ppe_assembly.hpp"
#include "test_support.hpp"

using namespace arksph;

namespace {
// Max-norm error of the grid solve of div((1/rho) grad p) = s on the unit square (Neumann walls),
// p = cos(pi x) cos(pi y), rho = 1 + 0.5 x: s = -2 pi^2 p / rho + d(1/rho)/dx dp/dx.
double grid_error(int n) {
  GridSpec g;
  g.nx = g.ny = n;
  g.h = 1.0 / n;
  GridPoisson poisson(g);
  std::vector<double> rho(g.cells()), s(g.cells()), exact(g.cells());
  const double pi = M_PI;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = (i + 0.5) * g.h, y = (j + 0.5) * g.h;
      const std::size_t c = g.index(i, j);
      rho[c] = 1 + 0.5 * x;
      exact[c] = std::cos(pi * x) * std::cos(pi * y);
      const double dsigma = -0.5 / (rho[c] * rho[c]);
      s[c] = -2 * pi * pi * exact[c] / rho[c] + dsigma * (-pi * std::sin(pi * x) * std::cos(pi * y));
    }
  poisson.set_density(rho);
  std::vector<double> p;
  const double res = poisson.solve(s, p);
  CHECK(res < 1e-10);  // a direct solve: round-off only
  double mean = 0;
  for (double v : exact) mean += v;
  mean /= static_cast<double>(exact.size());
  double err = 0;
  for (std::size_t c = 0; c < p.size(); ++c) err = std::max(err, std::abs(p[c] - (exact[c] - mean)));
  return err;
}

const char* kGppsBox = R"toml(
[scene]
name = "gpps_box"
[domain]
min = [0.0, 0.0]
max = [1.0, 1.0]
[fluid]
spacing = 0.025
viscosity = 0
[method]
scheme = "isph-gpps"
kernel = "wendland_quintic"
h_over_dx = 2.0
centre_positions = false
[time]
end = 1e-6
integrator = "ARKSPH_FORWARD_EULER_1_1"
dt = 1e-6
)toml";

double rms(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x * x;
  return std::sqrt(s / static_cast<double>(v.size()));
}
}  // namespace

TEST_CASE("gpps: the grid Poisson solve converges at second order (variable density, Neumann walls)") {
  const double e16 = grid_error(16), e32 = grid_error(32), e64 = grid_error(64);
  const double q1 = std::log2(e16 / e32), q2 = std::log2(e32 / e64);
  MESSAGE("max errors ", e16, " ", e32, " ", e64, "; orders ", q1, " ", q2);
  // A cell-centred five-point scheme is second order; 1.8 allows for the boundary cells.
  CHECK(q1 > 1.8);
  CHECK(q2 > 1.8);
  CHECK(e64 < 1e-3);
}

TEST_CASE("gpps: the grid matrix is factorised once and refactorised only when the density changes") {
  GridSpec g;
  g.nx = 8;
  g.ny = 4;
  g.h = 0.25;
  GridPoisson poisson(g);
  std::vector<double> rho(g.cells(), 1.0);
  CHECK(poisson.set_density(rho));
  CHECK_FALSE(poisson.set_density(rho));
  CHECK(poisson.factorisations() == 1);
  rho[5] = 1.8;
  CHECK(poisson.set_density(rho));
  CHECK(poisson.factorisations() == 2);
  // The solution satisfies the discrete equation (zero-mean source) away from the pinned cell.
  std::vector<double> s(g.cells()), p;
  for (std::size_t c = 0; c < s.size(); ++c) s[c] = std::sin(1.0 + c);
  double mean = 0;
  for (double v : s) mean += v;
  mean /= static_cast<double>(s.size());
  poisson.solve(s, p);
  const std::vector<double> lp = poisson.apply(p);
  for (std::size_t c = 1; c < s.size(); ++c) CHECK(lp[c] == doctest::Approx(s[c] - mean).epsilon(1e-9));
}

// u* = grad(phi) + curl(psi) on the particles, phi = cos(pi x) cos(pi y) / pi, psi = sin^2(pi x)
// sin^2(pi y) / pi, both with zero normal velocity on the walls. The exact projection keeps the
// solenoidal part only. One GPPS projection must remove most of the gradient part and leave the
// solenoidal part nearly untouched.
TEST_CASE("gpps: one projection makes a divergent particle field nearly divergence-free") {
  std::ostringstream warnings;
  const std::string grad_x = "-sin(pi*x)*cos(pi*y)", grad_y = "-cos(pi*x)*sin(pi*y)";
  const std::string curl_x = "2*sin(pi*x)^2*sin(pi*y)*cos(pi*y)", curl_y = "-2*sin(pi*y)^2*sin(pi*x)*cos(pi*x)";
  const Scene scene = read_scene_text(
      kGppsBox, "test",
      {"initial.velocity=[\"" + grad_x + " + " + curl_x + "\", \"" + grad_y + " + " + curl_y + "\"]",
       // the source and images the bounds below were measured with (auto: difference, free-slip images)
       "method.ppe_divergence=cummins_rudman", "boundary.free_slip_divergence=false"},
      warnings);
  Model model = build_model(scene);
  std::vector<double> y(model.rhs->layout().size());
  model.rhs->initial_state(y.data());
  model.rhs->eval(0.0, y.data(), nullptr);
  const StateLayout& L = model.rhs->layout();
  const std::size_t n = L.n;
  const double div_before = rms(divergence_cummins_rudman(model.rhs->fields()));
  std::vector<double> err_before(2 * n), err_after(2 * n);
  auto solenoidal = [&](std::size_t a, int k) {
    const double x = y[L.pos(0) + a], yy = y[L.pos(1) + a], pi = M_PI;
    return k == 0 ? 2 * std::pow(std::sin(pi * x), 2) * std::sin(pi * yy) * std::cos(pi * yy)
                  : -2 * std::pow(std::sin(pi * yy), 2) * std::sin(pi * x) * std::cos(pi * x);
  };
  for (std::size_t a = 0; a < n; ++a)
    for (int k = 0; k < 2; ++k) err_before[2 * a + k] = y[L.vel(k) + a] - solenoidal(a, k);
  model.projection->begin_step(0.0, y.data());
  model.projection->project(1e-6, y.data());
  for (std::size_t a = 0; a < n; ++a)
    for (int k = 0; k < 2; ++k) err_after[2 * a + k] = y[L.vel(k) + a] - solenoidal(a, k);
  model.rhs->eval(1e-6, y.data(), nullptr);
  const double div_after = rms(divergence_cummins_rudman(model.rhs->fields()));
  const double ratio_u = rms(err_after) / rms(err_before), ratio_div = div_after / div_before;
  MESSAGE("gradient part left ", ratio_u, ", divergence left ", ratio_div);
  // The ratios (printed) are limited by the grid transfer and the SPH divergence (whose wall
  // truncation the projection removes as a source): measured 0.04984 and 0.06609, the same in the
  // -march=native and the generic build. +-10 % around them: room for a change of summation order
  // or solver; a missing or wrongly signed correction gives ratios >= 1.
  constexpr double kMargin = 1.1;
  CHECK(ratio_u < 0.04984 * kMargin);
  CHECK(ratio_u > 0.04984 / kMargin);
  CHECK(ratio_div < 0.06609 * kMargin);
  CHECK(ratio_div > 0.06609 / kMargin);
  CHECK(model.projection->stats().symbolic_analyses == 1);
}

// method.gpps_volume_relaxation: from rest on a lattice squeezed towards x = 0.5, one projected
// step must move particles so that the particle volume per grid cell becomes more uniform; without
// the relaxation nothing moves (no source). With beta = 0.5 the r.m.s. of (phi - 1) falls from
// 0.04545 to 0.03386 (printed; ratio 0.7449, the same in the -march=native and the generic build);
// +-5 % around the ratio: room for a change of summation order, while a wrong sign makes it grow
// and a relaxation left out leaves it at 1.
TEST_CASE("gpps: the volume relaxation evens out the particle volume per cell") {
  auto phi_rms = [](const Model& model, const Scene& scene, const double* y) {
    const StateLayout& L = model.rhs->layout();
    const GridSpec g = gpps_grid(scene);
    std::vector<double> vol(L.n, scene.spacing * scene.spacing), one(L.n, 1.0);
    const GridDeposit d = deposit(g, L.n, y + L.pos(0), y + L.pos(1), vol.data(), one.data(), 0.0);
    double s = 0;
    for (double w : d.weight) s += (w / (g.h * g.h) - 1) * (w / (g.h * g.h) - 1);
    return std::sqrt(s / static_cast<double>(d.weight.size()));
  };
  std::ostringstream warnings;
  const Scene scene = read_scene_text(kGppsBox, "test",
                                      {"initial.offset=[\"-0.01*sin(2*pi*x)\", \"0\"]", "method.gpps_volume_relaxation=0.5",
                                       "method.centre_positions=true", "time.dt=0.01"},
                                      warnings);
  Model model = build_model(scene);
  std::vector<double> y0;
  const std::vector<double> y1 = testing::one_projected_step(scene, model, y0);
  const double before = phi_rms(model, scene, y0.data()), after = phi_rms(model, scene, y1.data());
  MESSAGE("r.m.s. of the cell volume fraction - 1: before ", before, ", after ", after);
  CHECK(before > 0.01);
  constexpr double kMeasuredRatio = 0.7449, kMargin = 1.05;
  CHECK(after / before < kMeasuredRatio * kMargin);
  CHECK(after / before > kMeasuredRatio / kMargin);
}

TEST_CASE("gpps: the deposits of two disjoint particle sets, combined, are the deposit of their union") {
  // What the ranks of a decomposed run do (ProjectionGrid_Szewc2012.hpp): each deposits its own
  // particles, the sums are added and the lows / highs reduced. 400 scattered particles on a 10 x 8
  // grid, the value constant (2.5) left of x = 0.3 so that those cells must come out exactly 2.5.
  GridSpec g;
  g.nx = 10;
  g.ny = 8;
  g.h = 0.1;
  const std::size_t n = 400;
  std::vector<double> x(n), y(n), vol(n), q(n);
  for (std::size_t a = 0; a < n; ++a) {
    x[a] = std::fmod(0.6180339887 * static_cast<double>(a), 1.0);
    y[a] = 0.8 * std::fmod(0.7548776662 * static_cast<double>(a) + 0.1, 1.0);
    vol[a] = 0.01 * (1 + 0.3 * std::sin(7.0 * static_cast<double>(a)));
    q[a] = x[a] < 0.3 ? 2.5 : std::cos(3 * x[a]) + y[a];
  }
  const GridDeposit whole = deposit(g, n, x.data(), y.data(), vol.data(), q.data(), -1.0);
  // Set A: the even particles, set B: the odd ones (so that both touch every cell).
  std::vector<double> xs[2], ys[2], vs[2], qs[2];
  for (std::size_t a = 0; a < n; ++a) {
    xs[a % 2].push_back(x[a]);
    ys[a % 2].push_back(y[a]);
    vs[a % 2].push_back(vol[a]);
    qs[a % 2].push_back(q[a]);
  }
  DepositSums sum = deposit_sums(g, xs[0].size(), xs[0].data(), ys[0].data(), vs[0].data(), qs[0].data());
  const DepositSums other = deposit_sums(g, xs[1].size(), xs[1].data(), ys[1].data(), vs[1].data(), qs[1].data());
  for (std::size_t i = 0; i < g.cells(); ++i) {
    sum.value[i] += other.value[i];
    sum.weight[i] += other.weight[i];
    sum.lo[i] = std::min(sum.lo[i], other.lo[i]);
    sum.hi[i] = std::max(sum.hi[i], other.hi[i]);
  }
  const GridDeposit combined = finish_deposit(std::move(sum), -1.0);
  int constant_cells = 0;
  for (std::size_t i = 0; i < g.cells(); ++i) {
    // Only the order of the sums differs: a few ulps of the cell's value.
    CHECK(std::abs(combined.value[i] - whole.value[i]) <= 1e-14 * std::max(1.0, std::abs(whole.value[i])));
    CHECK(std::abs(combined.weight[i] - whole.weight[i]) <= 1e-14 * whole.weight[i]);
    if (whole.value[i] == 2.5) {
      ++constant_cells;
      CHECK(combined.value[i] == 2.5);  // lo == hi over both sets: the value itself, not a quotient
    }
  }
  CHECK(constant_cells >= 8);  // the columns left of x = 0.3 away from their right edge
}
