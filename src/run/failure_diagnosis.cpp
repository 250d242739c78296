#include "run/failure_diagnosis.hpp"

#include <cmath>
#include <cstdio>
#include <exception>
#include <vector>

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
    std::size_t fastest = 0, hardest = 0;
    double speed2 = -1, accel2 = -1;
    for (std::size_t a = 0; a < L.n; ++a) {
      double s2 = 0, a2 = 0;
      for (int k = 0; k < L.dim; ++k) {
        const double u = y[L.vel(k) + a], acc = ydot[L.vel(k) + a] + implicit[L.vel(k) + a];
        s2 += u * u;
        a2 += acc * acc;
      }
      if (!(s2 <= speed2)) speed2 = s2, fastest = a;  // a NaN wins: it is the culprit
      if (!(a2 <= accel2)) accel2 = a2, hardest = a;
    }
    char text[96];
    std::snprintf(text, sizeof text, "; at t = %.10g the largest acceleration is %.4g (", t, std::sqrt(accel2));
    std::string s = text + where(particles, L, y, hardest);
    std::snprintf(text, sizeof text, "), the largest speed %.4g (", std::sqrt(speed2));
    return s + text + where(particles, L, y, fastest) + ")";
  } catch (const std::exception&) {
    return "";
  }
}

}  // namespace arksph
