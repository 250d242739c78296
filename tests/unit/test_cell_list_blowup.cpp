// A blown-up state reaching the cell list (e.g. in a stage, before the state check of the step) is a
// numerical failure (exit 3), not an allocation of an absurd number of cells (std::length_error,
// exit 1, seen on the spin-down at dt = 0.001 when a 53^2 run went unstable between t = 4 and 5).
#include <doctest/doctest.h>

#include <vector>

#include "core/errors.hpp"
#include "neighbors/cell_list.hpp"

using namespace arksph;

TEST_CASE("cell list: points spread over an absurd number of cells are a numerical failure") {
  std::vector<double> x = {0.0, 0.5, 1.0}, y = {0.0, 0.5, 1.0};
  CellList cells;
  x[1] = 1e12;  // a particle thrown far away: 1e12 / 0.1 = 1e13 cells along x
  CHECK_THROWS_AS(cells.build(x.data(), y.data(), x.size(), 0.1), NumericalFailure);
  x[1] = 0.5, y[2] = -1e12;
  CHECK_THROWS_AS(cells.build(x.data(), y.data(), x.size(), 0.1), NumericalFailure);
  // Sparse but sane: 3 points 1000 radii apart (1e6 cells, below the cap of 64 n + 1e7) still work.
  x = {0.0, 100.0, 0.0}, y = {0.0, 0.0, 100.0};
  cells.build(x.data(), y.data(), x.size(), 0.1);
  int found = 0;
  cells.for_each_near(100.0, 0.05, [&](std::size_t j, double, double) { found += j == 1; });
  CHECK(found == 1);
}
