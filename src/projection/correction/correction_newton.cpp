#include "projection/correction/correction_newton.hpp"

#include <algorithm>
#include <memory>
#include <cmath>
#include <numeric>

#include "kernels/kernel.hpp"
#include "projection/correction/correction_solver.hpp"

namespace arksph {

namespace {
using Vec = std::vector<double>;

double dot(const Vec& a, const Vec& b) {
  double s = 0;
#pragma omp parallel for schedule(static) reduction(+ : s)
  for (std::size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
  return s;
}

}  // namespace

CorrectionSpan local_span(const FluidFields& f) {
  CorrectionSpan span;
  span.own = f.n_real;
  span.sum = [](double v) { return v; };
  span.extend = [](Vec&) {};
  span.gather = [](const Vec& v) { return v; };
  span.any = [](bool v) { return v; };
  return span;
}

double density_fluctuation(const FluidFields& f, Vec& s) { return density_fluctuation(f, local_span(f), s); }

double density_fluctuation(const FluidFields& f, const CorrectionSpan& span, Vec& s) {
  const std::size_t n = span.own;
  const double w0 = f.kernel->W(0.0);
  s.resize(n);
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n; ++a) {
    double d = w0;
    f.pairs.for_pairs(a, [&](std::uint32_t, double, double, double, double w, double) { d += w; });
    s[a] = 1.0 - f.m[a] * d / f.rho0[a];
  }
  const double total = span.sum(static_cast<double>(n));
  const double mean = span.sum(std::accumulate(s.begin(), s.end(), 0.0)) / total;
  for (double& v : s) v -= mean;
  return std::sqrt(span.sum(dot(s, s)) / total);
}

namespace {
// BiCGSTAB (van der Vorst 1992) on K x = b from x = 0, matrix-free, at most max_it iterations.
// Right-preconditioned by the diagonal: solves K D^-1 z = b, x = D^-1 z. Returns the iterate of the
// smallest residual, not the last: BiCGSTAB's residual is not monotone, and where K D^-1 is
// indefinite (particles pressed into a corner) it can fall for a few iterations and then grow past
// |b| (measured on the spin-down: 0.41 |b| after 2 iterations, 1.3 |b| after 20), so that the last
// iterate would be worse than no shift at all.
// `dot`: the inner product of two vectors of the span's own particles, over every rank.
template <class Apply, class Dot>
int bicgstab(Apply&& K_plain, const Vec& inv_diag, const Vec& b, Vec& x, int max_it, double rel_tol, Dot&& dot) {
  const std::size_t n = b.size();
  Vec scaled(n);
  auto K = [&](const Vec& q, Vec& out) {
    for (std::size_t i = 0; i < n; ++i) scaled[i] = inv_diag[i] * q[i];
    K_plain(scaled, out);
  };
  x.assign(n, 0.0);
  Vec r = b, r0 = b, p(n, 0.0), v(n, 0.0), s(n), t(n), x_best = x;
  double rho = 1, alpha = 1, omega = 1;
  const double stop = rel_tol * std::sqrt(dot(b, b));
  double res = std::sqrt(dot(r, r)), res_best = res;
  int it = 0;
  for (; it < max_it && res > stop; ++it) {
    const double rho_new = dot(r0, r);
    if (rho_new == 0 || omega == 0) break;
    const double beta = (rho_new / rho) * (alpha / omega);
    rho = rho_new;
    for (std::size_t i = 0; i < n; ++i) p[i] = r[i] + beta * (p[i] - omega * v[i]);
    K(p, v);
    const double r0v = dot(r0, v);
    if (r0v == 0) break;
    alpha = rho / r0v;
    for (std::size_t i = 0; i < n; ++i) s[i] = r[i] - alpha * v[i];
    K(s, t);
    const double tt = dot(t, t);
    omega = tt > 0 ? dot(t, s) / tt : 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      x[i] += alpha * p[i] + omega * s[i];
      r[i] = s[i] - omega * t[i];
    }
    res = std::sqrt(dot(r, r));
    if (res < res_best) {
      res_best = res;
      x_best = x;
    }
  }
  for (std::size_t i = 0; i < n; ++i) x[i] = inv_diag[i] * x_best[i];
  return it;
}
}  // namespace

