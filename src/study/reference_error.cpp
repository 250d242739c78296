// Velocity errors against an analytic field or an interpolated reference run (see reference_error.hpp).
#include "study/reference_error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "kernels/kernel.hpp"
#include "neighbors/cell_list.hpp"

namespace arksph {

namespace {
// A NaN error (a velocity or a reference value that is not finite) makes every norm NaN.
struct Accumulator {
  double sum = 0, sum2 = 0, max = 0;
  std::size_t n = 0;
  bool nan = false;
  void add(double e) {
    sum += e, sum2 += e * e, max = std::max(max, e), ++n;
    nan = nan || std::isnan(e);
  }
  VelocityErrors result() const {
    if (n == 0) return {};
    if (nan) {
      const double q = std::numeric_limits<double>::quiet_NaN();
      return {q, q, q};
    }
    return {sum / static_cast<double>(n), std::sqrt(sum2 / static_cast<double>(n)), max};
  }
};
}  // namespace

ParticleVelocities velocities_of(const StateLayout& L, const double* state, const std::vector<double>& mass,
                                 const std::vector<double>& rho0) {
  ParticleVelocities p;
  p.x.assign(state + L.pos(0), state + L.pos(0) + L.n);
  p.u.assign(state + L.vel(0), state + L.vel(0) + L.n);
  if (L.dim > 1) {
    p.y.assign(state + L.pos(1), state + L.pos(1) + L.n);
    p.v.assign(state + L.vel(1), state + L.vel(1) + L.n);
  } else {
    p.y.assign(L.n, 0.0), p.v.assign(L.n, 0.0);
  }
  p.volume.resize(L.n);
  for (std::size_t a = 0; a < L.n; ++a) p.volume[a] = mass[a] / rho0[a];
  return p;
}

AnalyticVelocity::AnalyticVelocity(const std::string& u, const std::string& v) : u_(u), v_(v) {}

void AnalyticVelocity::eval(double x, double y, double t, double& u, double& v) const {
  u = u_.eval(x, y, t);
  v = v_.eval(x, y, t);
}

VelocityErrors errors_against_analytic(const ParticleVelocities& run, const AnalyticVelocity& exact, double t) {
  Accumulator acc;
  for (std::size_t a = 0; a < run.x.size(); ++a) {
    double ue, ve;
    exact.eval(run.x[a], run.y[a], t, ue, ve);
    acc.add(std::hypot(run.u[a] - ue, run.v[a] - ve));
  }
  return acc.result();
}

VelocityErrors errors_against_reference(const ParticleVelocities& run, const ParticleVelocities& ref,
                                        const std::string& kernel, double h) {
  const Kernel w = make_kernel(kernel, h, 2);
  CellList cells;
  cells.build(ref.x.data(), ref.y.data(), ref.x.size(), w.radius());
  Accumulator acc;
  for (std::size_t a = 0; a < run.x.size(); ++a) {
    double su = 0, sv = 0, sw = 0;
    cells.for_each_near(run.x[a], run.y[a], [&](std::size_t b, double dx, double dy) {
      const double wv = ref.volume[b] * w.W(std::hypot(dx, dy));
      su += wv * ref.u[b], sv += wv * ref.v[b], sw += wv;
    });
    const double ur = sw > 0 ? su / sw : 0.0, vr = sw > 0 ? sv / sw : 0.0;
    acc.add(std::hypot(run.u[a] - ur, run.v[a] - vr));
  }
  return acc.result();
}

}  // namespace arksph
