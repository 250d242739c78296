#include "projection/ConstrainedPressure.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/errors.hpp"
#include "core/particle_order.hpp"
#include "projection/divergence_operator.hpp"

namespace arksph {

double flow_rate(const Scene& scene, const RhsEvaluator& rhs) {
  // U: the largest initial particle speed or wall speed; a fluid starting at rest with still walls
  // relaxes over the run (U = h / time.end).
  const ParticleSet& p = rhs.particles();
  double u2 = 0;
  for (std::size_t a = 0; a < p.n; ++a) {
    double s2 = 0;
    for (int k = 0; k < p.dim; ++k) s2 += p.init_vel[k][a] * p.init_vel[k][a];
    u2 = std::max(u2, s2);
  }
  double speed = std::sqrt(u2);
  for (int s = 0; s < 2 * scene.dimension; ++s)
    speed = std::max(speed, std::hypot(scene.sides[s].velocity[0], scene.sides[s].velocity[1]));
  const double h = rhs.kernel().h();
  if (!(speed > 0)) speed = h / scene.end;
  return speed / h;
}

double relaxation_rate(const Scene& scene, const RhsEvaluator& rhs) {
  const double beta = scene.projection == "orthogonal" ? scene.orthogonal_relaxation : scene.constraint_relaxation;
  return beta * flow_rate(scene, rhs);
}

ConstrainedPressure::ConstrainedPressure(const Scene& scene, RhsEvaluator& rhs)
    : rhs_(rhs),
      split_(scene),
      solver_key_(scene.ppe_solver),
      tolerance_(scene.ppe_tolerance),
      relaxation_(relaxation_rate(scene, rhs)),
      zero_min_level_(scene.ppe_pressure_level == "zero_min"),
      solver_(make_poisson_solver(scene.ppe_solver, scene.ppe_tolerance)) {
  if (scene.density_correction == "pozorski_wawrenczuk")
    density_ = std::make_unique<DensityRelaxation>(scene, scene.correction_relaxation * flow_rate(scene, rhs));
  if (scene.projection == "orthogonal") {
    if (split_.active())
      throw InputError(scene.source + ": method.projection = \"orthogonal\" does not take fluid.body_force with walls yet "
                       "(the wall flux of the body force is not on its pressure space): use \"constrained\"");
    coarse_ = std::make_unique<CoarsePressureSpace>(scene, scene.orthogonal_spacing);
  }
}

void ConstrainedPressure::coarse_pressure(const double* u, const double* v) {
  const FluidFields& f = rhs_.fields();
  const std::size_t n = f.n_real;
  coarse_->assemble(f, operator_);  // operator_ assembled by the caller at these fields
  Eigen::VectorXd c = coarse_->restrict_weighted(f, div_.data());
  if (u) {
    udiv_.resize(n);
    operator_.divergence(u, v, udiv_.data());
    c += coarse_->motion_rate(f, u, v, udiv_.data());
  }
  coarse_->pressure(c, p_);
  gx_.resize(n);
  gy_.resize(n);
  operator_.gradient(p_.data(), gx_.data(), gy_.data());
  // The level of p does not enter its gradient's role here (G is the adjoint of D, whose image of
  // a constant is the disorder's small flux): the reported pressure takes the scene's level.
  const double level = zero_min_level_ ? *std::min_element(p_.begin(), p_.end())
                                       : std::accumulate(p_.begin(), p_.end(), 0.0) / static_cast<double>(n);
  for (double& x : p_) x -= level;
}

void ConstrainedPressure::project_orthogonal(double* u, double* v) {
  const std::size_t n = rhs_.fields().n_real;
  div_.resize(n);
  operator_.assemble(rhs_.fields());
  operator_.divergence(u, v, div_.data());
  const std::vector<double> keep = p_;
  coarse_pressure(nullptr, nullptr);
  for (std::size_t a = 0; a < n; ++a) {
    u[a] -= gx_[a];
    v[a] -= gy_[a];
  }
  p_ = keep;
}

void ConstrainedPressure::forget_warm_start() {
  p_.clear();
  solution_.clear();
  solver_ = make_poisson_solver(solver_key_, tolerance_);
}

void ConstrainedPressure::permute_particles(const std::vector<std::uint32_t>& from) {
  permute(p_, from);
  permute(solution_, from);
  solver_ = make_poisson_solver(solver_key_, tolerance_);  // its stored structure is in the old order
}

ConstraintReport ConstrainedPressure::solve_pressure(const std::vector<double>& w_div) {
  const FluidFields& f = rhs_.fields();
  const std::size_t n = f.n_real;
  assemble_ppe(f, w_div, 1.0, system_);
  if (solution_.size() != n) solution_.assign(n, 0.0);
  const SolveReport rep = solver_->solve(system_.A, system_.b, solution_);
  const double level = zero_min_level_ ? *std::min_element(solution_.begin(), solution_.end())
                                       : std::accumulate(solution_.begin(), solution_.end(), 0.0) / static_cast<double>(n);
  p_.resize(n);
  for (std::size_t a = 0; a < n; ++a) p_[a] = solution_[a] - level;
  return {rep.iterations, rep.relative_residual};
}

void ConstrainedPressure::pressure_gradient(const std::vector<double>& p, bool with_steps) {
  const FluidFields& f = rhs_.fields();
  const std::size_t n = f.n_real;
  gx_.resize(n);
  gy_.resize(n);
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n; ++a) {
    const double pa = p[a] / (f.rho[a] * f.rho[a]);
    double sx = 0, sy = 0;
    f.pairs.for_pairs(a, [&](std::uint32_t b, double rx, double ry, double, double, double F) {
      const double pb = with_steps ? f.point_pressure(p, b) : p[f.src[b]];
      const double c = f.m[b] * (pb / (f.rho[b] * f.rho[b]) + pa) * F;
      sx += c * rx;
      sy += c * ry;
    });
    gx_[a] = sx;
    gy_[a] = sy;
  }
}

