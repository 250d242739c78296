// The simulation box as the domain decomposition sees it: its corners, which axes are periodic, and a
// uniform grid of cells over it (the unit of the recursive coordinate bisection, rcb.hpp).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace arksph::parallel {

// An axis-aligned box [lo, hi) in `dim` dimensions (1 to 3; the axes beyond dim are ignored).
struct Box {
  std::array<double, 3> lo{}, hi{};
  bool contains(const double* x, int dim) const {
    for (int a = 0; a < dim; ++a)
      if (!(x[a] >= lo[a] && x[a] < hi[a])) return false;
    return true;
  }
  // Squared Euclidean distance from x to the box (0 inside).
  double distance2(const double* x, int dim) const {
    double d2 = 0;
    for (int a = 0; a < dim; ++a) {
      const double d = std::max({lo[a] - x[a], 0.0, x[a] - hi[a]});
      d2 += d * d;
    }
    return d2;
  }
  // Squared Euclidean distance between this box shifted by `shift` and `other` (0 if they overlap).
  double distance2(const Box& other, const std::array<double, 3>& shift, int dim) const {
    double d2 = 0;
    for (int a = 0; a < dim; ++a) {
      const double d = std::max({other.lo[a] - (hi[a] + shift[a]), 0.0, (lo[a] + shift[a]) - other.hi[a]});
      d2 += d * d;
    }
    return d2;
  }
};

struct Domain {
  int dim = 2;
  Box box;
  std::array<bool, 3> periodic{};
  double period(int a) const { return box.hi[a] - box.lo[a]; }
  // Brings x back into [lo, hi) along the periodic axes (any number of periods away); the other
  // axes are left as they are.
  void wrap(double* x) const {
    for (int a = 0; a < dim; ++a) {
      if (!periodic[a] || (x[a] >= box.lo[a] && x[a] < box.hi[a]) || !std::isfinite(x[a])) continue;
      const double L = period(a);
      if (x[a] < box.lo[a] && x[a] + L >= box.lo[a])
        x[a] += L;
      else if (x[a] >= box.hi[a] && x[a] - L < box.hi[a])
        x[a] -= L;
      else
        x[a] -= L * std::floor((x[a] - box.lo[a]) / L);
      if (x[a] >= box.hi[a] || x[a] < box.lo[a]) x[a] = box.lo[a];  // round-off at a side
    }
  }
};

// n[a] = floor(L_a / min_side) cells along each axis (at least one), of side L_a / n[a] >= min_side,
// so that the cells tile the box exactly. Cell (c0, c1, c2) has the flat index c0 + n0 (c1 + n1 c2).
class CellGrid {
 public:
  CellGrid(const Domain& domain, double min_side) : domain_(domain) {
    for (int a = 0; a < 3; ++a) {
      n_[a] = 1;
      side_[a] = 1;
      if (a < domain.dim) {
        const double L = domain.period(a);
        n_[a] = std::max<long>(1, static_cast<long>(std::floor(L / min_side)));
        side_[a] = L / static_cast<double>(n_[a]);
      }
    }
  }
  const Domain& domain() const { return domain_; }
  int dim() const { return domain_.dim; }
  long n(int a) const { return n_[a]; }
  std::size_t cells() const { return static_cast<std::size_t>(n_[0] * n_[1] * n_[2]); }
  double side(int a) const { return side_[a]; }
  // Coordinate of the cell edge c along a (c = 0 .. n[a]); the last edge is the box side itself.
  double edge(int a, long c) const {
    return c >= n_[a] ? domain_.box.hi[a] : domain_.box.lo[a] + static_cast<double>(c) * side_[a];
  }
  // Cell coordinate along a, clamped to the grid: points outside a wall (or NaN) go to the nearest cell.
  long coord(int a, double x) const {
    if (a >= domain_.dim) return 0;
    const double c = std::floor((x - domain_.box.lo[a]) / side_[a]);
    if (!(c >= 0)) return 0;
    return c >= static_cast<double>(n_[a]) ? n_[a] - 1 : static_cast<long>(c);
  }
  std::size_t flat(long c0, long c1, long c2) const { return static_cast<std::size_t>(c0 + n_[0] * (c1 + n_[1] * c2)); }
  std::size_t cell_of(const double* x) const {
    const int d = domain_.dim;
    return flat(coord(0, x[0]), d > 1 ? coord(1, x[1]) : 0, d > 2 ? coord(2, x[2]) : 0);
  }

 private:
  Domain domain_;
  std::array<long, 3> n_{};
  std::array<double, 3> side_{};
};

}  // namespace arksph::parallel
