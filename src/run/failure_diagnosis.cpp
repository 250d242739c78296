#include "run/failure_diagnosis.hpp"

#include <cmath>
#include <cstdio>
#include <exception>
#include <vector>

#include "core/scheme.hpp"

namespace arksph {

namespace {

std::string where(const ParticleSet& particles, const StateLayout& L, const double* y, std::size_t a) {
  char text[160];
  const long long id = a < particles.id.size() ? static_cast<long long>(particles.id[a]) : static_cast<long long>(a);
  if (L.dim == 2)
    std::snprintf(text, sizeof text, "particle id %lld at (%.6g, %.6g)", id, y[L.pos(0) + a], y[L.pos(1) + a]);
  else
    std::snprintf(text, sizeof text, "particle id %lld at x = %.6g", id, y[L.pos(0) + a]);
  return text;
}

}  // namespace

std::string failure_diagnosis(RhsEvaluator& rhs, const ParticleSet& particles, double t, const double* y) {
  try {
    const StateLayout& L = rhs.layout();
    if (L.n == 0) return "";
    std::vector<double> ydot(L.size(), 0.0), implicit(L.size(), 0.0);
    rhs.eval(t, y, ydot.data());
    if (rhs.options().imex_split) rhs.implicit_part(implicit.data());
    // Magnitudes by hypot: a component of 1e300 must not square to infinity.
    const auto magnitude = [&](const double* v, const double* w, std::size_t a) {
      const double x = v[L.vel(0) + a] + (w ? w[L.vel(0) + a] : 0.0);
      if (L.dim == 1) return std::fabs(x);
      return std::hypot(x, v[L.vel(1) + a] + (w ? w[L.vel(1) + a] : 0.0));
    };
    std::size_t fastest = 0, hardest = 0;
    double speed = -1, accel = -1;
    for (std::size_t a = 0; a < L.n; ++a) {
      const double s = magnitude(y, nullptr, a), acc = magnitude(ydot.data(), implicit.data(), a);
      if (!(s <= speed)) speed = s, fastest = a;  // a NaN wins: it is the culprit
      if (!(acc <= accel)) accel = acc, hardest = a;
    }
    char text[96];
    std::snprintf(text, sizeof text, "; at t = %.10g the largest acceleration is %.4g (", t, accel);
    std::string s = text + where(particles, L, y, hardest);
    std::snprintf(text, sizeof text, "), the largest speed %.4g (", speed);
    return s + text + where(particles, L, y, fastest) + ")";
  } catch (const std::exception&) {
    return "";
  }
}

std::string known_limit(const Scene& scene) {
  if (!scheme_traits(scene.scheme).projection || scene.fluid_region.empty()) return "";
  return "; note: scheme " + scene.scheme +
         " at a free surface is known to fail in violent flows (impacts on walls, spray: the dam break after "
         "its surge strikes the far wall; docs/methods/free-surface.md), which method.scheme = \"wcsph\" runs";
}

}  // namespace arksph
