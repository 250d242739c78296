#include "parallel/rcb.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace arksph::parallel {

namespace {

// Weight of each slab (one cell thick across `axis`) of the block, and the block's total.
std::vector<std::int64_t> slab_weights(const CellGrid& grid, const CellBlock& b, int axis,
                                       const std::vector<std::int64_t>& counts) {
  std::vector<std::int64_t> w(static_cast<std::size_t>(b.hi[axis] - b.lo[axis]), 0);
  for (long c2 = b.lo[2]; c2 < b.hi[2]; ++c2)
    for (long c1 = b.lo[1]; c1 < b.hi[1]; ++c1)
      for (long c0 = b.lo[0]; c0 < b.hi[0]; ++c0) {
        const long c[3] = {c0, c1, c2};
        w[static_cast<std::size_t>(c[axis] - b.lo[axis])] += counts[grid.flat(c0, c1, c2)];
      }
  return w;
}

}  // namespace

Decomposition Decomposition::rcb(const CellGrid& grid, const std::vector<std::int64_t>& counts, int ranks) {
  if (ranks < 1) throw std::invalid_argument("rcb: at least one rank");
  if (counts.size() != grid.cells()) throw std::invalid_argument("rcb: one count per cell expected");
  if (grid.cells() < static_cast<std::size_t>(ranks))
    throw std::invalid_argument("rcb: " + std::to_string(grid.cells()) + " cells for " + std::to_string(ranks) +
                                " ranks (each rank needs a cell)");
  Decomposition d(grid);
  d.blocks_.resize(static_cast<std::size_t>(ranks));
  d.weights_.resize(static_cast<std::size_t>(ranks));
  CellBlock all;
  for (int a = 0; a < 3; ++a) all.hi[a] = grid.n(a);
  d.split(all, 0, ranks, counts);
  return d;
}

int Decomposition::split(const CellBlock& block, int r0, int r1, const std::vector<std::int64_t>& counts) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.push_back(Node{});
  const int p = r1 - r0;
  if (p == 1) {
    nodes_[static_cast<std::size_t>(index)].rank = r0;
    blocks_[static_cast<std::size_t>(r0)] = block;
    weights_[static_cast<std::size_t>(r0)] = 0;
    for (std::int64_t w : slab_weights(grid_, block, 0, counts)) weights_[static_cast<std::size_t>(r0)] += w;
    return index;
  }
  const int p_left = p / 2, p_right = p - p_left;
  // Axes by decreasing physical length (stable: ties keep the lower axis first).
  std::array<int, 3> axes{0, 1, 2};
  const int dim = grid_.dim();
  auto length = [&](int a) { return static_cast<double>(block.hi[a] - block.lo[a]) * grid_.side(a); };
  for (int i = 1; i < dim; ++i)
    for (int j = i; j > 0 && length(axes[static_cast<std::size_t>(j)]) > length(axes[static_cast<std::size_t>(j - 1)]); --j)
      std::swap(axes[static_cast<std::size_t>(j)], axes[static_cast<std::size_t>(j - 1)]);
  for (int k = 0; k < dim; ++k) {
    const int axis = axes[static_cast<std::size_t>(k)];
    const long extent = block.hi[axis] - block.lo[axis];
    const long cross = block.cells() / extent;
    // Each side keeps at least as many cells as ranks: cut in [min_left, extent - min_right].
    const long min_left = (p_left + cross - 1) / cross, min_right = (p_right + cross - 1) / cross;
    if (min_left > extent - min_right) continue;
    std::vector<std::int64_t> w = slab_weights(grid_, block, axis, counts);
    std::int64_t total = 0;
    for (std::int64_t x : w) total += x;
    if (total == 0)  // no particles: by cell count
      for (auto& x : w) x = cross, total += cross;
    const double target = static_cast<double>(total) * p_left / p;
    long best = min_left;
    double best_miss = INFINITY;
    std::int64_t prefix = 0;
    for (long c = 1; c <= extent - min_right; ++c) {
      prefix += w[static_cast<std::size_t>(c - 1)];
      if (c < min_left) continue;
      const double miss = std::abs(static_cast<double>(prefix) - target);
      if (miss < best_miss) best_miss = miss, best = c;
    }
    CellBlock left = block, right = block;
    left.hi[axis] = right.lo[axis] = block.lo[axis] + best;
    const int l = split(left, r0, r0 + p_left, counts);
    const int r = split(right, r0 + p_left, r1, counts);
    Node& node = nodes_[static_cast<std::size_t>(index)];
    node.axis = axis;
    node.cut = block.lo[axis] + best;
    node.left = l;
    node.right = r;
    return index;
  }
  // Possible only with barely more cells than ranks (3 x 3 cells for 8 ranks).
  throw std::logic_error("rcb: no admissible cut for a block of " + std::to_string(block.cells()) + " cells and " +
                         std::to_string(p) + " ranks");
}

Box Decomposition::box(int rank) const {
  const CellBlock& b = block(rank);
  Box box;
  for (int a = 0; a < grid_.dim(); ++a) {
    box.lo[a] = grid_.edge(a, b.lo[a]);
    box.hi[a] = grid_.edge(a, b.hi[a]);
  }
  return box;
}

int Decomposition::owner(const double* x) const {
  long c[3] = {0, 0, 0};
  for (int a = 0; a < grid_.dim(); ++a) c[a] = grid_.coord(a, x[a]);
  int n = 0;
  while (nodes_[static_cast<std::size_t>(n)].axis >= 0) {
    const Node& node = nodes_[static_cast<std::size_t>(n)];
    n = c[node.axis] < node.cut ? node.left : node.right;
  }
  return nodes_[static_cast<std::size_t>(n)].rank;
}

std::vector<std::int64_t> count_per_cell(const CellGrid& grid, const ParticleFields& particles) {
  std::vector<std::int64_t> counts(grid.cells(), 0);
  double x[3] = {0, 0, 0};
  for (std::size_t i = 0; i < particles.size(); ++i) {
    particles.position(i, x);
    ++counts[grid.cell_of(x)];
  }
  return counts;
}

}  // namespace arksph::parallel

