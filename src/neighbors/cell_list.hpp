// Uniform cell list over a point cloud (real particles followed by ghosts), cell side >= search radius.
// Periodicity is not handled here: periodic images arrive as ghost points from boundary/ghosts.
#pragma once
#include <algorithm>
#include <cstdint>
#include <vector>

namespace arksph {

class CellList {
 public:
  // Bins n points (y may be null in 1D) into cells of side >= radius.
  void build(const double* x, const double* y, std::size_t n, double radius);

  // Calls visit(j, dx, dy) for every point j (any index, including i itself) with
  // |(px, py) - r_j| < radius, where (dx, dy) = (px, py) - r_j. Coordinates are read from copies
  // sorted by cell, so the three cells of a stencil row are one contiguous range.
  template <class Visit>
  void for_each_near(double px, double py, Visit&& visit) const {
    const long cx = cell_coord(px, x0_), cy = two_d_ ? cell_coord(py, y0_) : 0;
    const long x_lo = std::max(cx - 1, 0L), x_hi = std::min(cx + 1, nx_ - 1);
    for (long jy = std::max(cy - 1, 0L); jy <= std::min(cy + 1, ny_ - 1); ++jy) {
      const std::uint32_t k_begin = start_[static_cast<std::size_t>(jy * nx_ + x_lo)];
      const std::uint32_t k_end = start_[static_cast<std::size_t>(jy * nx_ + x_hi) + 1];
      for (std::uint32_t k = k_begin; k < k_end; ++k) {
        const double dx = px - sx_[k], dy = two_d_ ? py - sy_[k] : 0.0;
        if (dx * dx + dy * dy < r2_) visit(order_[k], dx, dy);
      }
    }
  }

 private:
  // Clamped, so that a point far outside (or NaN) cannot index outside the grid.
  long cell_coord(double p, double p0) const {
    const double c = (p - p0) * inv_side_;
    return c >= 0 && c < 1e9 ? static_cast<long>(c) : 0;
  }
  bool two_d_ = true;
  double x0_ = 0, y0_ = 0, inv_side_ = 1, r2_ = 0;
  long nx_ = 1, ny_ = 1;
  std::vector<std::uint32_t> start_, order_;  // cell offsets; point index in cell order
  std::vector<double> sx_, sy_;                // coordinates in cell order
};

// Neighbour pairs of each real particle a (a < n_real) among all points, self excluded, with
// r_ab = r_a - r_b, the kernel value W_ab and F_ab = (dW/dr)/r, so that grad_a W_ab = F_ab r_ab.
// Stored with a fixed stride per particle so that it is filled in parallel without atomics. Only the
// index, W and F are stored (16 + 4 bytes a pair); r_ab is recomputed from the positions the list was
// built from (px, py, which must outlive the list's use), in the same floating-point operations as
// when the pair was found, so results do not depend on the storage.
struct PairList {
  std::size_t n_real = 0, stride = 0;
  std::vector<std::uint32_t> count;  // neighbours of a
  std::vector<std::uint32_t> j;      // index b of the k-th neighbour of a: j[a * stride + k]
  std::vector<double> w, f;
  const double* px = nullptr;  // positions of all points (py null in 1D)
  const double* py = nullptr;
  // Grows the per-pair arrays to hold cap entries (never shrinks: no allocation in steady state).
  void reserve(std::size_t cap) {
    if (j.size() >= cap) return;
    j.resize(cap);
    w.resize(cap);
    f.resize(cap);
  }
  // body(b, rx, ry, r2, W_ab, F_ab) for every neighbour b of a.
  template <class Body>
  void for_pairs(std::size_t a, Body&& body) const {
    const std::size_t base = a * stride, end = base + count[a];
    const double xa = px[a], ya = py ? py[a] : 0.0;
    for (std::size_t k = base; k < end; ++k) {
      const std::uint32_t b = j[k];
      const double rx = xa - px[b], ry = py ? ya - py[b] : 0.0;
      body(b, rx, ry, rx * rx + ry * ry, w[k], f[k]);
    }
  }
};

class Kernel;
// Fills `pairs` for real particles 0..n_real-1 against all n_all points. Returns the largest count.
void build_pairs(const CellList& cells, const Kernel& kernel, const double* x, const double* y,
                 std::size_t n_real, PairList& pairs);

}  // namespace arksph

namespace arksph {

// Verlet candidates: for each real particle, the points within radius + skin at the last rebuild.
// While no particle has moved more than skin / 2 since then, every pair closer than the radius is
// among the candidates, so the pair list is refreshed from them without a cell search.
struct CandidateList {
  std::size_t n_real = 0, stride = 0;
  std::vector<std::uint32_t> count, j;
};

// cells must have been built with radius + skin over all points.
void build_candidates(const CellList& cells, const double* x, const double* y, std::size_t n_real,
                      CandidateList& cand);
// The pairs among the candidates closer than the kernel radius, with kernel values (as build_pairs).
void pairs_from_candidates(const CandidateList& cand, const Kernel& kernel, const double* x, const double* y,
                           PairList& pairs);

}  // namespace arksph
