#include "run/memory_estimate.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>

#include "core/errors.hpp"
#include "core/memory_limit.hpp"
#include "core/scheme.hpp"
#include "kernels/kernel.hpp"

namespace arksph {

namespace {
constexpr double kBytesPerParticle = 200, kBytesPerPair = 16, kBytesPerPpePair = 40, kBytesPerGridCell = 1500;
}  // namespace

MemoryEstimate estimate_run_memory(const Scene& s) {
  MemoryEstimate e;
  e.particles = 1;
  for (int k = 0; k < s.dimension; ++k) e.particles *= std::round((s.max[k] - s.min[k]) / s.spacing);
  // Neighbours of a particle: the lattice points within the kernel radius R (pi R^2 / dx^2 in 2D).
  const double radius = make_kernel(s.kernel, s.h_over_dx * s.spacing, s.dimension).radius() / s.spacing;
  const double neighbours = s.dimension == 2 ? std::numbers::pi * radius * radius : 2 * radius;
  e.pairs = e.particles * neighbours;
  const SchemeTraits& scheme = scheme_traits(s.scheme);
  const double pair_bytes = kBytesPerPair + (scheme.particle_poisson() ? kBytesPerPpePair : 0.0);
  e.bytes = e.particles * kBytesPerParticle + e.pairs * pair_bytes;
  e.key = "fluid.spacing";
  if (scheme.grid) {
    const double cell = s.gpps_spacing > 0 ? s.gpps_spacing : s.spacing;
    e.grid_cells = 1;
    for (int k = 0; k < s.dimension; ++k) e.grid_cells *= std::round((s.max[k] - s.min[k]) / cell);
    e.bytes += e.grid_cells * kBytesPerGridCell;
    if (e.grid_cells * kBytesPerGridCell > e.bytes / 2) e.key = "method.gpps_spacing";
  }
  return e;
}

void check_run_memory(const Scene& scene) {
  const MemoryEstimate e = estimate_run_memory(scene);
  const MemoryLimit limit = memory_limit();
  if (e.bytes <= limit.bytes) return;
  auto count = [](double v) {  // 2500, 1.26e+05
    char buf[32];
    std::snprintf(buf, sizeof buf, v < 1e5 ? "%.0f" : "%.3g", v);
    return std::string(buf);
  };
  std::ostringstream msg;
  msg << scene.source << ": " << e.key << ": the run needs at least " << format_bytes(e.bytes) << " ("
      << count(e.particles) << " particles, " << count(e.pairs) << " neighbour pairs";
  if (e.grid_cells > 0) msg << ", " << count(e.grid_cells) << " grid cells";
  msg << "), more than the memory limit of " << format_bytes(limit.bytes) << " (" << limit.source
      << (limit.source == "ARKSPH_MEMORY_LIMIT" ? ")" : "; ARKSPH_MEMORY_LIMIT sets another)");
  throw InputError(msg.str());
}

}  // namespace arksph