ConstraintReport ConstrainedPressure::constrain(const double* y, double* ydot, const double* au, const double* av) {
  const FluidFields& f = rhs_.fields();
  const StateLayout& L = rhs_.layout();
  const std::size_t n = L.n;
  const double* u = y + L.vel(0);
  const double* v = L.dim == 2 ? y + L.vel(1) : nullptr;
  // L p = D (a* + alpha u) - Q
  wx_.resize(n);
  wy_.resize(n);
  for (std::size_t a = 0; a < n; ++a) {
    wx_[a] = ydot[L.vel(0) + a] + (au ? au[a] : 0.0) + relaxation_ * u[a];
    if (v) wy_[a] = ydot[L.vel(1) + a] + (av ? av[a] : 0.0) + relaxation_ * v[a];
  }
  if (split_.active()) {  // D(a* - g) + div g, the flux of g as Neumann data
    split_.at(n, f.x.data(), v ? f.y.data() : nullptr, f.t, bx_, by_);
    for (std::size_t a = 0; a < n; ++a) {
      wx_[a] -= bx_[a];
      if (v) wy_[a] -= by_[a];
    }
  }
  div_.resize(n);
  if (coarse_) {
    // D(w - (u . grad) u): the motion term as the divergence of the convective acceleration, with
    // the same D as the constraint (coarse_pressure_space.hpp says why).
    convective_acceleration(f, u, v, cx_, cy_);
    for (std::size_t a = 0; a < n; ++a) {
      wx_[a] -= cx_[a];
      wy_[a] -= cy_[a];
    }
    difference_divergence(f, wx_.data(), wy_.data(), div_.data());
  } else {
    divergence_minus_motion(f, wx_.data(), wy_.data(), u, v, div_.data());
  }
  if (split_.active()) {
    const std::vector<double> dg = split_.divergence(f), flux = neumann_source(f);
    for (std::size_t a = 0; a < n; ++a) div_[a] += dg[a] + flux[a];
  }
  ConstraintReport rep;
  if (coarse_) {
    operator_.assemble(f);
    coarse_pressure(u, v);
  } else {
    rep = solve_pressure(div_);
    pressure_gradient(p_, true);
  }
  for (std::size_t a = 0; a < n; ++a) {
    ydot[L.vel(0) + a] -= gx_[a];
    if (v) ydot[L.vel(1) + a] -= gy_[a];
  }
  if (density_) density_->add_velocity(f, ydot + L.pos(0), v ? ydot + L.pos(1) : nullptr);
  return rep;
}

ConstraintReport ConstrainedPressure::project_velocity(double t, double* y) {
  rhs_.eval(t, y, nullptr);
  const StateLayout& L = rhs_.layout();
  const std::size_t n = L.n;
  double* u = y + L.vel(0);
  double* v = L.dim == 2 ? y + L.vel(1) : nullptr;
  if (coarse_) {
    project_orthogonal(u, v);
    return {};
  }
  div_.resize(n);
  difference_divergence(rhs_.fields(), u, v, div_.data());
  const std::vector<double> keep_p = p_, keep_solution = solution_;
  solution_.assign(n, 0.0);  // phi is a potential, not the pressure: the pressure's warm start kept apart
  const ConstraintReport rep = solve_pressure(div_);
  pressure_gradient(p_, false);
  for (std::size_t a = 0; a < n; ++a) {
    u[a] -= gx_[a];
    if (v) v[a] -= gy_[a];
  }
  p_ = keep_p;
  solution_ = keep_solution;
  return rep;
}

}  // namespace arksph
