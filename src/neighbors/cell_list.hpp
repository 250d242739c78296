// Uniform cell list over a point cloud (real particles followed by ghosts), cell side >= search radius.
// Periodicity is not handled here: periodic images arrive as ghost points from boundary/ghosts.
#pragma once
#include <cstdint>
#include <vector>

namespace arksph {

class CellList {
 public:
  // Bins n points (y may be null in 1D) into cells of side >= radius.
  void build(const double* x, const double* y, std::size_t n, double radius);

  // Calls visit(j) for every point j (any index, including i itself) within `radius` of (px, py).
  template <class Visit>
  void for_each_near(double px, double py, Visit&& visit) const {
    const long cx = cell_coord(px, x0_), cy = y_ ? cell_coord(py, y0_) : 0;
    for (long jy = cy - 1; jy <= cy + 1; ++jy) {
      if (jy < 0 || jy >= ny_) continue;
      for (long jx = cx - 1; jx <= cx + 1; ++jx) {
        if (jx < 0 || jx >= nx_) continue;
        const std::size_t c = static_cast<std::size_t>(jy * nx_ + jx);
        for (std::uint32_t k = start_[c]; k < start_[c + 1]; ++k) {
          const std::uint32_t j = order_[k];
          const double dx = px - x_[j], dy = y_ ? py - y_[j] : 0.0;
          if (dx * dx + dy * dy < r2_) visit(j, dx, dy);
        }
      }
    }
  }

 private:
  long cell_coord(double p, double p0) const { return static_cast<long>((p - p0) * inv_side_); }
  const double* x_ = nullptr;
  const double* y_ = nullptr;
  double x0_ = 0, y0_ = 0, inv_side_ = 1, r2_ = 0;
  long nx_ = 1, ny_ = 1;
  std::vector<std::uint32_t> start_, order_;
};

// Neighbour pairs of each real particle a (a < n_real) among all points, self excluded, with
// r_ab = r_a - r_b, the kernel value W_ab and F_ab = (dW/dr)/r, so that grad_a W_ab = F_ab r_ab.
// Stored with a fixed stride per particle so that it is filled in parallel without atomics.
struct PairList {
  std::size_t n_real = 0, stride = 0;
  std::vector<std::uint32_t> count;  // neighbours of a
  std::vector<std::uint32_t> j;      // index b of the k-th neighbour of a: j[a * stride + k]
  std::vector<double> rx, ry, r2, w, f;
  template <class Body>
  void for_pairs(std::size_t a, Body&& body) const {
    const std::size_t base = a * stride, end = base + count[a];
    for (std::size_t k = base; k < end; ++k) body(j[k], rx[k], ry[k], r2[k], w[k], f[k]);
  }
};

class Kernel;
// Fills `pairs` for real particles 0..n_real-1 against all n_all points. Returns the largest count.
void build_pairs(const CellList& cells, const Kernel& kernel, const double* x, const double* y,
                 std::size_t n_real, PairList& pairs);

}  // namespace arksph
