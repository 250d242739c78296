#include "integrate/dependency_pattern.hpp"

#include <algorithm>
#include <cmath>

#include "neighbors/cell_list.hpp"

namespace arksph {

namespace {
// Minimum-image separation along axis k (both searches use this very expression).
double gap(double d, int k, const PeriodicAxes& axes) {
  if (axes.periodic[k]) d -= axes.len[k] * std::round(d / axes.len[k]);
  return d;
}

bool within(const double* x, const double* y, std::size_t a, std::size_t b, double r2, const PeriodicAxes& axes) {
  const double dx = gap(x[a] - x[b], 0, axes), dy = y ? gap(y[a] - y[b], 1, axes) : 0.0;
  return dx * dx + dy * dy <= r2;
}

// Points plus their periodic copies: px, py coordinates; src the particle each point stands for.
struct ImagedPoints {
  std::vector<double> px, py;
  std::vector<std::uint32_t> src;
  // Appends, for every point present so far, its copies shifted by +-len along axis k that can
  // come within `reach` of some point. A pair whose minimum image crosses the seam (round = +1,
  // x_a - x_b - len >= -reach) has x_b <= hi - len + reach: copying those by +len (and, by
  // symmetry, the points x_b >= lo + len - reach by -len) covers every such pair. Pairs more than
  // half a period outside the box (round = +-2) would be a blown-up run and are not sought.
  void add_images(int k, double len, double reach) {
    std::vector<double>& c = k == 0 ? px : py;
    const std::size_t m = c.size();
    if (m == 0) return;
    const auto [lo_it, hi_it] = std::minmax_element(c.begin(), c.end());
    const double lo = *lo_it, hi = *hi_it;
    for (std::size_t i = 0; i < m; ++i) {
      for (const double shift : {len, -len}) {
        const bool near_seam = shift > 0 ? c[i] <= hi - len + reach : c[i] >= lo + len - reach;
        if (!near_seam) continue;
        px.push_back(px[i] + (k == 0 ? shift : 0.0));
        if (!py.empty()) py.push_back(py[i] + (k == 1 ? shift : 0.0));
        src.push_back(src[i]);
      }
    }
  }
};
}  // namespace

std::vector<std::vector<std::uint32_t>> dependency_pattern(const double* x, const double* y, std::size_t n,
                                                           double radius, const PeriodicAxes& axes) {
  const double r2 = radius * radius;
  ImagedPoints pts;
  pts.px.assign(x, x + n);
  if (y) pts.py.assign(y, y + n);
  pts.src.resize(n);
  for (std::size_t i = 0; i < n; ++i) pts.src[i] = static_cast<std::uint32_t>(i);
  // The cell list finds distances < its radius: search a little wider, then decide every
  // candidate by the exact test of the brute force (<= radius, minimum image).
  const double reach = radius * (1.0 + 1e-9);
  for (int k = 0; k < (y ? 2 : 1); ++k)
    if (axes.periodic[k]) pts.add_images(k, axes.len[k], reach);
  CellList cells;
  cells.build(pts.px.data(), y ? pts.py.data() : nullptr, pts.px.size(), reach);
  std::vector<std::vector<std::uint32_t>> pat(n);
  for (std::size_t a = 0; a < n; ++a) {
    std::vector<std::uint32_t>& row = pat[a];
    cells.for_each_near(x[a], y ? y[a] : 0.0, [&](std::uint32_t p, double, double) {
      const std::uint32_t b = pts.src[p];
      if (within(x, y, a, b, r2, axes)) row.push_back(b);
    });
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());  // b and its copy may both be in reach
  }
  return pat;
}

std::vector<std::vector<std::uint32_t>> dependency_pattern_brute(const double* x, const double* y, std::size_t n,
                                                                 double radius, const PeriodicAxes& axes) {
  const double r2 = radius * radius;
  std::vector<std::vector<std::uint32_t>> pat(n);
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = 0; b < n; ++b)
      if (within(x, y, a, b, r2, axes)) pat[a].push_back(static_cast<std::uint32_t>(b));
  return pat;
}

std::vector<int> greedy_colouring(const std::vector<std::vector<std::uint32_t>>& near, bool distance2, int& colours) {
  const std::size_t n = near.size();
  std::vector<int> colour(n, -1);
  std::vector<std::size_t> stamp(n + 1, n);  // stamp[c] == j: colour c is taken for vertex j
  colours = 0;
  const auto take = [&](std::uint32_t k, std::size_t j) {
    if (colour[k] >= 0) stamp[static_cast<std::size_t>(colour[k])] = j;
  };
  for (std::size_t j = 0; j < n; ++j) {
    for (std::uint32_t a : near[j])
      if (distance2)
        for (std::uint32_t k : near[a]) take(k, j);
      else
        take(a, j);
    int c = 0;
    while (stamp[static_cast<std::size_t>(c)] == j) ++c;
    colour[j] = c;
    colours = std::max(colours, c + 1);
  }
  return colour;
}

}  // namespace arksph