void correction_shift(const FluidFields& f, const std::vector<double>& p, std::vector<double>& dx,
                      std::vector<double>& dy, std::size_t count) {
  const std::size_t n = std::min(count, f.n_real);
  dx.resize(n), dy.resize(n);
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n; ++a) {
    double gx = 0, gy = 0;
    f.pairs.for_pairs(a, [&](std::uint32_t b, double rx, double ry, double, double, double F) {
      const double c = f.m[b] / f.rho[b] * F * (p[f.src[b]] - p[a]);  // V_b (p_src(b) - p_a) grad_a W_ab
      gx += c * rx;
      gy += c * ry;
    });
    dx[a] = -gx / f.rho0[a];
    dy[a] = f.dim == 2 ? -gy / f.rho0[a] : 0.0;
  }
}

void density_change(const FluidFields& f, const std::vector<double>& dx, const std::vector<double>& dy,
                    std::vector<double>& ds, std::size_t count) {
  const std::size_t n = std::min(count, f.n_real);
  ds.resize(n);
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n; ++a) {
    double dd = 0;  // d(sum_b W_ab) = sum_b F_ab r_ab . (dr_a - M_b dr_src(b))
    f.pairs.for_pairs(a, [&](std::uint32_t b, double rx, double ry, double, double, double F) {
      const std::uint32_t c = f.src[b];
      const double mx = f.flip_x.empty() ? 1.0 : f.flip_x[b], my = f.flip_y.empty() ? 1.0 : f.flip_y[b];
      dd += F * (rx * (dx[a] - mx * dx[c]) + (f.dim == 2 ? ry * (dy[a] - my * dy[c]) : 0.0));
    });
    ds[a] = -f.m[a] / f.rho0[a] * dd;
  }
}

namespace {
// diag(K), the Jacobi preconditioner: dK_aa = -(m_a/rho0_a) sum_b F_ab r_ab . (e_a - M_b e_src(b)),
// with e_c = d(dr_c)/dp_a. For c = a, e_a = (1/rho0_a) sum_{b': src(b') != a} V_b' F_ab' r_ab'; for
// c != a, e_c = -(1/rho0_c) sum over c's neighbours b' that are a or an image of a of V_b' F_cb' r_cb'.
// Wall particles, whose own mirror image enters, have a diagonal several times the bulk's.
// Rows of the first `count` real particles.
Vec diagonal(const FluidFields& f, std::size_t count) {
  const std::size_t n = std::min(count, f.n_real);
  Vec diag(n);
#pragma omp parallel for schedule(dynamic, 64)
  for (std::size_t a = 0; a < n; ++a) {
    double eax = 0, eay = 0;
    f.pairs.for_pairs(a, [&](std::uint32_t b, double rx, double ry, double, double, double F) {
      if (f.src[b] == a) return;
      const double c = f.m[b] / f.rho[b] * F;
      eax += c * rx, eay += c * ry;
    });
    eax /= f.rho0[a], eay /= f.rho0[a];
    double dd = 0;
    f.pairs.for_pairs(a, [&](std::uint32_t b, double rx, double ry, double, double, double F) {
      const std::uint32_t c = f.src[b];
      const double mx = f.flip_x.empty() ? 1.0 : f.flip_x[b], my = f.flip_y.empty() ? 1.0 : f.flip_y[b];
      double ecx = eax, ecy = eay;
      if (c != a) {
        ecx = 0, ecy = 0;
        f.pairs.for_pairs(c, [&](std::uint32_t b2, double rx2, double ry2, double, double, double F2) {
          if (f.src[b2] != a) return;
          const double v = f.m[b2] / f.rho[b2] * F2;
          ecx -= v * rx2, ecy -= v * ry2;
        });
        ecx /= f.rho0[c], ecy /= f.rho0[c];
      }
      dd += F * (rx * (eax - mx * ecx) + (f.dim == 2 ? ry * (eay - my * ecy) : 0.0));
    });
    diag[a] = -f.m[a] / f.rho0[a] * dd;
  }
  return diag;
}
}  // namespace

