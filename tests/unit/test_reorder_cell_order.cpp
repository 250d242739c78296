// The cell order that re-sorting uses (run/particle_reorder.hpp): a stable permutation into
// non-decreasing row-major cell index. Runs with re-sorts: process/test_reorder_runs.cpp.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "run/particle_reorder.hpp"
#include "test_support.hpp"

using namespace arksph;

TEST_CASE("reorder: cell_order is a stable permutation into non-decreasing row-major cell index") {
  // Points below the box (negative cell coordinates, clamped to 0): cell_keys, vectorised under
  // -fno-trapping-math, converts every lane to an integer before its select keeps 0 for those, and
  // the discarded conversions raise FE_INVALID. No floating-point traps here.
  const testing::FpTrapsOff traps_off;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> pos(-0.05, 1.05);
  const std::size_t n = 3000;
  std::vector<double> x(n), y(n);
  for (std::size_t a = 0; a < n; ++a) x[a] = pos(rng), y[a] = pos(rng);
  const Permutation from = cell_order(x.data(), y.data(), n, 0.0, 0.0, 0.1);
  std::vector<std::uint32_t> sorted(from);
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 0; i < n; ++i) REQUIRE(sorted[i] == i);  // a permutation
  const std::vector<std::uint64_t> key = cell_keys(x.data(), y.data(), n, 0.0, 0.0, 0.1);
  std::size_t out_of_order = 0;
  for (std::size_t i = 1; i < n; ++i) {
    const std::uint64_t k0 = key[from[i - 1]], k1 = key[from[i]];
    out_of_order += k1 < k0 || (k1 == k0 && from[i] < from[i - 1]);  // stable within a cell
  }
  CHECK(out_of_order == 0);
  // The key itself: cell (i, j) of side 0.1 from the origin, j * nx + i, negatives clamped to 0.
  const double px[] = {0.05, 0.15, 0.05, -0.01}, py[] = {0.05, 0.05, 0.25, 0.35};
  const std::vector<std::uint64_t> k4 = cell_keys(px, py, 4, 0.0, 0.0, 0.1);
  CHECK(k4 == std::vector<std::uint64_t>{0, 1, 4, 6});  // nx = 2 (largest x cell is 1)
}
