// Recursive coordinate bisection over the cells of a CellGrid, weighted by the particles per cell.
//
// The rank range [r0, r1) of a block of cells is split into p_left = floor(p / 2) and
// p_right = p - p_left ranks (p = r1 - r0, any p, not only powers of two). The block is cut across
// its longest side (physical length; ties: the lowest axis) between two slabs of cells, at the slab
// boundary whose left-hand weight is closest to W p_left / p (ties: the lowest cut), such that each
// side keeps at least as many cells as ranks. Each half is then split in the same way, down to one
// rank per block. A block of zero weight is cut by cell count instead.
//
// The result depends only on the grid, the counts and p, so every rank computes the same one from
// the globally summed counts (Communicator::sum_in_place). Each rank's box is a block of whole
// cells; the owner of a position is the owner of its cell (positions outside a wall belong to the
// nearest cell; periodic axes are wrapped first, Domain::wrap).
#pragma once
#include <cstdint>
#include <vector>

#include "parallel/domain.hpp"
#include "parallel/particle_fields.hpp"

namespace arksph::parallel {

// A block of cells [lo[a], hi[a]) along each axis.
struct CellBlock {
  std::array<long, 3> lo{}, hi{};
  long cells() const { return (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]); }
};

class Decomposition {
 public:
  // counts: one weight per cell of the grid (flat index), the same on every rank. Throws
  // std::invalid_argument when the grid has fewer cells than ranks, std::logic_error when a block
  // cannot be cut so that both sides keep as many cells as ranks (barely more cells than ranks).
  static Decomposition rcb(const CellGrid& grid, const std::vector<std::int64_t>& counts, int ranks);

  const CellGrid& grid() const { return grid_; }
  int ranks() const { return static_cast<int>(blocks_.size()); }
  const CellBlock& block(int rank) const { return blocks_[static_cast<std::size_t>(rank)]; }
  Box box(int rank) const;
  // Sum of the counts over the cells of rank's block.
  std::int64_t weight(int rank) const { return weights_[static_cast<std::size_t>(rank)]; }
  // The rank whose block holds the cell of x (x wrapped into the box on periodic axes beforehand).
  int owner(const double* x) const;

 private:
  explicit Decomposition(const CellGrid& grid) : grid_(grid) {}
  struct Node {
    int axis = -1;          // -1: leaf
    long cut = 0;           // cells with coordinate < cut go to `left`
    int left = 0, right = 0;  // node indices
    int rank = 0;           // leaf: its rank
  };
  int split(const CellBlock& block, int r0, int r1, const std::vector<std::int64_t>& counts);
  CellGrid grid_;
  std::vector<Node> nodes_;
  std::vector<CellBlock> blocks_;
  std::vector<std::int64_t> weights_;
};

// Particles per cell of the grid among `particles` (this rank only; sum over the ranks for rcb).
std::vector<std::int64_t> count_per_cell(const CellGrid& grid, const ParticleFields& particles);

}  // namespace arksph::parallel
