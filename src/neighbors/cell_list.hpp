// Uniform cell list over a point cloud (real particles followed by ghosts), cell side >= search radius.
// Periodicity is not handled here: periodic images arrive as ghost points from boundary/ghosts.
#pragma once
#include <algorithm>
#include <cstdint>
#include <vector>

#include "kernels/kernel.hpp"
#include "neighbors/split_sum.hpp"

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
    for_each_run(px, py, [&](std::uint32_t k_begin, std::uint32_t k_end) {
      for (std::uint32_t k = k_begin; k < k_end; ++k) {
        const double dx = px - sx_[k], dy = two_d_ ? py - sy_[k] : 0.0;
        if (dx * dx + dy * dy < r2_) visit(order_[k], dx, dy);
      }
    });
  }

  // Calls run(k_begin, k_end) for each row of the 3 x 3 stencil around (px, py): the sorted points
  // k_begin .. k_end - 1 (point(), sorted_x(), sorted_y()) are those of the row's three cells. For
  // loops that test every point without a branch (build_candidates).
  template <class Run>
  void for_each_run(double px, double py, Run&& run) const {
    const long cx = cell_coord(px, x0_), cy = two_d_ ? cell_coord(py, y0_) : 0;
    const long x_lo = std::max(cx - 1, 0L), x_hi = std::min(cx + 1, nx_ - 1);
    for (long jy = std::max(cy - 1, 0L); jy <= std::min(cy + 1, ny_ - 1); ++jy)
      run(start_[static_cast<std::size_t>(jy * nx_ + x_lo)], start_[static_cast<std::size_t>(jy * nx_ + x_hi) + 1]);
  }
  const std::uint32_t* point() const { return order_.data(); }  // point index of each sorted entry
  const double* sorted_x() const { return sx_.data(); }
  const double* sorted_y() const { return two_d_ ? sy_.data() : nullptr; }
  double radius2() const { return r2_; }

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

[[noreturn]] void pair_list_not_built();

