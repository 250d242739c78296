// Recursive coordinate bisection (src/parallel/rcb.hpp): the blocks tile the grid, owner() agrees
// with the boxes, the weights are balanced, and every rank computes the same decomposition.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <random>

#include "mpi_test_support.hpp"

using namespace arksph::parallel;
using namespace arksph::parallel::testing;

namespace {

// The heaviest slab of cells one cell thick across the whole grid, along any axis: the balance
// bound of the bisection (each cut misses its target by at most half a slab of the block it cuts,
// and the misses of nested cuts shrink with the share of ranks they concern).
std::int64_t heaviest_slab(const CellGrid& g, const std::vector<std::int64_t>& counts) {
  std::int64_t best = 0;
  for (int a = 0; a < g.dim(); ++a)
    for (long k = 0; k < g.n(a); ++k) {
      std::int64_t w = 0;
      for (long c1 = 0; c1 < g.n(1); ++c1)
        for (long c0 = 0; c0 < g.n(0); ++c0)
          if ((a == 0 ? c0 : c1) == k) w += counts[g.flat(c0, c1, 0)];
      best = std::max(best, w);
    }
  return best;
}

void check_decomposition(const CellGrid& g, const std::vector<std::int64_t>& counts, int ranks) {
  CAPTURE(ranks);
  const Decomposition d = Decomposition::rcb(g, counts, ranks);
  REQUIRE(d.ranks() == ranks);
  std::int64_t total = 0, weights = 0;
  for (auto c : counts) total += c;
  long cells = 0;
  for (int r = 0; r < ranks; ++r) {
    CHECK(d.block(r).cells() >= 1);
    cells += d.block(r).cells();
    weights += d.weight(r);
  }
  CHECK(cells == static_cast<long>(g.cells()));  // with the owner check below: a tiling
  CHECK(weights == total);
  // Each cell's centre belongs to the box of its owner, and to no other box.
  int misplaced = 0;
  for (long c1 = 0; c1 < g.n(1); ++c1)
    for (long c0 = 0; c0 < g.n(0); ++c0) {
      const double x[2] = {g.edge(0, c0) + 0.5 * g.side(0), g.edge(1, c1) + 0.5 * g.side(1)};
      const int owner = d.owner(x);
      for (int r = 0; r < ranks; ++r)
        if (d.box(r).contains(x, 2) != (r == owner)) ++misplaced;
    }
  CHECK(misplaced == 0);
  const double ideal = static_cast<double>(total) / ranks;
  const auto slab = static_cast<double>(heaviest_slab(g, counts));
  for (int r = 0; r < ranks; ++r) {
    CAPTURE(r);
    CHECK(std::abs(static_cast<double>(d.weight(r)) - ideal) <= slab);
  }
}

}  // namespace

TEST_CASE("rcb: blocks tile the grid, owner matches the boxes, weights within one slab of the ideal") {
  const CellGrid g(unit_domain(3.0, 2.0, true, false), 0.1);
  REQUIRE(g.n(0) == 30);
  REQUIRE(g.n(1) == 20);
  std::mt19937_64 rng(12345);
  std::vector<std::int64_t> uniform(g.cells()), clustered(g.cells(), 0);
  std::poisson_distribution<int> poisson(9.0);
  for (auto& c : uniform) c = poisson(rng);
  // Clustered: weight only in a disc in the lower left, a few cells elsewhere.
  for (long c1 = 0; c1 < g.n(1); ++c1)
    for (long c0 = 0; c0 < g.n(0); ++c0)
      if ((c0 - 6) * (c0 - 6) + (c1 - 5) * (c1 - 5) < 25) clustered[g.flat(c0, c1, 0)] = 20 + (c0 * c1) % 7;
  std::vector<std::int64_t> empty(g.cells(), 0);
  for (int ranks = 1; ranks <= 7; ++ranks) {
    check_decomposition(g, uniform, ranks);
    check_decomposition(g, clustered, ranks);
    check_decomposition(g, empty, ranks);
  }
  check_decomposition(g, uniform, 16);
}

TEST_CASE("rcb: too few cells for the ranks is an error") {
  const CellGrid g(unit_domain(1.0, 1.0, false, false), 0.5);  // 2 x 2 cells
  const std::vector<std::int64_t> counts(g.cells(), 1);
  CHECK_NOTHROW(Decomposition::rcb(g, counts, 4));
  CHECK_THROWS_AS(Decomposition::rcb(g, counts, 5), std::invalid_argument);
}

TEST_CASE("rcb: the same boxes on every rank from the summed counts, balanced within one slab") {
  const Communicator comm;
  const Domain dom = unit_domain(3.0, 2.0, true, true);
  const CellGrid g(dom, 0.25);
  // Uneven per rank: rank r has 300 + 200 r particles, rank 0's squeezed into the left half.
  ParticleFields p = random_particles(comm, dom, 300 + 200 * static_cast<std::size_t>(comm.rank()), 3);
  if (comm.rank() == 0)
    for (auto& x : p.field[X]) x *= 0.5;
  std::vector<std::int64_t> counts = count_per_cell(g, p);
  comm.sum_in_place(counts);
  const Decomposition d = Decomposition::rcb(g, counts, comm.size());
  std::vector<std::array<double, 4>> boxes;
  for (int r = 0; r < comm.size(); ++r) boxes.push_back({d.box(r).lo[0], d.box(r).lo[1], d.box(r).hi[0], d.box(r).hi[1]});
  const auto all = comm.allgatherv(boxes);
  bool same = true;
  for (std::size_t k = 0; k < all.size(); ++k) same = same && all[k] == boxes[k % boxes.size()];
  CHECK(on_all_ranks(comm, same));
  const double ideal = static_cast<double>(comm.sum(static_cast<std::int64_t>(p.size()))) / comm.size();
  const auto slab = static_cast<double>(heaviest_slab(g, counts));
  CHECK(std::abs(static_cast<double>(d.weight(comm.rank())) - ideal) <= slab);
  // The weight of each block is the number of particles, over all ranks, that it owns.
  std::vector<std::int64_t> owned(static_cast<std::size_t>(comm.size()), 0);
  double x[3] = {0, 0, 0};
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.position(i, x);
    ++owned[static_cast<std::size_t>(d.owner(x))];
  }
  comm.sum_in_place(owned);
  bool weights_ok = true;
  for (int r = 0; r < comm.size(); ++r) weights_ok = weights_ok && owned[static_cast<std::size_t>(r)] == d.weight(r);
  CHECK(weights_ok);
  CHECK(comm.sum(d.weight(comm.rank())) == comm.sum(static_cast<std::int64_t>(p.size())));
}
