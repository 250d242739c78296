#include "projection/grid/grid_transfer.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace arksph {

namespace {
// The two cell indices bracketing coordinate s along an axis of n cells, and the weight of the upper.
void axis_weights(double s, double origin, double h, int n, bool periodic, int& i0, int& i1, double& w1) {
  if (n == 1) {
    i0 = i1 = 0;
    w1 = 0;
    return;
  }
  const double f = (s - origin) / h - 0.5;
  const double fl = std::floor(f);
  w1 = f - fl;
  i0 = static_cast<int>(fl);
  i1 = i0 + 1;
  if (periodic) {
    i0 = ((i0 % n) + n) % n;
    i1 = ((i1 % n) + n) % n;
  } else {
    if (i0 < 0) { i0 = 0; i1 = 0; w1 = 0; }
    if (i1 > n - 1) { i0 = n - 1; i1 = n - 1; w1 = 0; }
  }
}
}  // namespace

CellWeights cell_weights(const GridSpec& g, double x, double y) {
  int i0, i1, j0, j1;
  double wx, wy;
  axis_weights(x, g.x0, g.h, g.nx, g.periodic[0], i0, i1, wx);
  axis_weights(y, g.y0, g.h, g.ny, g.periodic[1], j0, j1, wy);
  CellWeights c;
  c.cell[0] = g.index(i0, j0);
  c.cell[1] = g.index(i1, j0);
  c.cell[2] = g.index(i0, j1);
  c.cell[3] = g.index(i1, j1);
  c.w[0] = (1 - wx) * (1 - wy);
  c.w[1] = wx * (1 - wy);
  c.w[2] = (1 - wx) * wy;
  c.w[3] = wx * wy;
  return c;
}

std::array<int, 4> cell_box(const GridSpec& g, std::size_t n, const double* x, const double* y) {
  std::array<int, 4> box{g.nx, -1, g.ny, -1};
  bool wraps[2] = {false, false};
  for (std::size_t a = 0; a < n; ++a) {
    int i0, i1, j0, j1;
    double w;
    axis_weights(x[a], g.x0, g.h, g.nx, g.periodic[0], i0, i1, w);
    axis_weights(y ? y[a] : 0.0, g.y0, g.h, g.ny, g.periodic[1], j0, j1, w);
    wraps[0] = wraps[0] || i1 < i0;
    wraps[1] = wraps[1] || j1 < j0;
    box[0] = std::min(box[0], std::min(i0, i1));
    box[1] = std::max(box[1], std::max(i0, i1));
    box[2] = std::min(box[2], std::min(j0, j1));
    box[3] = std::max(box[3], std::max(j0, j1));
  }
  if (n == 0) return {0, -1, 0, -1};
  if (wraps[0]) box[0] = 0, box[1] = g.nx - 1;
  if (wraps[1]) box[2] = 0, box[3] = g.ny - 1;
  return box;
}

namespace {
// The deposit's loop, with or without the cells' extremes (a compile-time choice: the loop without
// them tests nothing per cell).
template <bool kExtremes>
void deposit_into(const GridSpec& g, std::size_t n, const double* x, const double* y, const double* volume,
                  const double* q, DepositSums& d) {
  for (std::size_t a = 0; a < n; ++a) {
    const CellWeights c = cell_weights(g, x[a], y ? y[a] : 0.0);
    for (int k = 0; k < 4; ++k) {
      if (c.w[k] == 0) continue;
      const double wv = c.w[k] * volume[a];
      d.value[c.cell[k]] += wv * q[a];
      d.weight[c.cell[k]] += wv;
      if constexpr (kExtremes) {
        d.lo[c.cell[k]] = std::min(d.lo[c.cell[k]], q[a]);
        d.hi[c.cell[k]] = std::max(d.hi[c.cell[k]], q[a]);
      }
    }
  }
}
}  // namespace

DepositSums deposit_sums(const GridSpec& g, std::size_t n, const double* x, const double* y, const double* volume,
                         const double* q, bool extremes) {
  const std::size_t nc = g.cells();
  DepositSums d;
  d.value.assign(nc, 0.0);
  d.weight.assign(nc, 0.0);
  if (!extremes) {
    deposit_into<false>(g, n, x, y, volume, q, d);
    return d;
  }
  d.lo.assign(nc, HUGE_VAL);
  d.hi.assign(nc, -HUGE_VAL);
  deposit_into<true>(g, n, x, y, volume, q, d);
  return d;
}

GridDeposit finish_deposit(DepositSums&& s, double fallback) {
  GridDeposit d;
  d.value = std::move(s.value);
  d.weight = std::move(s.weight);
  const bool extremes = !s.lo.empty();
  for (std::size_t i = 0; i < d.value.size(); ++i) {
    if (d.weight[i] <= 0)
      d.value[i] = fallback;
    else if (extremes && s.lo[i] == s.hi[i])
      d.value[i] = s.lo[i];
    else
      d.value[i] /= d.weight[i];
  }
  return d;
}

GridDeposit deposit(const GridSpec& g, std::size_t n, const double* x, const double* y, const double* volume,
                    const double* q, double fallback) {
  return finish_deposit(deposit_sums(g, n, x, y, volume, q), fallback);
}

std::vector<double> interpolate(const GridSpec& g, std::size_t n, const double* x, const double* y,
                                const std::vector<double>& field) {
  std::vector<double> out(n);
  for (std::size_t a = 0; a < n; ++a) {
    const CellWeights c = cell_weights(g, x[a], y ? y[a] : 0.0);
    out[a] = c.w[0] * field[c.cell[0]] + c.w[1] * field[c.cell[1]] + c.w[2] * field[c.cell[2]] + c.w[3] * field[c.cell[3]];
  }
  return out;
}

std::vector<std::vector<double>> interpolate_fields(const GridSpec& g, std::size_t n, const double* x, const double* y,
                                                    const std::vector<const std::vector<double>*>& fields) {
  std::vector<std::vector<double>> out(fields.size(), std::vector<double>(n));
  for (std::size_t a = 0; a < n; ++a) {
    const CellWeights c = cell_weights(g, x[a], y ? y[a] : 0.0);
    for (std::size_t k = 0; k < fields.size(); ++k) {
      const std::vector<double>& field = *fields[k];
      out[k][a] = c.w[0] * field[c.cell[0]] + c.w[1] * field[c.cell[1]] + c.w[2] * field[c.cell[2]] + c.w[3] * field[c.cell[3]];
    }
  }
  return out;
}

}  // namespace arksph
