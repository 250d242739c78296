// The transform solver of the GPPS grid Poisson equation (grid_poisson_transform.hpp) against the KLU
// factorisation of the same five-point matrix: random sources on walled, periodic and mixed grids,
// odd and even (and prime) sizes, 1D and 2D; the choice of the solver by the density field; and the
// transfers that the grid part over ranks uses (the cell box of a rank's particles, several fields
// interpolated at once, the deposit without extremes).
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>

#include "projection/grid/grid_poisson.hpp"
#include "projection/grid/grid_poisson_transform.hpp"
#include "projection/grid/grid_transfer.hpp"

using namespace arksph;

namespace {

GridSpec grid_of(int nx, int ny, bool px, bool py) {
  GridSpec g;
  g.nx = nx;
  g.ny = ny;
  g.h = 0.37;  // not 1: the h^2 scaling must be right
  g.x0 = -0.2;
  g.periodic = {px, py};
  return g;
}

// max |p_transform - p_klu| / max |p_klu| for one random source, density rho in every cell.
double transform_against_klu(const GridSpec& g, double rho, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> s(g.cells());
  for (double& v : s) v = 3.0 + u(gen);  // a non-zero mean: the solvers must both drop it
  const std::vector<double> density(g.cells(), rho);
  GridPoisson fast(g), klu(g, GridPoisson::Solver::klu);
  CHECK(fast.set_density(density));
  CHECK(klu.set_density(density));
  REQUIRE(fast.uses_transform());
  REQUIRE_FALSE(klu.uses_transform());
  std::vector<double> pf, pk;
  const double rf = fast.solve(s, pf);
  const double rk = klu.solve(s, pk);
  // Both are direct solves: their residuals are round-off (a few eps times the condition of the
  // matrix, below 1e3 for these at most 17-cell axes).
  CHECK(rf < 1e-12);
  CHECK(rk < 1e-12);
  double mean = 0;
  for (double v : pf) mean += v;
  CHECK(std::abs(mean) / static_cast<double>(pf.size()) < 1e-14);  // zero mean, as the KLU path's
  double diff = 0, scale = 0;
  for (std::size_t c = 0; c < pf.size(); ++c) {
    diff = std::max(diff, std::abs(pf[c] - pk[c]));
    scale = std::max(scale, std::abs(pk[c]));
  }
  REQUIRE(scale > 0);
  return diff / scale;
}

}  // namespace

TEST_CASE("grid Poisson transforms: the KLU solution to round-off on walled, periodic and mixed grids") {
  struct Case {
    int nx, ny;
    bool px, py;
  };
  const Case cases[] = {
      {8, 6, false, false},  {7, 5, false, false},  {13, 11, false, false}, {2, 2, false, false},
      {8, 6, true, true},    {9, 7, true, true},    {2, 3, true, true},     {12, 17, true, true},
      {10, 7, true, false},  {5, 12, false, true},  {11, 4, true, false},   {3, 9, false, true},
      {16, 1, false, false}, {9, 1, false, false},  {2, 1, false, false},   {12, 1, true, false},
      {7, 1, true, false},   {2, 1, true, false},   {6, 1, true, true},
  };
  unsigned seed = 1;
  for (const Case& c : cases) {
    const GridSpec g = grid_of(c.nx, c.ny, c.px, c.py);
    const double rel = transform_against_klu(g, 1.7, seed++);
    INFO(c.nx, "x", c.ny, " periodic ", c.px, c.py, ": relative difference ", rel);
    // Two direct solves of a system with condition number below 1e3: they agree to a few eps times
    // that; 1e-12 is the agreement asked of the transforms (a wrong eigenvalue or ordering is O(1)).
    CHECK(rel < 1e-12);
  }
}

TEST_CASE("grid Poisson transforms: a non-uniform density keeps KLU, a uniform one returns to the transforms") {
  const GridSpec g = grid_of(6, 5, false, true);
  GridPoisson poisson(g);
  std::vector<double> rho(g.cells(), 1.0);
  CHECK(poisson.set_density(rho));
  CHECK(poisson.uses_transform());
  rho[7] = 2.0;
  CHECK(poisson.set_density(rho));
  CHECK_FALSE(poisson.uses_transform());
  std::vector<double> s(g.cells()), p;
  for (std::size_t c = 0; c < s.size(); ++c) s[c] = std::cos(0.3 * static_cast<double>(c));
  CHECK(poisson.solve(s, p) < 1e-12);  // a direct solve: round-off (the matrix has condition < 1e3)
  std::fill(rho.begin(), rho.end(), 1000.0);
  CHECK(poisson.set_density(rho));
  CHECK(poisson.uses_transform());
  CHECK(poisson.factorisations() == 3);
  // The density enters the uniform solve as a factor: p(rho = 1000) = 1000 p(rho = 1), to round-off.
  std::vector<double> p1000, p1;
  poisson.solve(s, p1000);
  GridPoisson unit(g);
  unit.set_density(std::vector<double>(g.cells(), 1.0));
  unit.solve(s, p1);
  for (std::size_t c = 0; c < s.size(); ++c) CHECK(p1000[c] == doctest::Approx(1000.0 * p1[c]).epsilon(1e-12));
}