namespace {
// 1/d for the Jacobi preconditioner, with every entry held to the bulk's sign and to at least a tenth
// of the median magnitude: at a corner, where the images of all sides meet, an entry can be near
// zero or of the other sign, and its inverse would blow that particle's shift up.
Vec safe_inverse(Vec d, const CorrectionSpan& span) {
  Vec mag(d.size());
  std::size_t positive = 0;
  for (std::size_t i = 0; i < d.size(); ++i) {
    mag[i] = std::abs(d[i]);
    positive += d[i] > 0 ? 1 : 0;
  }
  const double total = span.sum(static_cast<double>(d.size()));
  if (total == 0) return d;
  mag = span.gather(mag);
  std::nth_element(mag.begin(), mag.begin() + static_cast<long>(mag.size() / 2), mag.end());
  const double floor = 0.1 * mag[mag.size() / 2];
  const double sign = 2 * span.sum(static_cast<double>(positive)) >= total ? 1.0 : -1.0;
  for (double& v : d) v = floor > 0 ? sign / std::max(sign * v, floor) : 1.0;
  return d;
}
}  // namespace

int newton_shift(const FluidFields& f, const std::vector<double>& s, std::vector<double>& p, std::vector<double>& dx,
                 std::vector<double>& dy) {
  return newton_shift(f, local_span(f), s, p, dx, dy);
}

int newton_shift(const FluidFields& f, const CorrectionSpan& span, const std::vector<double>& s, std::vector<double>& p,
                 std::vector<double>& dx, std::vector<double>& dy) {
  // Krylov iterations per Newton step: enough for the smooth part of the error, too few to chase
  // the near-null odd-even modes (measured on cases/perturbed_lattice and the cavity).
  constexpr int kKrylovIterations = 20;
  const std::size_t n = span.own;
  const double total = span.sum(static_cast<double>(n));
  Vec q_all;
  // dr = correction_shift(q) of the own particles, then at every real point.
  auto shift = [&](const Vec& q) {
    q_all.assign(q.begin(), q.end());
    span.extend(q_all);
    correction_shift(f, q_all, dx, dy, n);
  };
  auto K = [&](const Vec& q, Vec& out) {  // out = K q - mean: the change of s - mean s
    shift(q);
    span.extend(dx), span.extend(dy);
    density_change(f, dx, dy, out, n);
    const double mean = span.sum(std::accumulate(out.begin(), out.end(), 0.0)) / total;
    for (double& v : out) v -= mean;
  };
  Vec minus_s(n);
  for (std::size_t a = 0; a < n; ++a) minus_s[a] = -s[a];
  const Vec inv_diag = safe_inverse(diagonal(f, n), span);
  const auto global_dot = [&](const Vec& a, const Vec& b) { return span.sum(dot(a, b)); };
  const int iterations = bicgstab(K, inv_diag, minus_s, p, kKrylovIterations, 1e-3, global_dot);
  shift(p);
  return iterations;
}

NewtonCorrectionResult correct_density_newton(RhsEvaluator& rhs, double t, double* y, int max_iterations,
                                              double threshold, double spacing) {
  return correct_density_newton([&](const double* state) { rhs.eval(t, state, nullptr); },
                                [&]() -> const FluidFields& { return rhs.fields(); },
                                [&] { return local_span(rhs.fields()); }, rhs.layout(), y, max_iterations, threshold,
                                spacing);
}

