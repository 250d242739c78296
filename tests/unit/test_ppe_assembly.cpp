// The compressed PPE matrix built row by row in parallel (assemble_ppe) against the pair-by-pair
// approximate Laplacian of C&R eq. 19 (apply_laplacian, a serial loop over the same pairs with the
// ghost's pressure read from its source): (A p)_a = -V_a L(p)_a for every row but the pinned one.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>

#include "run/setup.hpp"
#include "io/scene_reader.hpp"
#include "projection/free_surface.hpp"
#include "projection/ppe_assembly.hpp"
#include "projection/velocity_correction.hpp"
#include "test_support.hpp"

using namespace arksph;

namespace {
// Walls at the bottom and top, periodic left and right: wall images and periodic images both land
// in their source's column.
const char* kChannel = R"toml(
[scene]
name = "ppe_channel"
[domain]
min = [0.0, 0.0]
max = [1.0, 0.5]
[boundary]
left = { kind = "periodic" }
right = { kind = "periodic" }
[fluid]
spacing = 0.1
viscosity = 0.01
[initial]
velocity = ["sin(2*pi*x)*y", "0.1*cos(2*pi*x)"]
[method]
scheme = "isph"
kernel = "wendland_quintic"
h_over_dx = 2.0
[time]
end = 0.01
dt = 0.01
)toml";
}  // namespace

