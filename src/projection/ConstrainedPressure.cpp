#include "projection/ConstrainedPressure.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

#include "core/errors.hpp"
#include "core/particle_order.hpp"
#include "projection/correction/DensityCorrection_PozorskiWawrenczuk.hpp"
#include "projection/divergence_operator.hpp"
#include "projection/free_surface.hpp"
#include "projection/ppe_assembly.hpp"
#include "projection/projection_options.hpp"
#include "projection/velocity_correction.hpp"
#include "rhs/body_force_field.hpp"

namespace arksph {

namespace {
// The fixed point of the surface's terms: the change of p relative to its largest value. A plain
// iteration shrinks the change by 0.12-0.17 on the standing wave (dx = 0.05), but by only 0.8-0.9
// on the dam break's surge, where 50 iterations left 1e-7 to 1e-6 of p; Anderson acceleration
// over the last kAndersonDepth iterates removes those slow modes.
constexpr double kFixedPointTolerance = 1e-12;
constexpr int kMaxFixedPointIterations = 50;
constexpr int kAndersonDepth = 5;
}  // namespace

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

double surface_gravity_rate(const Scene& scene) {
  if (scene.fluid_region.empty()) return 0.0;
  const BodyForceField force(scene.body_force, scene.dimension);
  if (force.zero()) return 0.0;
  // |g| at t = 0 on a 17 x 17 lattice of the domain (exact for a uniform g).
  constexpr int kSamples = 17;
  double g_max = 0;
  for (int i = 0; i < kSamples; ++i)
    for (int j = 0; j < kSamples; ++j) {
      const double x = scene.min[0] + (scene.max[0] - scene.min[0]) * i / (kSamples - 1);
      const double y = scene.min[1] + (scene.max[1] - scene.min[1]) * j / (kSamples - 1);
      double g[2];
      force.at(x, y, 0.0, g);
      g_max = std::max(g_max, std::hypot(g[0], g[1]));
    }
  const double h = scene.h_over_dx * scene.spacing;
  return g_max > 0 && std::isfinite(g_max) ? 4.0 * std::sqrt(g_max / h) : 0.0;
}

double relaxation_rate(const Scene& scene, double flow_rate) {
  const double beta = scene.projection == ProjectionMethod::orthogonal ? scene.orthogonal_relaxation
                                                                                 : scene.constraint_relaxation;
  return std::max(beta * flow_rate, beta > 0 ? surface_gravity_rate(scene) : 0.0);
}

ConstrainedPressure::ConstrainedPressure(const Scene& scene, ParticleDomain& domain, double flow_rate)
    : domain_(domain),
      split_(scene),
      relaxation_(relaxation_rate(scene, flow_rate)),
      zero_min_level_(scene.ppe_pressure_level.value() == PressureLevel::zero_min),
      poisson_(domain.poisson(scene, false)),
      free_surface_(!scene.fluid_region.empty()),
      surface_threshold_(free_surface_threshold(scene.dimension)),
      surface_depth_(0.5 * scene.spacing),
      anderson_(kAndersonDepth, [&domain](std::vector<double>& v) { domain.sum_in_place(v); }) {
  if (density_corrections().at(scene.density_correction).traits.corrects_density)
    density_ = std::make_unique<DensityRelaxation>(scene, scene.correction_relaxation * flow_rate);
  if (scene.projection == ProjectionMethod::orthogonal) {
    if (split_.active())
      throw InputError(scene.source + ": method.projection = \"orthogonal\" does not take fluid.body_force with walls yet "
                       "(the wall flux of the body force is not on its pressure space): use \"constrained\"");
    coarse_ = std::make_unique<CoarsePressureSpace>(scene, scene.orthogonal_spacing);
  }
}

void ConstrainedPressure::coarse_pressure(const double* u, const double* v) {
  const FluidFields& f = domain_.fields();
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
  const std::size_t n = domain_.fields().n_real;
  div_.resize(n);
  operator_.assemble(domain_.fields());
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
  poisson_->reset();
}

void ConstrainedPressure::particles_moved() {
  solution_.clear();
  poisson_->reset();
}

void ConstrainedPressure::permute_particles(const std::vector<std::uint32_t>& from) {
  permute(p_, from);
  permute(solution_, from);
  poisson_->reset();  // its stored structure is in the old order
}

SolveReport ConstrainedPressure::solve_pressure(const std::vector<double>& source, std::vector<double>& solution) {
  const SolveReport rep = poisson_->solve(domain_.fields(), source, 1.0, solution);
  // A free surface fixes the level: p = 0 there.
  const double level = free_surface_ ? 0.0 : domain_.level(solution, zero_min_level_);
  const std::size_t n = solution.size();
  p_.resize(n);
  for (std::size_t a = 0; a < n; ++a) p_[a] = solution[a] - level;
  return rep;
}

// The surface's rows and the Laplacian's defect (projection/free_surface.hpp) depend on p itself:
// p_k+1 solves L p = source - c . grad p_k with the surface values depth dp_k/dn. C&R's projection
// takes p_k from the last step; here the iteration runs to its fixed point within the evaluation, so
// that f is a function of (t, y) alone and the tables keep their order (lagged by one evaluation,
// every table measured order 1 on the standing wave). Its start is the last evaluation's p, or
// without one (the first evaluation, a checkpoint, a re-sort) the solve without the two terms.
SolveReport ConstrainedPressure::solve_at_surface(const std::vector<double>& source, DirichletRows& given) {
  const FluidFields& f = domain_.fields();
  const std::size_t n = source.size();
  SolveReport rep;
  if (solution_.size() != n) {
    poisson_->set_given(surface_rows(f, n, surface_threshold_, surface_depth_, {}));
    rep = solve_pressure(source, solution_);
  }
  std::vector<double> rhs(n);
  anderson_.reset();
  ++surface_stats_.evaluations;
  for (int k = 0;; ++k) {
    last_gradient_ = renormalised_gradients(f, domain_.with_halo(solution_), n);
    const std::vector<double> defect = linear_laplacian_defect(f, last_gradient_, n);
    for (std::size_t a = 0; a < n; ++a) rhs[a] = source[a] + defect[a];
    given = surface_rows(f, n, surface_threshold_, surface_depth_, last_gradient_);
    poisson_->set_given(given);
    std::vector<double> x = solution_;
    rep = solve_pressure(rhs, solution_);
    double change = 0, size = 0;
    for (std::size_t a = 0; a < n; ++a) {
      change = std::max(change, std::abs(solution_[a] - x[a]));
      size = std::max(size, std::abs(solution_[a]));
    }
    ++surface_stats_.solves;
    // Every rank iterates as often (each solve is collective over the ranks).
    if (!(domain_.largest(change) > kFixedPointTolerance * domain_.largest(size))) break;
    if (k + 1 >= kMaxFixedPointIterations) {
      ++surface_stats_.unconverged;
      break;
    }
    anderson_.next(x, solution_);
    solution_ = std::move(x);
  }
  // No suction below the surface, p >= 0, as in C&R's projection (projection.cpp says why).
  for (double& p : p_) p = std::max(p, 0.0);
  return rep;
}

SolveReport ConstrainedPressure::constrain(const double* y, double* ydot, const double* au, const double* av) {
  const FluidFields& f = domain_.fields();
  const StateLayout L = domain_.layout();
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
  div_.resize(f.n_real);
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
    // w at every real point (the halo copies' from their owners: D w reads w at the neighbours),
    // the velocities of the motion term those the fields were evaluated with.
    std::vector<double> wx_all, wy_all;
    if (v)
      std::tie(wx_all, wy_all) = domain_.with_halo(wx_, wy_);  // one exchange for both components
    else
      wx_all = domain_.with_halo(wx_);
    divergence_minus_motion(f, wx_all.data(), v ? wy_all.data() : nullptr, domain_.point_velocity(y, 0),
                            v ? domain_.point_velocity(y, 1) : nullptr, div_.data());
  }
  div_.resize(n);  // the own particles' sources
  if (split_.active()) {
    const std::vector<double> dg = split_.divergence(f), flux = neumann_source(f);
    for (std::size_t a = 0; a < n; ++a) div_[a] += dg[a] + flux[a];
  }
  SolveReport rep;
  if (coarse_) {
    operator_.assemble(f);
    coarse_pressure(u, v);
    for (std::size_t a = 0; a < n; ++a) {
      ydot[L.vel(0) + a] -= gx_[a];
      if (v) ydot[L.vel(1) + a] -= gy_[a];
    }
  } else if (free_surface_) {
    DirichletRows given;
    rep = solve_at_surface(div_, given);
    subtract_renormalised_gradient(f, domain_.with_halo(p_), 1.0, n, ydot + L.vel(0), v ? ydot + L.vel(1) : nullptr,
                                   given.fixed);
  } else {
    rep = solve_pressure(div_, solution_);
    // du/dt -= G p (C&R eq. 11), wall points at P_src + rho g . d, the halo copies' p their owners'.
    subtract_pressure_gradient(f, domain_.with_halo(p_), 1.0, n, ydot + L.vel(0), v ? ydot + L.vel(1) : nullptr);
  }
  if (density_)
    density_->add_velocity(f, domain_.correction_span(), ydot + L.pos(0), v ? ydot + L.pos(1) : nullptr);
  return rep;
}

