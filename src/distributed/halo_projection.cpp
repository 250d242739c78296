#include "distributed/halo_projection.hpp"

#include <algorithm>
#include <chrono>

#include "core/errors.hpp"
#include "core/scheme.hpp"
#include "distributed/gather_state.hpp"
#include "distributed/rank_verdict.hpp"
#include "projection/ppe_assembly.hpp"
#include "projection/velocity_correction.hpp"

namespace arksph::distributed {

namespace {
double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

HaloProjection::HaloProjection(const Scene& scene, const parallel::Communicator& comm, HaloRhs& f,
                               RankParticles& owned, std::int64_t pinned_id, double flow_rate)
    : comm_(comm),
      f_(f),
      owned_(owned),
      poisson_(comm, f, owned, pinned_id, scene.ppe_tolerance),
      split_(scene),
      slip_origin_(split_.active() && scene.projection_points == "step" && !scene.pressure_in_f()),
      centre_positions_(scene.centre_positions),
      difference_divergence_(scene.ppe_divergence == "difference"),
      zero_min_level_(scene.ppe_pressure_level == "zero_min"),
      pressure_offset_(scene.ppe_pressure_offset) {
  if (scheme_traits(scene.scheme).grid) grid_ = std::make_unique<GridProjection>(scene);
  if (scene.pressure_in_f())
    constrained_ = std::make_unique<HaloConstrainedPressure>(scene, comm, f, owned, pinned_id, flow_rate);
  // The constrained projection carries the correction inside f (HaloConstrainedPressure).
  if (scene.density_correction != "none" && !scene.pressure_in_f()) correction_ = std::make_unique<HaloDensityCorrection>(scene, comm, f, owned, pinned_id);
}

std::vector<double> HaloProjection::pressure_at(const std::vector<std::int64_t>& ids, std::size_t n) const {
  const std::vector<double> by_id = spread_by_id(comm_, pressure_ids_, pressure_, n);
  std::vector<double> out(ids.size());
  for (std::size_t a = 0; a < ids.size(); ++a) out[a] = by_id[static_cast<std::size_t>(ids[a])];
  return out;
}

void HaloProjection::particles_moved() {
  poisson_.particles_moved();
  if (constrained_) constrained_->particles_moved();
  solution_.clear();
  y_prev_.clear();
  if (correction_) correction_->particles_moved();
}

void HaloProjection::constrain(const double* y, double* ydot) {
  const auto t0 = std::chrono::steady_clock::now();
  const distributed_ppe::HypreSolveReport rep = constrained_->constrain(y, ydot);
  stats_.record_solve(rep.iterations, rep.refactored_symbolic, rep.relative_residual);
  pressure_ = constrained_->pressure();
  pressure_ids_ = owned_.ids();
  const double s = since(t0);
  stats_.seconds += s;
  stats_.solve_seconds += s;
}

void HaloProjection::project_initial(double t, double* y) {
  if (!constrained_) return;
  const distributed_ppe::HypreSolveReport rep = constrained_->project_velocity(t, y);
  stats_.max_residual = std::max(stats_.max_residual, rep.relative_residual);
}

void HaloProjection::begin_step(double t, const double* y) {
  // The stages of a step projected at its end carry (t - t_n) g (body_force_split.hpp).
  f_.set_slip_origin(slip_origin_, t);
  t_prev_ = t;
  y_prev_.assign(y, y + owned_.layout().size());
}

void HaloProjection::project(double t, double* y) {
  const auto t0 = std::chrono::steady_clock::now();
  const double dt = t - t_prev_;
  if (dt <= 0) return;  // the same on every rank (the same steps)
  project_velocities(dt, t, y);
  const StateLayout L = owned_.layout();

  // 4. Positions centred in time, C&R eq. 12, plus the step's regularisation displacement dt du_s
  // (du_s of the fields at r*), as in one process.
  if (centre_positions_ && y_prev_.size() == L.size()) centre_positions(L, f_.evaluator().fields(), y_prev_, dt, y);
  stats_.seconds += since(t0);

  // 5. Density correction, Szewc eqs. 57-59 (timed separately).
  if (correction_) correction_->apply(t, y);
}

void HaloProjection::project_stage(double t, double* y) {
  const double dt = t - t_prev_;
  if (dt <= 0) return;  // a stage at c_i = 0 needs no projection
  const auto t0 = std::chrono::steady_clock::now();
  project_velocities(dt, t, y);
  stats_.seconds += since(t0);
}

void HaloProjection::project_velocities(double dt, double t, double* y) {
  const StateLayout L = owned_.layout();
  const std::size_t n = L.n;

  // 1. Fields at r* with u* over the rank's particles and the halo (the copies take u* too).
  double* u = y + L.vel(0);
  double* v = L.dim == 2 ? y + L.vel(1) : nullptr;
  // the source sees u* - dt g; the flux of g is the PPE's Neumann data
  if (split_.active()) split_.remove_step(n, y + L.pos(0), L.dim == 2 ? y + L.pos(1) : nullptr, t, dt, u, v);
  f_.set_slip_origin(false, 0.0);  // the increment is out of u* above: plain images
  // A field refresh that fails on one rank (a blown-up neighbour grid) fails on all, with its
  // message: the others would otherwise wait in the solve's collectives.
  Verdict refreshed;
  try {
    f_.eval(t, y, nullptr);
  } catch (const NumericalFailure& e) {
    refreshed = {3, e.what()};
  }
  refreshed = agree(comm_, refreshed);
  if (refreshed.code) throw NumericalFailure(refreshed.message);
  if (split_.active()) split_.restore_velocities(u, v);
  const FluidFields& f = f_.evaluator().fields();

  // 2. Source of the owned particles (the halo's divergences are not used). On the grid the flux of
  // g enters at the wall faces (GridProjection), on the particles in the source.
  const auto ta = std::chrono::steady_clock::now();
  std::vector<double> div = difference_divergence_ ? divergence_difference(f) : divergence_cummins_rudman(f);
  if (split_.active()) {
    const std::vector<double> dg = split_.divergence(f);
    const std::vector<double> flux = grid_ ? std::vector<double>(n, 0.0) : neumann_source(f);
    for (std::size_t a = 0; a < n; ++a) div[a] += dt * (dg[a] + flux[a]);
  }
  stats_.assembly_seconds += since(ta);
  pressure_ids_ = owned_.ids();
  if (grid_)
    project_on_grid(f, div, dt, u, v);
  else
    project_on_particles(f, div, dt, u, v);
}

void HaloProjection::project_on_grid(const FluidFields& f, const std::vector<double>& div, double dt, double* u,
                                     double* v) {
  const std::size_t n = owned_.layout().n;
  const auto ts = std::chrono::steady_clock::now();
  const CellCombine combine = [this](std::vector<double>& sums, std::vector<double>& maxima) {
    comm_.sum_in_place(sums);
    comm_.max_in_place(maxima);
  };
  GridCorrection c = grid_->solve(f, n, div, dt, combine);
  stats_.solve_seconds += since(ts);
  stats_.record_solve(1, c.refactorised, c.residual);
  pressure_ = std::move(c.pressure);
  if (zero_min_level_) {  // the grid's p has zero mean over the cells; P >= 0 over every rank
    const double level = poisson_.level(pressure_, true);
    for (double& p : pressure_) p -= level;
  }
  // Velocity correction, Szewc eq. 30, with (1/rho) grad p from the grid.
  for (std::size_t a = 0; a < n; ++a) u[a] -= dt * c.ax[a];
  if (v)
    for (std::size_t a = 0; a < n; ++a) v[a] -= dt * c.ay[a];
}

void HaloProjection::project_on_particles(const FluidFields& f, std::vector<double>& div, double dt, double* u,
                                          double* v) {
  const std::size_t n = owned_.layout().n;
  const double assembly_before = poisson_.assembly_seconds();
  const auto ts = std::chrono::steady_clock::now();
  // solution_ keeps the pinned system's own solution (P_pinned = 0) as the next warm start, as in
  // one process (a start shifted by a constant would hand CG a smooth error).
  const distributed_ppe::HypreSolveReport rep = poisson_.solve(div, dt, solution_);
  const double assembly = poisson_.assembly_seconds() - assembly_before;
  stats_.assembly_seconds += assembly;
  stats_.solve_seconds += since(ts) - assembly;
  stats_.record_solve(rep.iterations, rep.refactored_symbolic, rep.relative_residual);

  // 3. The level over all ranks: zero minimum or zero mean, then the offset.
  const double level = poisson_.level(solution_, zero_min_level_);
  pressure_.resize(n);
  for (std::size_t a = 0; a < n; ++a) pressure_[a] = solution_[a] - level + pressure_offset_;
  // Velocity correction, C&R eq. 11, with P at every real point of the evaluator (the copies their
  // owners'); ghosts carry their source's P, plus the hydrostatic step under a body force
  // (FluidFields::point_pressure).
  subtract_pressure_gradient(f, poisson_.with_halo(pressure_), dt, n, u, v);
}

}  // namespace arksph::distributed