TEST_CASE("grid transfers: the cell box of a set of points, the whole axis where they wrap a periodic side") {
  GridSpec g = grid_of(10, 8, false, false);
  g.x0 = 0.0;
  g.h = 0.1;
  // Points in x in [0.32, 0.58], y in [0.21, 0.44]: cell centres at (i + 0.5) h bracket them from
  // i = 2 (centre 0.25) to i = 5 (0.55 < 0.58 < 0.65: 5 and 6), j = 1 .. 4.
  const std::vector<double> x = {0.32, 0.58, 0.45}, y = {0.21, 0.44, 0.30};
  const std::array<int, 4> box = cell_box(g, x.size(), x.data(), y.data());
  CHECK(box[0] == 2);
  CHECK(box[1] == 6);
  CHECK(box[2] == 1);
  CHECK(box[3] == 4);
  // A point left of the first cell centre on a periodic x axis takes weights from cell nx-1 too.
  g.periodic = {true, false};
  const std::vector<double> xw = {0.02, 0.3}, yw = {0.3, 0.3};
  const std::array<int, 4> wrapped = cell_box(g, xw.size(), xw.data(), yw.data());
  CHECK(wrapped[0] == 0);
  CHECK(wrapped[1] == g.nx - 1);
  CHECK(wrapped[2] == 2);
  CHECK(wrapped[3] == 3);
  // The acceleration in the box equals the whole grid's there (and is 0 outside).
  GridPoisson poisson(g);
  poisson.set_density(1.3);
  std::vector<double> p(g.cells()), ax, ay, bx, by;
  for (std::size_t c = 0; c < p.size(); ++c) p[c] = std::sin(0.7 * static_cast<double>(c));
  poisson.acceleration(p, ax, ay);
  poisson.acceleration(p, bx, by, box);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const std::size_t c = g.index(i, j);
      const bool in = i >= box[0] && i <= box[1] && j >= box[2] && j <= box[3];
      CHECK(bx[c] == (in ? ax[c] : 0.0));
      CHECK(by[c] == (in ? ay[c] : 0.0));
    }
}

TEST_CASE("grid transfers: several fields interpolated at once are each field's interpolation, bit for bit") {
  GridSpec g = grid_of(7, 5, true, false);
  std::vector<double> x(50), y(50), f1(g.cells()), f2(g.cells());
  for (std::size_t a = 0; a < x.size(); ++a) {
    x[a] = g.x0 + 7 * g.h * std::fmod(0.618 * static_cast<double>(a), 1.0);
    y[a] = 5 * g.h * std::fmod(0.755 * static_cast<double>(a) + 0.1, 1.0);
  }
  for (std::size_t c = 0; c < f1.size(); ++c) {
    f1[c] = std::cos(static_cast<double>(c));
    f2[c] = 1.0 / (1.0 + static_cast<double>(c));
  }
  const std::vector<std::vector<double>> both = interpolate_fields(g, x.size(), x.data(), y.data(), {&f1, &f2});
  CHECK(both[0] == interpolate(g, x.size(), x.data(), y.data(), f1));
  CHECK(both[1] == interpolate(g, x.size(), x.data(), y.data(), f2));
  // Without extremes a deposit is value / weight, within an ulp or two of the one with them.
  std::vector<double> vol(x.size(), 0.01), q(x.size());
  for (std::size_t a = 0; a < q.size(); ++a) q[a] = 2.0 + std::sin(static_cast<double>(a));
  const GridDeposit with = deposit(g, x.size(), x.data(), y.data(), vol.data(), q.data(), 0.0);
  const GridDeposit without = finish_deposit(deposit_sums(g, x.size(), x.data(), y.data(), vol.data(), q.data(), false), 0.0);
  for (std::size_t c = 0; c < g.cells(); ++c) {
    CHECK(without.weight[c] == with.weight[c]);
    // Equal where the particles differ; where one particle (or several alike) feeds a cell, with
    // extremes gives q exactly and without (w V q) / (w V): a product and a division, a few ulps.
    CHECK(std::abs(without.value[c] - with.value[c]) <= 1e-15 * std::abs(with.value[c]));
  }
}