// Neighbour pairs of each real particle a (a < n_real) among all points, self excluded, with
// r_ab = r_a - r_b, the kernel value W_ab and F_ab = (dW/dr)/r, so that grad_a W_ab = F_ab r_ab.
// Compressed rows: a's pairs are entries start[a] .. start[a] + count[a] - 1, counted in a first pass
// and filled in parallel in a second (no atomics, no padding: 20 bytes a pair). Only the index, W and
// F are stored; r_ab is recomputed from the positions the list was built from (px, py, which must
// outlive the list's use), in the same floating-point operations as when the pair was found, so
// results do not depend on the storage.
struct PairList {
  std::size_t n_real = 0;
  std::vector<std::size_t> start;    // first entry of a
  std::vector<std::uint32_t> count;  // neighbours of a
  std::vector<std::uint32_t> j;      // index b of the k-th neighbour of a: j[start[a] + k]
  std::vector<double> w, f;
  const double* px = nullptr;  // positions of all points (py null in 1D)
  const double* py = nullptr;
  std::size_t total() const {
    std::size_t s = 0;
    for (std::size_t a = 0; a < n_real; ++a) s += count[a];
    return s;
  }
  // Makes room for cap entries (contents are not kept: the caller refills them). Never shrinks, so
  // no allocation in steady state; grows by 1/16 at a time, each array freed before its new one is
  // made (vector::resize would double the capacity and hold both blocks at once).
  void reserve(std::size_t cap) {
    if (j.size() >= cap) return;
    cap += cap / 16;
    regrow(j, cap);
    regrow(w, cap);
    regrow(f, cap);
  }
  template <class T>
  static void regrow(std::vector<T>& v, std::size_t cap) {
    std::vector<T>().swap(v);
    v.resize(cap);
  }
  // Lean storage (method.neighbor_storage = "candidates"): no per-pair arrays; for_pairs walks the
  // Verlet candidates, skips those outside the support and evaluates the kernel on the fly (same
  // values, same order as the stored list; slower, about 20 bytes a pair less).
  const std::vector<std::size_t>* cand_start = nullptr;
  const std::vector<std::uint32_t>* cand_count = nullptr;
  const std::vector<std::uint32_t>* cand_j = nullptr;
  const Kernel* kernel = nullptr;
  double r2_max = 0;
  // body(b, rx, ry, r2, W_ab, F_ab) for every neighbour b of a.
  template <class Body>
  void for_pairs(std::size_t a, Body&& body) const {
    // One compare per particle (not per pair): a programming error, reported as such. With the force
    // sweep, a WCSPH f(t, y) with ydot stores no pairs; eval(t, y, nullptr) refreshes them.
    if (a >= n_real) [[unlikely]] pair_list_not_built();
    const double xa = px[a], ya = py ? py[a] : 0.0;
    if (kernel) {
      const std::size_t cbase = (*cand_start)[a], cend = cbase + (*cand_count)[a];
      const std::uint32_t* cj = cand_j->data();
      for (std::size_t c = cbase; c < cend; ++c) {
        const std::uint32_t b = cj[c];
        const double rx = xa - px[b], ry = py ? ya - py[b] : 0.0;
        const double r2 = rx * rx + ry * ry;
        if (!(r2 < r2_max)) continue;
        double w = 0, f = 0;
        kernel->eval_r2(r2, w, f);
        body(b, rx, ry, r2, w, f);
      }
      return;
    }
    const std::size_t base = start[a], end = base + count[a];
    for (std::size_t k = base; k < end; ++k) {
      const std::uint32_t b = j[k];
      const double rx = xa - px[b], ry = py ? ya - py[b] : 0.0;
      body(b, rx, ry, rx * rx + ry * ry, w[k], f[k]);
    }
  }
  // body(lane, b, rx, ry, r2, W_ab, F_ab) with lane = Lane<k % 2> for a's k-th neighbour (SplitSum);
  // with C::plain two pairs at a time where stored, as Neighborhood::for_pairs_split.
  template <class C, class Body>
  void for_pairs_split(C, std::size_t a, Body&& body) const {
    if (a >= n_real) [[unlikely]] pair_list_not_built();
    if (kernel) {  // lean storage: the pairs are found on the way, so count them (one lane at a time)
      bool odd = false;
      for_pairs(a, [&](std::uint32_t b, double rx, double ry, double r2, double w, double F) {
        if (odd)
          body(Lane<1>{}, b, rx, ry, r2, w, F);
        else
          body(Lane<0>{}, b, rx, ry, r2, w, F);
        odd = !odd;
      });
      return;
    }
    const double xa = px[a], ya = py ? py[a] : 0.0;
    auto one = [&](auto lane, std::size_t k) {
      const std::uint32_t b = j[k];
      const double rx = xa - px[b], ry = py ? ya - py[b] : 0.0;
      body(lane, b, rx, ry, rx * rx + ry * ry, w[k], f[k]);
    };
    if constexpr (C::plain) {  // two dimensions
      visit_two_at_a_time(start[a], start[a] + count[a], [&](std::size_t k) {
        const std::uint32_t b0 = j[k], b1 = j[k + 1];
        const Two rx = Two{xa, xa} - Two{px[b0], px[b1]}, ry = Two{ya, ya} - Two{py[b0], py[b1]};
        body(BothLanes{}, TwoIndices{b0, b1}, rx, ry, rx * rx + ry * ry, load_two(&w[k]), load_two(&f[k]));
      }, one);
    } else {
      visit_in_lanes(start[a], start[a] + count[a], one);
    }
  }
};

// Fills `pairs` for real particles 0..n_real-1 against all n_all points. Returns the largest count.
void build_pairs(const CellList& cells, const Kernel& kernel, const double* x, const double* y,
                 std::size_t n_real, PairList& pairs);

}  // namespace arksph

namespace arksph {

// Verlet candidates: for each real particle, the points within radius + skin at the last rebuild.
// While no particle has moved more than skin / 2 since then, every pair closer than the radius is
// among the candidates, so the pair list is refreshed from them without a cell search.
// Compressed rows as in PairList: a's candidates are j[start[a] .. start[a] + count[a] - 1].
struct CandidateList {
  std::size_t n_real = 0;
  std::vector<std::size_t> start;
  std::vector<std::uint32_t> count, j;
};

// cells must have been built with radius + skin over all points.
void build_candidates(const CellList& cells, const double* x, const double* y, std::size_t n_real,
                      CandidateList& cand);
// The pairs among the candidates closer than the kernel radius, with kernel values (as build_pairs).
void pairs_from_candidates(const CandidateList& cand, const Kernel& kernel, const double* x, const double* y,
                           PairList& pairs);
// The same neighbours without per-pair storage: only the counts; for_pairs then reads the candidates
// (which must outlive the list's use) and evaluates the kernel.
void lean_pairs_from_candidates(const CandidateList& cand, const Kernel& kernel, const double* x, const double* y,
                                PairList& pairs);

}  // namespace arksph
