#include "projection/projection.hpp"

#include <algorithm>
#include <chrono>
#include <numeric>

#include "core/errors.hpp"
#include "core/param_builder.hpp"
#include "core/particle_order.hpp"
#include "core/particles.hpp"
#include "core/scheme.hpp"
#include "core/seconds_since.hpp"
#include "projection/free_surface.hpp"
#include "projection/ppe_assembly.hpp"
#include "projection/projection_options.hpp"
#include "projection/velocity_correction.hpp"

namespace arksph {

namespace {
// method.ppe_divergence = "auto". isph-gpps: the difference form; with C&R eq. 17 the cavity blows
// up (Re = 100 at t ~ 2.2, Re = 400 at t ~ 2.9, Re = 1000 by t ~ 2), with the difference form it
// runs (the cavity's walls also need boundary.free_slip_divergence, see its rule). isph: C&R eq. 17,
// C&R's scheme: the difference form is more accurate on the cavities but the Rayleigh-Taylor case
// with it blows up at t ~ 0.4. Below a free surface (fluid.region) the difference form, which reads
// the floor's free-slip images (boundary.free_slip_divergence): C&R eq. 17 leaves the wall out,
// and the surge of the dam break then lifts off the floor at its tip and sprays ahead.
std::string automatic_ppe_divergence(const Scene& s) {
  return scheme_traits(s.scheme).grid || !s.fluid_region.empty() ? "difference" : "cummins_rudman";
}

// method.ppe_pressure_level = "auto". The projection after each step: zero_min. With a zero-mean P
// the suction (P < 0) makes pairs attract (C&R eq. 11) and isph blows up on the periodic
// Taylor-Green vortex (Re = 100, 50 x 50, at t ~ 0.49) and on the cavity (Re = 100, 400 and 1000 at
// t ~ 0.38, 0.68 and 0.73); with zero_min they run (to t = 1 and 3), and the spin-down ends (t = 10)
// with a quarter of the density error (CV 0.045 against 0.17).
// isph-gpps corrects the velocity with the grid's gradient, which the level does not change. The
// constrained projection the same, for the same reason: with a zero-mean P the published-scheme
// cavity (Re = 100, no shifting) blew up at t = 0.18 (particle pairs at the lid corners), the
// spin-down at t = 7.3 and the cavity at Re = 1000 before t = 1; with zero_min the first two run to
// their ends (t = 30: Ghia u / v L_inf 0.034 / 0.037; t = 10), and the orders of
// cases/isph_order keep (walled box: velocity 1.03, 2.20, 3.07, 3.95; periodic Taylor-Green 1.00,
// 2.04, 2.98, 4.20; pressure likewise).
std::string automatic_ppe_pressure_level(const Scene&) { return "zero_min"; }

// method.body_force_pressure = "auto": modified wherever it applies (one density, a constant body
// force; rhs/pressure_gravity.hpp), split otherwise. With the split a closed tank at rest drifts
// (mean summation density +10 % by t = 5 at the viscous step limit, H = g = 1, 40 x 40) and the
// constrained projection blows up by t = 0.6; with the modified pressure both stay at rest.
std::string automatic_body_force_pressure(const Scene& s) {
  return modified_pressure_applies(s) ? "modified" : "split";
}
}  // namespace

const std::vector<Param>& projection_params() {
  static const std::vector<Param> params = {
      choice("method.projection", "cummins_rudman").choices(projection_methods().names())
          .doc("cummins_rudman: approximate projection after each step (C&R 1999); constrained: pressure solved inside f(t, y) at every stage, the table's temporal order; "
               "orthogonal: as constrained, with an idempotent (orthogonal) projection on a coarse pressure space (docs/methods/isph.md)")
          .to(&Scene::projection, projection_methods()),
      number("method.orthogonal_spacing", 3.0).in(at_least(1.5))
          .doc("orthogonal projection: spacing of the pressure's B-spline nodes over fluid.spacing (coarser: fewer "
               "constraints, better conditioned; at 1 the nodes resolve the particles' odd-even modes and K_c "
               "turns singular within a few steps of the cavity)")
          .to(&Scene::orthogonal_spacing),
      number("method.orthogonal_relaxation", 0.1).in(at_least(0))
          .doc("orthogonal projection: beta of its relaxation rate alpha = beta U/h (as method.constraint_relaxation; smaller, because the coarse divergence of a smooth flow on disordered particles is not zero, and relaxing it damps the flow)")
          .to(&Scene::orthogonal_relaxation),
      number("method.constraint_relaxation", 1.0).in(at_least(0))
          .doc("constrained projection: beta of the decay rate alpha = beta U/h of a divergence left by the time integration, d(Du)/dt = -alpha Du (U: the largest initial or wall speed); at a free surface under a body force g at least 4 sqrt(|g|/h), the inverse of the body-force step; 0: no relaxation")
          .to(&Scene::constraint_relaxation),
      choice("method.ppe_operator", "approximate").choices(projection_options().ppe_operator.names())
          .doc("Laplacian of the PPE: approximate (Cummins & Rudman 1999 eq. 19) or exact (eq. 18: odd-even decoupling; scheme isph with klu only)")
          .to(&Scene::ppe_operator, projection_options().ppe_operator),
      choice("method.ppe_divergence", "auto").choices(projection_options().ppe_divergence.names())
          .doc("source of the PPE: C&R eq. 17 without ghosts, or the difference form of Szewc et al. 2012 eq. 19 / rho with ghosts; "
               "auto: difference for isph-gpps and below a free surface (fluid.region), cummins_rudman otherwise")
          .automatic(automatic_ppe_divergence).to(&Scene::ppe_divergence, projection_options().ppe_divergence),
      choice("method.ppe_pressure_level", "auto").choices(projection_options().ppe_pressure_level.names())
          .doc("free level of P of the Neumann problem: zero mean, or zero minimum (P >= 0, so C&R eq. 11 never attracts); "
               "auto: zero_min")
          .automatic(automatic_ppe_pressure_level).to(&Scene::ppe_pressure_level, projection_options().ppe_pressure_level),
      number("method.ppe_pressure_offset", 0.0).in(at_least(0))
          .doc("constant added to P after the level (a background pressure)").to(&Scene::ppe_pressure_offset),
      choice("method.body_force_pressure", "auto").choices(body_force_pressures().names())
          .doc("a constant body force g along walled axes: modified: the pressure equation solves for P = p - rho0 g . r "
               "(one density; a tank at rest stays exactly at rest); split: g in the momentum equation, its wall flux as "
               "the pressure's Neumann data (C&R's p); auto: modified where it applies, split otherwise")
          .automatic(automatic_body_force_pressure).to(&Scene::body_force_pressure, body_force_pressures()),
  };
  return params;
}

const std::vector<Param>& projection_time_params() {
  static const std::vector<Param> params = {
      flag("method.centre_positions", true).doc("positions centred in time (Cummins & Rudman 1999 eq. 12)")
          .to(&Scene::centre_positions),
      choice("method.projection_points", "step").choices(projection_options().projection_points.names())
          .doc("project after each accepted step (C&R), or also after every ERK stage")
          .to(&Scene::projection_points, projection_options().projection_points),
  };
  return params;
}

Projection::Projection(const Scene& scene, std::unique_ptr<ParticleDomain> domain, double flow_rate)
    : domain_(std::move(domain)),
      split_(scene),
      centre_positions_(scene.centre_positions),
      exact_operator_(scene.ppe_operator == PpeOperator::exact),
      difference_divergence_(scene.ppe_divergence.value() == PpeDivergence::difference),
      zero_min_level_(scene.ppe_pressure_level.value() == PressureLevel::zero_min),
      free_surface_(!scene.fluid_region.empty()),
      surface_threshold_(free_surface_threshold(scene.dimension)),
      surface_depth_(0.5 * scene.spacing),
      pressure_offset_(scene.ppe_pressure_offset),
      gravity_(pressure_gravity(scene)) {
  if (scheme_traits(scene.scheme).grid)
    grid_ = std::make_unique<GridProjection>(scene);
  else
    poisson_ = domain_->poisson(scene, exact_operator_);
  // The constrained projection carries the correction inside f (ConstrainedPressure).
  if (density_corrections().at(scene.density_correction).traits.corrects_density && !scene.pressure_in_f())
    correction_ = std::make_unique<DensityCorrection>(scene, *domain_);
  // Stages projected one by one, or a pressure inside f (constrained), carry no increment.
  const bool after_step = scene.projection_points == ProjectionPoints::step;
  slip_origin_ = split_.active() && after_step && !scene.pressure_in_f();
  if (scene.pressure_in_f()) constrained_ = std::make_unique<ConstrainedPressure>(scene, *domain_, flow_rate);
}

void Projection::constrain(const double* y, double* ydot, const double* au, const double* av) {
  const auto t0 = std::chrono::steady_clock::now();
  const SolveReport rep = constrained_->constrain(y, ydot, au, av);
  stats_.record_solve(rep.iterations, rep.refactored_symbolic, rep.relative_residual);
  stats_.setup_seconds += rep.setup_seconds;
  if (gravity_.active) report(constrained_->pressure());
  const double s = seconds_since(t0);
  stats_.seconds += s;
  stats_.solve_seconds += s;
}

void Projection::project_initial(double t, double* y) {
  if (!constrained_) return;
  const SolveReport rep = constrained_->project_velocity(t, y);
  stats_.max_residual = std::max(stats_.max_residual, rep.relative_residual);
}

void Projection::forget_warm_start() {
  if (constrained_) constrained_->forget_warm_start();
  pressure_.clear();
  reported_.clear();
  solution_.clear();
  if (poisson_) poisson_->reset();
  if (correction_) correction_->forget_warm_start();
}

void Projection::particles_moved() {
  if (constrained_) constrained_->particles_moved();
  solution_.clear();
  y_prev_.clear();
  if (poisson_) poisson_->reset();
  if (correction_) correction_->forget_warm_start();
}

void Projection::permute_particles(const std::vector<std::uint32_t>& from) {
  const StateLayout L = domain_->layout();
  permute(pressure_, from);
  permute(reported_, from);
  permute(solution_, from);
  if (y_prev_.size() == L.size()) permute_state(L, y_prev_.data(), from);
  if (correction_) correction_->permute_particles(from);
  if (constrained_) constrained_->permute_particles(from);
  // A solver's stored structure (KLU's symbolic analysis, cg_amg's aggregates) is in the old order.
  if (poisson_) poisson_->reset();
}

void Projection::begin_step(double t, const double* y) {
  // The stages of a step projected at its end carry (t - t_n) g (body_force_split.hpp).
  domain_->set_slip_origin(slip_origin_, t);
  t_prev_ = t;
  y_prev_.assign(y, y + domain_->layout().size());
}

void Projection::project_stage(double t, double* y) {
  const double dt = t - t_prev_;
  if (dt <= 0) return;  // a stage at c_i = 0 needs no projection
  const auto t0 = std::chrono::steady_clock::now();
  project_velocities(dt, t, y);
  stats_.seconds += seconds_since(t0);
}

void Projection::project(double t, double* y) {
  const auto t0 = std::chrono::steady_clock::now();
  const StateLayout L = domain_->layout();
  const double dt = t - t_prev_;
  if (dt <= 0) return;  // the same on every rank (the same steps)
  project_velocities(dt, t, y);

  // 4. Positions centred in time, C&R eq. 12, plus the step's regularisation displacement dt du_s
  // (du_s of the fields at r*, refreshed by the projection) when a regularisation part is on.
  if (centre_positions_ && y_prev_.size() == L.size()) centre_positions(L, domain_->fields(), y_prev_, dt, y);
  stats_.seconds += seconds_since(t0);

  // 5. Density correction, Szewc eqs. 57-58 (timed separately).
  if (correction_) correction_->apply(t, y);
}

void Projection::project_velocities(double dt, double t, double* y) {
  const StateLayout L = domain_->layout();
  const std::size_t n = L.n;
  double* u = y + L.vel(0);
  double* v = L.dim == 2 ? y + L.vel(1) : nullptr;
  // 1. Fields at r* with u* (on ranks the halo copies take u* from their owners). The source sees
  // u* - dt g; the flux of g is the PPE's Neumann data.
  if (split_.active()) split_.remove_step(n, y + L.pos(0), L.dim == 2 ? y + L.pos(1) : nullptr, t, dt, u, v);
  domain_->set_slip_origin(false, 0.0);  // the increment is out of u* above: plain images
  domain_->refresh(t, y);
  if (split_.active()) split_.restore_velocities(u, v);
  const FluidFields& f = domain_->fields();
  // 2.-3. Pressure Poisson equation and velocity correction, on the particles or on the grid. The
  // source of the own particles (on ranks the halo copies' divergences are not used).
  const auto ta = std::chrono::steady_clock::now();
  std::vector<double> div = difference_divergence_ ? divergence_difference(f) : divergence_cummins_rudman(f);
  if (split_.active()) {
    const std::vector<double> dg = split_.divergence(f);
    // On the grid the flux of g enters at the wall faces (GridProjection), on the particles here.
    const std::vector<double> flux = grid_ ? std::vector<double>(n, 0.0)
                                     : exact_operator_ ? neumann_source_exact(f) : neumann_source(f);
    for (std::size_t a = 0; a < n; ++a) div[a] += dt * (dg[a] + flux[a]);
  }
  // At a free surface the last projection's P gives the Laplacian's defect at cut supports
  // (free_surface.hpp): L(P) - c . grad P = div/dt, its lagged part in the source; and the surface
  // particles' given P (p = 0 half a spacing beyond them). Without a last P
  // (the first step, or after the solvers forgot theirs: a checkpoint, a re-sort, a migration) one
  // solve without the defect gives it, so that a restarted run continues bit for bit.
  if (free_surface_ && !grid_) {
    if (solution_.size() != n) {
      poisson_->set_given(surface_rows(f, n, surface_threshold_, surface_depth_, {}));
      const SolveReport rep = poisson_->solve(f, div, dt, solution_);
      stats_.record_solve(rep.iterations, rep.refactored_symbolic, rep.relative_residual);
    }
    last_gradient_ = renormalised_gradients(f, domain_->with_halo(solution_), n);
    const std::vector<double> defect = linear_laplacian_defect(f, last_gradient_, n);
    for (std::size_t a = 0; a < n; ++a) div[a] += dt * defect[a];
  }
  stats_.assembly_seconds += seconds_since(ta);
  if (grid_) {
    project_on_grid(f, div, dt, y);
  } else {
    project_on_particles(f, div, dt, y);
  }
}

void Projection::project_on_particles(const FluidFields& f, const std::vector<double>& div, double dt, double* y) {
  const StateLayout L = domain_->layout();
  const std::size_t n = L.n;
  DirichletRows given;
  if (free_surface_) {
    given = surface_rows(f, n, surface_threshold_, surface_depth_, last_gradient_);
    poisson_->set_given(given);
  }
  const double assembly_before = poisson_->assembly_seconds();
  const auto ts = std::chrono::steady_clock::now();
  // solution_ keeps the pinned system's own solution (one P = 0) as the next warm start: a start
  // shifted by a constant would hand CG a smooth error, its slowest mode.
  const SolveReport rep = poisson_->solve(f, div, dt, solution_);
  const double assembly = poisson_->assembly_seconds() - assembly_before;
  stats_.assembly_seconds += assembly;
  stats_.solve_seconds += seconds_since(ts) - assembly;
  stats_.record_solve(rep.iterations, rep.refactored_symbolic, rep.relative_residual);
  stats_.setup_seconds += rep.setup_seconds;
  // The level of P is free (Neumann walls) but matters to the symmetric gradient of eq. 11 on
  // disordered particles: zero mean, or zero minimum (P >= 0: pair forces never attract), over
  // every particle, then the offset.
  // A free surface fixes the level: p = 0 there.
  const double level = free_surface_ ? 0.0 : domain_->level(solution_, zero_min_level_);
  const double offset = free_surface_ ? 0.0 : pressure_offset_;
  pressure_.resize(n);
  for (std::size_t a = 0; a < n; ++a) pressure_[a] = solution_[a] - level + offset;
  // Below a free surface no suction: p >= 0. The rows next to the surface rows solve to p < 0 where
  // the surge thins and at the walls' contact lines, and the pairs there then pull together (the
  // instability the zero_min level removes in a closed box, where a level can be chosen; here p = 0
  // at the surface fixes it). Without the limit the a/40 dam break blows up at t sqrt(g/a) ~ 1.7.
  if (free_surface_)
    for (double& p : pressure_) p = std::max(p, 0.0);
  if (gravity_.active) report(pressure_);

  // 3. Velocity correction, C&R eq. 11, with P at every real point of the fields (on ranks the
  // halo copies' their owners'); ghosts carry their source's P, plus the hydrostatic step under a
  // body force (FluidFields::point_pressure). At a free surface the renormalised difference
  // gradient instead (free_surface.hpp).
  double* u = y + L.vel(0);
  double* v = L.dim == 2 ? y + L.vel(1) : nullptr;
  if (free_surface_)
    subtract_renormalised_gradient(f, domain_->with_halo(pressure_), dt, n, u, v, given.fixed);
  else
    subtract_pressure_gradient(f, domain_->with_halo(pressure_), dt, n, u, v);
}


void Projection::project_on_grid(const FluidFields& f, const std::vector<double>& div, double dt, double* y) {
  const StateLayout L = domain_->layout();
  const std::size_t n = L.n;
  const auto ts = std::chrono::steady_clock::now();
  // On ranks each deposits its own particles and the cell sums are combined: every rank solves the
  // whole grid problem and interpolates at its own particles.
  GridCorrection c = grid_->solve(f, n, div, dt, domain_->cell_combine());
  stats_.solve_seconds += seconds_since(ts);
  stats_.record_solve(1, c.refactorised, c.residual);
  pressure_ = std::move(c.pressure);
  if (zero_min_level_) {  // the grid's p has zero mean over the cells; P >= 0 over every particle
    const double level = domain_->level(pressure_, true);
    for (double& p : pressure_) p -= level;
  }
  if (gravity_.active) report(pressure_);
  // Velocity correction, Szewc eq. 30, with (1/rho) grad p from the grid.
  double* u = y + L.vel(0);
  for (std::size_t a = 0; a < n; ++a) u[a] -= dt * c.ax[a];
  if (L.dim == 2) {
    double* v = y + L.vel(1);
    for (std::size_t a = 0; a < n; ++a) v[a] -= dt * c.ay[a];
  }
}

void Projection::report(const std::vector<double>& p) {
  const FluidFields& f = domain_->fields();
  const std::size_t n = p.size();
  const std::vector<double> h = gravity_.head(n, f.x.data(), f.dim == 2 ? f.y.data() : nullptr);
  const double lowest = domain_->level(h, true);  // over every particle
  reported_.resize(n);
  for (std::size_t a = 0; a < n; ++a) reported_[a] = p[a] + gravity_.rho0 * (h[a] - lowest);
}

}  // namespace arksph
