// The transform solver of the GPPS grid Poisson equation (grid_poisson_transform.hpp) against the KLU
// factorisation of the same five-point matrix: random sources on walled, periodic and mixed grids,
// odd and even (and prime) sizes, 1D and 2D; and the choice of the solver by the density field.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "projection/grid/grid_poisson.hpp"
#include "projection/grid/grid_poisson_transform.hpp"

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
