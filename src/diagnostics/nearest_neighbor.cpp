#include "diagnostics/nearest_neighbor.hpp"

#include <cmath>
#include <limits>

namespace arksph {

Histogram nearest_neighbor_histogram(const FluidFields& f, double dx, double bin_width, double max_ratio) {
  return nearest_neighbor_histogram_of(f, f.n_real, dx, bin_width, max_ratio);
}

Histogram nearest_neighbor_histogram_of(const FluidFields& f, std::size_t n, double dx, double bin_width,
                                        double max_ratio) {
  Histogram h;
  h.bin_width = bin_width;
  const auto bins = static_cast<std::size_t>(std::ceil(max_ratio / bin_width));
  h.counts.assign(bins, 0);
  for (std::size_t a = 0; a < n; ++a) {
    double r2min = std::numeric_limits<double>::infinity();
    f.pairs.for_pairs(a, [&](std::uint32_t b, double, double, double r2, double, double) {
      // Real neighbours and their periodic images; not wall images, which mirror the same gaps.
      if ((b < f.n_real || !f.is_wall_image(b)) && r2 < r2min) r2min = r2;
    });
    if (!std::isfinite(r2min)) continue;  // isolated particle: no neighbour within the support
    const auto k = static_cast<std::size_t>(std::sqrt(r2min) / dx / bin_width);
    ++h.counts[std::min(k, bins - 1)];
  }
  return h;
}

}  // namespace arksph