// Tolerance 1e-13 of max_a sum_b |A_ab| max |p|: round-off of ~50-term sums summed in another order.
TEST_CASE("ppe assembly: the compressed matrix applies the C&R eq. 19 Laplacian") {
  for (const std::string spacing : {"fluid.spacing=0.1", "fluid.spacing=0.025"}) {
    std::ostringstream warnings;
    const Scene scene = read_scene_text(kChannel, "<test>", {spacing}, warnings);
    Model model = build_model(scene);
    const FluidFields& f = testing::fields_at_start(model);
    const PoissonSystem sys = assemble_ppe(f, divergence_cummins_rudman(f), 0.01);
    const std::size_t n = f.n_real;
    REQUIRE(sys.A.rows() == static_cast<long>(n));
    std::mt19937 gen(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<double> p(n);
    for (double& v : p) v = u(gen);
    p[0] = 0.0;  // the pinned unknown: its column is dropped from the matrix
    const Eigen::Map<const Eigen::VectorXd> pp(p.data(), static_cast<long>(n));
    const Eigen::VectorXd ap = sys.A * pp;
    const std::vector<double> lap = apply_laplacian(f, p);
    double worst = 0, row_scale = 0;
    for (std::size_t a = 1; a < n; ++a) {
      worst = std::max(worst, std::abs(ap[static_cast<long>(a)] + f.m[a] / f.rho[a] * lap[a]));
      double s = 0;
      for (SparseMatrix::InnerIterator it(sys.A, static_cast<long>(a)); it; ++it) s += std::abs(it.value());
      row_scale = std::max(row_scale, s);
    }
    MESSAGE(spacing, ": N = ", n, ", nonzeros ", sys.A.nonZeros(), ", max |A p + V L(p)| ", worst, " (row scale ", row_scale, ")");
    CHECK(row_scale > 0);
    CHECK(worst <= 1e-13 * row_scale);
    // Row 0 is the identity (P_0 = 0), and the matrix is symmetric to round-off.
    CHECK(ap[0] == doctest::Approx(0.0));
    CHECK((SparseMatrix(sys.A.transpose()) - sys.A).norm() <= 1e-12 * sys.A.norm());
    // Indices strictly increasing within every column: sorted, duplicates merged.
    long unsorted = 0;
    for (long c = 0; c < sys.A.outerSize(); ++c) {
      long last = -1;
      for (SparseMatrix::InnerIterator it(sys.A, c); it; ++it) {
        unsorted += it.row() <= last;
        last = it.row();
      }
    }
    CHECK(unsorted == 0);
  }
}

namespace {
// The channel's lower part holds fluid (fluid.region), under WCSPH, which runs a free surface: the
// fields of its particles with a free surface at y = 0.3.
const FluidFields& channel_with_surface(Model& model) { return testing::fields_at_start(model); }
Scene surface_scene() {
  std::ostringstream warnings;
  return read_scene_text(kChannel, "<test>",
                         {"fluid.spacing=0.025", "fluid.region=\"y < 0.3\"", "method.scheme=\"wcsph\""}, warnings);
}
}  // namespace

// Lind et al. 2012: div r is d (2) in the bulk, about half at a free surface. The wall images at the
// floor and the periodic images at the sides stand in for fluid: only the top rows are surface.
TEST_CASE("ppe assembly: the divergence of position finds the free surface and only it") {
  const Scene scene = surface_scene();
  Model model = build_model(scene);
  const FluidFields& f = channel_with_surface(model);
  const std::vector<double> div = position_divergence(f);
  const std::vector<char> surface = free_surface_particles(f, 1.5);
  double top = 0;
  for (std::size_t a = 0; a < f.n_real; ++a) top = std::max(top, f.y[a]);
  for (std::size_t a = 0; a < f.n_real; ++a) {
    CAPTURE(f.y[a]);
    if (f.y[a] == top) {
      CHECK(surface[a]);
      CHECK(div[a] < 1.5);
    }
    // Rows two and more below the top see most of their support filled: not surface.
    if (f.y[a] < top - 1.5 * scene.spacing) CHECK_FALSE(surface[a]);
    // Beyond the support (radius 2h = 4 dx) of the missing fluid, the bulk: 2 within 1 % (the
    // lattice's kernel moment at h = 2 dx).
    if (f.y[a] < top - 4.5 * scene.spacing) CHECK(div[a] == doctest::Approx(2.0).epsilon(0.01));
  }
}

// With rows of given P: the solution of the assembled system takes the given values there, and
// elsewhere satisfies -V_a L(P)_a = -V_a div_a / dt with L of C&R eq. 19 over every neighbour, the
// given ones included (apply_laplacian, a separate serial loop). The matrix stays symmetric.
// Tolerance 1e-9 of the source's scale: a direct solve (LDL^T) of a well-conditioned system.
TEST_CASE("ppe assembly: rows of given pressure (a free surface) keep the equation elsewhere and symmetry") {
  const Scene scene = surface_scene();
  Model model = build_model(scene);
  const FluidFields& f = channel_with_surface(model);
  const std::size_t n = f.n_real;
  DirichletRows given;
  given.fixed = free_surface_particles(f, 1.5);
  given.value.assign(n, 0.0);
  std::size_t fixed = 0;
  for (std::size_t a = 0; a < n; ++a)
    if (given.fixed[a]) given.value[a] = 0.1 * f.x[a] + (++fixed % 3) * 0.01;  // not constant: they must reach the source
  REQUIRE(fixed > 0);
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> div(n);
  for (double& d : div) d = u(gen);
  const double dt = 0.01;
  PoissonSystem sys;
  assemble_ppe(f, div, dt, given, sys);
  const SparseMatrix At = sys.A.transpose();
  CHECK((sys.A - At).norm() <= 1e-12 * sys.A.norm());
  Eigen::SimplicialLDLT<SparseMatrix> ldlt(sys.A);
  REQUIRE(ldlt.info() == Eigen::Success);
  const Eigen::VectorXd b = Eigen::Map<const Eigen::VectorXd>(sys.b.data(), static_cast<long>(n));
  const Eigen::VectorXd x = ldlt.solve(b);
  std::vector<double> p(x.data(), x.data() + n);
  const std::vector<double> lp = apply_laplacian(f, p);
  double scale = 0;
  for (std::size_t a = 0; a < n; ++a) scale = std::max(scale, std::abs(div[a] / dt));
  for (std::size_t a = 0; a < n; ++a) {
    CAPTURE(a);
    if (given.fixed[a])
      CHECK(p[a] == doctest::Approx(given.value[a]).epsilon(1e-12));
    else
      CHECK(std::abs(lp[a] - div[a] / dt) <= 1e-9 * scale);
  }
}

// At a free surface (projection/free_surface.hpp), on the channel's lattice below y = 0.3 with a
// linear P = 2 - 3 y, away from the floor (whose mirror images carry their source's P, not the
// line's): the projection's gradient (the renormalised difference gradient at the surface rows, the
// neighbour-based one below) reads -3 at every row, the top ones included,
// where C&R eq. 11's symmetric sum does not; and the Laplacian's linear defect c . grad P equals
// C&R eq. 19 applied to P (apply_laplacian, a separate loop), zero in the bulk and not at the top.
// Tolerance 1e-10 of |grad P| / dx: round-off of ~50-term sums; the checks that can fail are of
// order 1 (the symmetric gradient) and 1/dx (the defect) at the surface.
TEST_CASE("ppe assembly: at a free surface the renormalised gradient and the Laplacian's defect are exact for a linear P") {
  const Scene scene = surface_scene();
  Model model = build_model(scene);
  const FluidFields& f = channel_with_surface(model);
  const std::size_t n = f.n_real;
  const double dx = scene.spacing, support = 4 * dx;  // h = 2 dx, Wendland's radius 2h
  std::vector<double> p(n);
  for (std::size_t a = 0; a < n; ++a) p[a] = 2.0 - 3.0 * f.y[a];
  double top = 0;
  for (std::size_t a = 0; a < n; ++a) top = std::max(top, f.y[a]);
  std::vector<double> u(n, 0.0), v(n, 0.0), us(n, 0.0), vs(n, 0.0);
  subtract_renormalised_gradient(f, p, 1.0, n, u.data(), v.data(), free_surface_particles(f, 1.5));
  subtract_pressure_gradient(f, p, 1.0, n, us.data(), vs.data());
  const std::vector<double> defect = linear_laplacian_defect(f, renormalised_gradients(f, p, n), n);
  const std::vector<double> lap = apply_laplacian(f, p);
  const double tol = 1e-10 * 3.0 / dx;
  int top_rows = 0;
  for (std::size_t a = 0; a < n; ++a) {
    if (f.y[a] < support) continue;  // the floor's images
    CAPTURE(f.y[a]);
    CHECK(std::abs(f.rho[a] * v[a] - 3.0) <= tol);  // -dt grad P / rho with dt = 1
    CHECK(std::abs(f.rho[a] * u[a]) <= tol);
    CHECK(std::abs(defect[a] - lap[a]) <= tol);
    if (f.y[a] < top - support) CHECK(std::abs(defect[a]) <= tol);
    if (f.y[a] == top) {
      ++top_rows;
      CHECK(std::abs(f.rho[a] * vs[a] - 3.0) > 0.3);  // the symmetric sum is off by more than 10 %
      CHECK(std::abs(defect[a]) > 1.0 / dx);
    }
  }
  CHECK(top_rows > 0);
}

// The projection's divergence and gradient as a pair, with the volumes V_a = m_a / rho_a as weights:
// sum_a V_a P_a (D u)_a = -sum_a V_a u_a . (G P)_a holds for the difference divergence with C&R
// eq. 11's symmetric gradient, and for C&R eq. 17's divergence with the difference gradient (each
// pair adjoint, swapping a and b in the double sum). The pair at a free surface, the difference
// divergence with the renormalised difference gradient, is not, which lets a projection amplify a
// particle-scale pattern (docs/methods/free-surface.md). On the channel under a free surface, with
// random u and P that vanish within the floor's images' reach (the images carry their sources'
// values reflected, which the identity does not cover) and periodic images at the sides. Tolerance
// 1e-12 of sum_a V_a |u_a| |G P_a|: round-off of ~50-term sums; the surface pair misses by order 1.
TEST_CASE("ppe assembly: the adjoint pairs of divergence and gradient, and the free surface's pair that is not") {
  const Scene scene = surface_scene();
  Model model = build_model(scene);
  FluidFields f = channel_with_surface(model);
  const std::size_t n = f.n_real;
  const double reach = 4 * scene.spacing;  // the kernel's radius 2h, h = 2 dx
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> r(-1.0, 1.0);
  std::vector<double> ux(n), uy(n), p(n);
  for (std::size_t a = 0; a < n; ++a) {
    const double mask = f.y[a] > reach ? 1.0 : 0.0;
    ux[a] = mask * r(gen);
    uy[a] = mask * r(gen);
    p[a] = mask * r(gen);
  }
  for (std::size_t i = 0; i < f.n_all; ++i) {  // every point carries its source's u (periodic images)
    f.u[i] = f.ud[i] = ux[f.src[i]];
    f.v[i] = f.vd[i] = uy[f.src[i]];
  }
  const auto weighted = [&](const std::vector<double>& div, const std::vector<double>& gx,
                            const std::vector<double>& gy, double& scale) {
    double lhs = 0, rhs = 0;
    scale = 0;
    for (std::size_t a = 0; a < n; ++a) {
      const double va = f.m[a] / f.rho[a];
      lhs += va * p[a] * div[a];
      rhs += va * (ux[a] * gx[a] + uy[a] * gy[a]);
      scale += va * std::hypot(ux[a], uy[a]) * std::hypot(gx[a], gy[a]);
    }
    return lhs + rhs;
  };
  // G P = (u - u') / dt of each correction with dt = 1 from u = 0 (the symmetric one with rho = 1
  // reads sum_b V_b (P_a + P_b) grad W_ab; the difference one without B is B^-1 times the renormalised).
  std::vector<double> sx(n, 0.0), sy(n, 0.0);
  subtract_pressure_gradient(f, p, 1.0, n, sx.data(), sy.data());
  for (std::size_t a = 0; a < n; ++a) {
    sx[a] = -sx[a] * f.rho[a];
    sy[a] = -sy[a] * f.rho[a];
  }
  std::vector<double> dgx(n), dgy(n), rgx(n), rgy(n);
  for (std::size_t a = 0; a < n; ++a) {
    double gx = 0, gy = 0;  // sum_b V_b (P_b - P_a) grad_a W_ab
    f.pairs.for_pairs(a, [&](std::uint32_t b, double rx, double ry, double, double, double F) {
      const double c = f.m[b] / f.rho[b] * (p[f.src[b]] - p[a]) * F;
      gx += c * rx;
      gy += c * ry;
    });
    dgx[a] = gx;
    dgy[a] = gy;
    const RenormalisedGradient g = renormalised_gradient(f, p, a);
    rgx[a] = g.x;
    rgy[a] = g.y;
  }
  double scale = 0;
  const double diff_sym = weighted(divergence_difference(f), sx, sy, scale);
  CHECK(std::abs(diff_sym) <= 1e-12 * scale);
  const double cr_diff = weighted(divergence_cummins_rudman(f), dgx, dgy, scale);
  CHECK(std::abs(cr_diff) <= 1e-12 * scale);
  const double surface_pair = weighted(divergence_difference(f), rgx, rgy, scale);
  CHECK(std::abs(surface_pair) > 1e-3 * scale);
}

namespace {
// The projection after a step as a linear map of the velocities, u <- u - G L^-1 D u, with the
// surface rows' P held at 0 (their values only shift u by a constant field): D the difference
// divergence (wall images reflect their source's velocity), L C&R eq. 19 on the other rows, G the
// gradient given. Dense, for a few hundred particles.
enum class Correction { symmetric, renormalised, projection };
Eigen::MatrixXd projection_map(FluidFields& f, const std::vector<char>& fixed, Correction correction) {
  const std::size_t n = f.n_real;
  const auto N = static_cast<long>(n);
  std::vector<long> free_rows;
  for (std::size_t a = 0; a < n; ++a)
    if (!fixed[a]) free_rows.push_back(static_cast<long>(a));
  const auto m = static_cast<long>(free_rows.size());
  Eigen::MatrixXd d(m, 2 * N), g(2 * N, m), l(m, m);
  for (long k = 0; k < 2; ++k)
    for (long c = 0; c < N; ++c) {
      for (std::size_t i = 0; i < f.n_all; ++i) {
        const bool on = static_cast<long>(f.src[i]) == c;
        f.ud[i] = on && k == 0 ? f.flip_x[i] : 0.0;
        f.vd[i] = on && k == 1 ? f.flip_y[i] : 0.0;
      }
      const std::vector<double> div = divergence_difference(f);
      for (long r = 0; r < m; ++r) d(r, k * N + c) = div[static_cast<std::size_t>(free_rows[static_cast<std::size_t>(r)])];
    }
  for (long j = 0; j < m; ++j) {
    std::vector<double> p(n, 0.0);
    p[static_cast<std::size_t>(free_rows[static_cast<std::size_t>(j)])] = 1.0;
    std::vector<double> gx(n, 0.0), gy(n, 0.0);
    if (correction == Correction::projection) {
      subtract_renormalised_gradient(f, p, -1.0, n, gx.data(), gy.data(), fixed);
    } else if (correction == Correction::renormalised) {
      const std::vector<RenormalisedGradient> rg = renormalised_gradients(f, p, n);
      for (std::size_t a = 0; a < n; ++a) {
        gx[a] = rg[a].x / f.rho[a];
        gy[a] = rg[a].y / f.rho[a];
      }
    } else {
      subtract_pressure_gradient(f, p, -1.0, n, gx.data(), gy.data());
    }
    for (long a = 0; a < N; ++a) {
      g(a, j) = gx[static_cast<std::size_t>(a)];
      g(N + a, j) = gy[static_cast<std::size_t>(a)];
    }
    const std::vector<double> lp = apply_laplacian(f, p);
    for (long r = 0; r < m; ++r) l(r, j) = lp[static_cast<std::size_t>(free_rows[static_cast<std::size_t>(r)])];
  }
  return Eigen::MatrixXd::Identity(2 * N, 2 * N) - g * l.partialPivLu().solve(d);
}

Eigen::VectorXcd eigenvalues(const Eigen::MatrixXd& p) { return Eigen::EigenSolver<Eigen::MatrixXd>(p, false).eigenvalues(); }
}  // namespace

// The approximate projection u <- u - G L^-1 D u is applied at every step, so a velocity pattern it
// multiplies by more than 1 grows with the number of steps, faster on shorter ones. With the
// symmetric gradient of C&R eq. 11, the adjoint of the difference divergence, G L^-1 D is similar
// to a symmetric positive semidefinite form: the map's eigenvalues are real and at most 1, and on
// this lattice at least -1 (L^-1 D G at most 2; the smallest is -0.04, a mode L under-reads).
// The same divergence with the renormalised difference gradient is not adjoint, and on this
// channel the second row's odd-even vertical motion is multiplied by 1.019 at each projection
// (docs/methods/free-surface.md); the projection's own gradient at a surface (renormalised at the
// surface rows, neighbour-based below: velocity_correction.hpp) leaves no pattern growing. The
// tolerances 1e-9: the dense eigen-solver's round-off on a 960 x 960 map with entries of order 1;
// the check that can fail is the renormalised one's, off by 0.019.
TEST_CASE("ppe assembly: the projection map at a free surface is non-expansive with its gradient, not with the renormalised one" *
          doctest::test_suite("asan_slow")) {
  const Scene scene = surface_scene();
  Model model = build_model(scene);
  FluidFields f = channel_with_surface(model);
  const std::vector<char> fixed = free_surface_particles(f, 1.5);
  const Eigen::VectorXcd sym = eigenvalues(projection_map(f, fixed, Correction::symmetric));
  const Eigen::VectorXcd ren = eigenvalues(projection_map(f, fixed, Correction::renormalised));
  const Eigen::VectorXcd used = eigenvalues(projection_map(f, fixed, Correction::projection));
  MESSAGE("spectral radius of the projection map: symmetric gradient " << sym.cwiseAbs().maxCoeff()
          << ", renormalised " << ren.cwiseAbs().maxCoeff() << ", the projection's " << used.cwiseAbs().maxCoeff());
  CHECK(sym.cwiseAbs().maxCoeff() <= 1.0 + 1e-9);
  CHECK(sym.imag().cwiseAbs().maxCoeff() <= 1e-9);
  CHECK(used.cwiseAbs().maxCoeff() <= 1.0 + 1e-9);
  CHECK(ren.cwiseAbs().maxCoeff() > 1.0 + 1e-3);
}