NewtonCorrectionResult correct_density_newton(const std::function<void(const double*)>& refresh,
                                              const std::function<const FluidFields&()>& fields,
                                              const std::function<CorrectionSpan()>& span, const StateLayout& L,
                                              double* y, int max_iterations, double threshold, double spacing) {
  // Largest shift of a particle per step as a fraction of the spacing: the linearisation of eq. 59
  // holds for shifts small against the kernel radius.
  constexpr double kMaxShift = 0.1;
  // Halvings of a step that does not lower the error before the step is given up.
  constexpr int kStepHalvings = 2;
  const std::size_t n = L.n;
  NewtonCorrectionResult res;
  Vec s, p, sx, sy;
  refresh(y);
  CorrectionSpan sp = span();
  res.error = density_fluctuation(fields(), sp, s);
  for (int it = 0; it < max_iterations && res.error > threshold; ++it) {
    res.krylov_iterations += newton_shift(fields(), sp, s, p, sx, sy);
    bool finite = true;
    for (std::size_t a = 0; a < n; ++a) finite = finite && std::isfinite(sx[a]) && std::isfinite(sy[a]);
    if (sp.any(!finite)) break;  // the solve failed: leave the positions as they are
    // Each particle's shift is clipped on its own: scaling the whole field down for one outlier
    // (a particle in a corner) would stall the correction everywhere else.
    const double cap = kMaxShift * spacing;
    for (std::size_t a = 0; a < n; ++a) {
      const double len = std::hypot(sx[a], sy[a]);
      const double scale = len > cap ? cap / len : 1.0;
      sx[a] *= scale;
      sy[a] *= scale;
    }
    // Accept the step only if it lowers the error, halving it otherwise. The truncated solve can
    // return a shift dominated by the near-null odd-even modes (where the linearisation says
    // little); applied unchecked, such a step raises the error and the next solves chase it.
    const Vec x_before(y + L.pos(0), y + L.pos(0) + n);
    const Vec y_before = L.dim == 2 ? Vec(y + L.pos(1), y + L.pos(1) + n) : Vec();
    const double error_before = res.error;
    Vec s_trial;
    bool accepted = false;
    double step = 1.0;
    for (int trial = 0; trial <= kStepHalvings && !accepted; ++trial, step *= 0.5) {
      for (std::size_t a = 0; a < n; ++a) {
        y[L.pos(0) + a] = x_before[a] + step * sx[a];
        if (L.dim == 2) y[L.pos(1) + a] = y_before[a] + step * sy[a];
      }
      refresh(y);
      sp = span();
      const double e = density_fluctuation(fields(), sp, s_trial);
      if (e < error_before) {
        accepted = true;
        res.error = e;
        s.swap(s_trial);
      }
    }
    if (!accepted) {  // no step along this direction helps: positions back, fields with them
      std::copy(x_before.begin(), x_before.end(), y + L.pos(0));
      if (L.dim == 2) std::copy(y_before.begin(), y_before.end(), y + L.pos(1));
      refresh(y);
      ++res.rejected;
      break;
    }
    ++res.iterations;
  }
  return res;
}

}  // namespace arksph

namespace arksph {

namespace {
// method.correction_solver = "newton": correct_density_newton over the domain (its refresh, fields
// and span), up to method.correction_max_iterations Newton iterations.
class NewtonCorrection : public CorrectionSolver {
 public:
  NewtonCorrection(const Scene& scene, ParticleDomain& domain)
      : domain_(domain),
        threshold_(scene.correction_threshold),
        max_iterations_(scene.correction_max_iterations),
        spacing_(scene.spacing) {}
  CorrectionOutcome correct(double t, double* y, std::vector<double>&, double, std::vector<double>*) override {
    const NewtonCorrectionResult r = correct_density_newton(
        [&](const double* state) { domain_.refresh(t, state); },
        [&]() -> const FluidFields& { return domain_.fields(); }, [&] { return domain_.correction_span(); },
        domain_.layout(), y, max_iterations_, threshold_, spacing_);
    return {r.error, r.iterations};
  }

 private:
  ParticleDomain& domain_;
  double threshold_;
  int max_iterations_;
  double spacing_;
};
}  // namespace

std::unique_ptr<CorrectionSolver> make_correction_newton(const Scene& scene, ParticleDomain& domain) {
  return std::make_unique<NewtonCorrection>(scene, domain);
}

}  // namespace arksph