SolveReport ConstrainedPressure::project_velocity(double t, double* y) {
  domain_.refresh(t, y);
  const FluidFields& f = domain_.fields();
  const StateLayout L = domain_.layout();
  const std::size_t n = L.n;
  double* u = y + L.vel(0);
  double* v = L.dim == 2 ? y + L.vel(1) : nullptr;
  if (coarse_) {
    project_orthogonal(u, v);
    return {};
  }
  div_.resize(f.n_real);
  difference_divergence(f, domain_.point_velocity(y, 0), v ? domain_.point_velocity(y, 1) : nullptr, div_.data());
  div_.resize(n);
  // phi is a potential, not the pressure: its own cold start, the pressure and its warm start kept apart.
  const std::vector<double> keep_p = p_;
  std::vector<double> phi;
  DirichletRows given;  // at a free surface phi = 0 there
  if (free_surface_) {
    given = surface_rows(f, n, surface_threshold_, surface_depth_, {});
    poisson_->set_given(given);
  }
  const SolveReport rep = solve_pressure(div_, phi);
  if (free_surface_)
    subtract_renormalised_gradient(f, domain_.with_halo(p_), 1.0, n, u, v, given.fixed, false);
  else
    subtract_pressure_gradient(f, domain_.with_halo(p_), 1.0, n, u, v, false);
  p_ = keep_p;
  return rep;
}

}  // namespace arksph
