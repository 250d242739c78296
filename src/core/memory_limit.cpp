#include "core/memory_limit.hpp"

#include <sys/resource.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>

#include "core/errors.hpp"

namespace arksph {

namespace {
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

}  // namespace arksph
