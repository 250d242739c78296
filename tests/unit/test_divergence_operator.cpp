// The adjoint pair of the constrained projection (projection/divergence_operator.hpp), on disordered
// particles in a box with walls and periodic sides:
//   - D is the difference-form SPH divergence, pair by pair (brute force over the same pairs);
//   - <u, G p>_m = -<D u, p>_V for random u, p (G = -M^-1 D^T V by construction: round-off);
//   - K = V D M^-1 D^T V is symmetric and K p = -V D G p.
#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <sstream>
#include <Eigen/Dense>

#include "io/scene_reader.hpp"
#include "projection/divergence_operator.hpp"
#include "run/setup.hpp"
#include "test_support.hpp"

using namespace arksph;

namespace {
const char* kDivergenceBox = R"toml(
[scene]
name = "divergence_box"
[domain]
min = [0.0, 0.0]
max = [1.0, 0.6]
[boundary]
left = { kind = "periodic" }
right = { kind = "periodic" }
[fluid]
spacing = 0.05
[method]
scheme = "isph"
projection = "constrained"
kernel = "wendland_quintic"
h_over_dx = 1.5
[time]
end = 0.01
dt = 0.01
)toml";

struct DisorderedBox {
  Model model;
  std::vector<double> y;
  const FluidFields* f = nullptr;
};

// The lattice shaken by up to 0.2 dx, fields refreshed at the shaken positions.
DisorderedBox disordered_box(const std::vector<std::string>& sets) {
  std::ostringstream warnings;
  const Scene scene = read_scene_text(kDivergenceBox, "<test>", sets, warnings);
  DisorderedBox d{build_model(scene), {}, nullptr};
  RhsEvaluator& rhs = *d.model.rhs;
  d.y.resize(rhs.layout().size());
  rhs.initial_state(d.y.data());
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> shake(-0.2 * scene.spacing, 0.2 * scene.spacing);
  for (int k = 0; k < 2; ++k)
    for (std::size_t a = 0; a < rhs.layout().n; ++a) d.y[rhs.layout().pos(k) + a] += shake(gen);
  rhs.eval(0.0, d.y.data(), nullptr);
  d.f = &rhs.fields();
  return d;
}

std::vector<double> random_values(std::size_t n, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> v(n);
  for (double& x : v) x = u(gen);
  return v;
}
}  // namespace

TEST_CASE("divergence operator: difference-form divergence with reflected wall images") {
  const DisorderedBox d = disordered_box({});
  const FluidFields& f = *d.f;
  DivergenceOperator op;
  op.assemble(f);
  const std::size_t n = f.n_real;
  const auto u = random_values(n, 1), v = random_values(n, 2);
  std::vector<double> div(n);
  op.divergence(u.data(), v.data(), div.data());
  // Brute force: (D u)_a = sum_b V_b (R_b u_src(b) - u_a) . grad_a W_ab, pair by pair.
  double worst = 0, scale = 0;
  for (std::size_t a = 0; a < n; ++a) {
    double s = 0, mag = 0;
    f.pairs.for_pairs(a, [&](std::uint32_t b, double rx, double ry, double, double, double F) {
      const double ub = f.flip_x[b] * u[f.src[b]], vb = f.flip_y[b] * v[f.src[b]];
      const double term = f.m[b] / f.rho[b] * F * ((ub - u[a]) * rx + (vb - v[a]) * ry);
      s += term;
      mag += std::abs(term);
    });
    worst = std::max(worst, std::abs(s - div[a]));
    scale = std::max(scale, mag);
  }
  MESSAGE("N = ", n, ", max |D u - brute force| ", worst, " (term scale ", scale, ")");
  CHECK(scale > 0);
  CHECK(worst <= 1e-13 * scale);  // the same sums in another order: round-off
  // A uniform velocity has no divergence, walls or not: the difference form is exact for it.
  const std::vector<double> one(n, 1.0), zero(n, 0.0);
  op.divergence(one.data(), zero.data(), div.data());
  double interior = 0;
  for (std::size_t a = 0; a < n; ++a)
    if (f.y[a] > 0.25 && f.y[a] < 0.35) interior = std::max(interior, std::abs(div[a]));
  CHECK(interior <= 1e-12 * scale);  // away from the walls (a wall image of a uniform u_x is u_x: also exact there)
}

