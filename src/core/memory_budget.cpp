#include "core/memory_budget.hpp"

#include <sys/resource.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <numbers>
#include <sstream>

#include "core/errors.hpp"
#include "kernels/kernel.hpp"

namespace arksph {

namespace {
constexpr double kBytesPerParticle = 200, kBytesPerPair = 16, kBytesPerPpePair = 40, kBytesPerGridCell = 1500;

// MemAvailable in bytes, +infinity if /proc/meminfo does not tell.
double mem_available() {
  std::ifstream in("/proc/meminfo");
  std::string line;
  while (std::getline(in, line)) {
    double kb = 0;
    if (std::sscanf(line.c_str(), "MemAvailable: %lf kB", &kb) == 1) return kb * 1024.0;
  }
  return std::numeric_limits<double>::infinity();
}
}  // namespace

double parse_byte_count(const std::string& text, const std::string& what) {
  const char* s = text.c_str();
  char* end = nullptr;
  const double v = std::strtod(s, &end);
  double scale = 1;
  std::string suffix(end ? end : "");
  if (suffix.size() == 2 && (suffix[1] == 'B' || suffix[1] == 'b')) suffix.pop_back();  // "4GB"
  if (suffix.size() == 1) {
    switch (suffix[0]) {
      case 'k': case 'K': scale = 1024.0; break;
      case 'm': case 'M': scale = 1024.0 * 1024; break;
      case 'g': case 'G': scale = 1024.0 * 1024 * 1024; break;
      case 't': case 'T': scale = 1024.0 * 1024 * 1024 * 1024; break;
      default: scale = 0;
    }
  } else if (!suffix.empty()) {
    scale = 0;
  }
  if (end == s || scale == 0 || !std::isfinite(v) || v <= 0)
    throw InputError(what + ": expected a positive number of bytes such as 4000000000 or 4G, got \"" + text + "\"");
  return v * scale;
}

MemoryLimit memory_limit() {
  if (const char* env = std::getenv("ARKSPH_MEMORY_LIMIT"))
    return {parse_byte_count(env, "ARKSPH_MEMORY_LIMIT"), "ARKSPH_MEMORY_LIMIT"};
  MemoryLimit m{mem_available(), "MemAvailable"};
  struct rlimit r {};
  if (getrlimit(RLIMIT_AS, &r) == 0 && r.rlim_cur != RLIM_INFINITY && static_cast<double>(r.rlim_cur) < m.bytes)
    m = {static_cast<double>(r.rlim_cur), "RLIMIT_AS"};
  return m;
}

std::string format_bytes(double bytes) {
  const char* units[] = {"bytes", "kB", "MB", "GB", "TB", "PB", "EB"};
  int u = 0;
  while (bytes >= 1000 && u < 6) {
    bytes /= 1000;
    ++u;
  }
  char buf[48];
  std::snprintf(buf, sizeof buf, u == 0 ? "%.0f %s" : "%.3g %s", bytes, units[u]);
  return buf;
}

MemoryEstimate estimate_run_memory(const Scene& s) {
  MemoryEstimate e;
  e.particles = 1;
  for (int k = 0; k < s.dimension; ++k) e.particles *= std::round((s.max[k] - s.min[k]) / s.spacing);
  // Neighbours of a particle: the lattice points within the kernel radius R (pi R^2 / dx^2 in 2D).
  const double radius = make_kernel(s.kernel, s.h_over_dx * s.spacing, s.dimension).radius() / s.spacing;
  const double neighbours = s.dimension == 2 ? std::numbers::pi * radius * radius : 2 * radius;
  e.pairs = e.particles * neighbours;
  const double pair_bytes = kBytesPerPair + (s.scheme == "isph" ? kBytesPerPpePair : 0.0);
  e.bytes = e.particles * kBytesPerParticle + e.pairs * pair_bytes;
  e.key = "fluid.spacing";
  if (s.scheme == "isph-gpps") {
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
  std::ostringstream msg;
  msg.precision(3);
  msg << scene.source << ": " << e.key << ": the run needs at least " << format_bytes(e.bytes) << " (" << e.particles
      << " particles, " << e.pairs << " neighbour pairs";
  if (e.grid_cells > 0) msg << ", " << e.grid_cells << " grid cells";
  msg << "), more than the memory limit of " << format_bytes(limit.bytes) << " (" << limit.source
      << "; ARKSPH_MEMORY_LIMIT sets another)";
  throw InputError(msg.str());
}

}  // namespace arksph