TEST_CASE("divergence operator: G is the negative adjoint of D, K is symmetric and K = -V D G") {
  const DisorderedBox d = disordered_box({});
  const FluidFields& f = *d.f;
  DivergenceOperator op;
  op.assemble(f);
  const std::size_t n = f.n_real;
  const auto u = random_values(n, 3), v = random_values(n, 4), p = random_values(n, 5);
  std::vector<double> div(n), gx(n), gy(n);
  op.divergence(u.data(), v.data(), div.data());
  op.gradient(p.data(), gx.data(), gy.data());
  double lhs = 0, rhs = 0, mag = 0;
  for (std::size_t a = 0; a < n; ++a) {
    lhs += f.m[a] * (u[a] * gx[a] + v[a] * gy[a]);
    rhs -= op.volume()[a] * div[a] * p[a];
    mag += std::abs(f.m[a] * (u[a] * gx[a] + v[a] * gy[a]));
  }
  MESSAGE("<u, G p>_m = ", lhs, ", -<D u, p>_V = ", rhs);
  CHECK(std::abs(lhs - rhs) <= 1e-12 * mag);  // round-off of two N-term sums
  const SparseMatrix& K = op.normal_matrix();
  CHECK((SparseMatrix(K.transpose()) - K).norm() <= 1e-13 * K.norm());
  // K p = -V D G p
  const Eigen::VectorXd kp = K * Eigen::Map<const Eigen::VectorXd>(p.data(), static_cast<long>(n));
  std::vector<double> dg(n);
  op.divergence(gx.data(), gy.data(), dg.data());
  double worst = 0;
  for (std::size_t a = 0; a < n; ++a) worst = std::max(worst, std::abs(kp[static_cast<long>(a)] + op.volume()[a] * dg[a]));
  CHECK(worst <= 1e-12 * kp.cwiseAbs().maxCoeff());
}


// The exact projection P = I - G (D G)^+ D of the adjoint pair is idempotent: ||P(P u) - P u|| /
// ||u|| at round-off (C&R's approximate projection measures 0.13, tests/physics/test_projection_stages.cpp).
// (D G)^+ is applied through a dense complete orthogonal decomposition of K (the box is small), so
// that the null space of K (odd-even modes) is handled exactly. Tolerance 1e-10: the pseudo-inverse
// of K, whose condition number on the shaken lattice is about 1e5, times round-off.
TEST_CASE("divergence operator: the exact projection is idempotent and leaves D u = 0") {
  const DisorderedBox d = disordered_box({});
  const FluidFields& f = *d.f;
  DivergenceOperator op;
  op.assemble(f);
  const std::size_t n = f.n_real;
  const Eigen::MatrixXd K(op.normal_matrix());
  const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(K);
  auto project = [&](std::vector<double>& u, std::vector<double>& v) {
    std::vector<double> div(n), gx(n), gy(n);
    op.divergence(u.data(), v.data(), div.data());
    Eigen::VectorXd b(static_cast<long>(n));
    for (std::size_t a = 0; a < n; ++a) b[static_cast<long>(a)] = -op.volume()[a] * div[a];
    const Eigen::VectorXd phi = cod.solve(b);
    op.gradient(phi.data(), gx.data(), gy.data());
    for (std::size_t a = 0; a < n; ++a) {
      u[a] -= gx[a];
      v[a] -= gy[a];
    }
  };
  std::vector<double> u = random_values(n, 6), v = random_values(n, 7);
  double norm = 0;
  for (std::size_t a = 0; a < n; ++a) norm += u[a] * u[a] + v[a] * v[a];
  project(u, v);
  const std::vector<double> pu = u, pv = v;
  std::vector<double> div(n);
  op.divergence(u.data(), v.data(), div.data());
  double div_max = 0, row = 0;
  for (std::size_t a = 0; a < n; ++a) {
    div_max = std::max(div_max, std::abs(div[a]));
    row = std::max(row, op.row_magnitude(0)[a] + op.row_magnitude(1)[a]);
  }
  project(u, v);
  double change = 0;
  for (std::size_t a = 0; a < n; ++a) change += (u[a] - pu[a]) * (u[a] - pu[a]) + (v[a] - pv[a]) * (v[a] - pv[a]);
  const double idempotence = std::sqrt(change / norm);
  MESSAGE("exact projection: |P(Pu) - Pu| / |u| = ", idempotence, ", max |D P u| = ", div_max, " (row scale ", row, ")");
  CHECK(idempotence <= 1e-10);
  CHECK(div_max <= 1e-10 * row);
}

// The fused source of the constrained projection, D w - Q in one pass, against its two parts.
TEST_CASE("divergence operator: the fused source D w - Q equals its parts") {
  const DisorderedBox d = disordered_box({});
  const FluidFields& f = *d.f;
  const std::size_t n = f.n_real;
  const auto wx = random_values(n, 8), wy = random_values(n, 9), u = random_values(n, 10), v = random_values(n, 11);
  std::vector<double> fused(n), div(n);
  divergence_minus_motion(f, wx.data(), wy.data(), u.data(), v.data(), fused.data());
  difference_divergence(f, wx.data(), wy.data(), div.data());
  const std::vector<double> q = divergence_rate_of_motion(f, u.data(), v.data());
  double worst = 0, scale = 0;
  for (std::size_t a = 0; a < n; ++a) {
    worst = std::max(worst, std::abs(fused[a] - (div[a] - q[a])));
    scale = std::max(scale, std::abs(div[a]) + std::abs(q[a]));
  }
  CHECK(worst <= 1e-12 * scale);  // the same terms summed in another order
}
