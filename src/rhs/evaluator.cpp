#include "rhs/evaluator.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include <omp.h>

#include "core/particle_order.hpp"

namespace arksph {

namespace {
// Loops of a few operations per particle run on one thread below this size: waking the other
// threads (futex, with passive waiting) costs more than the loop itself.
constexpr std::size_t kCheapLoopParallelMin = 20000;
// The passes that load the state and store the derivatives: about ten arrays each, in parallel
// from this size on (BM_RhsEval, N = 2,500, 2 threads: faster than with these passes serial).
constexpr std::size_t kLoadParallelMin = 2000;

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

RhsEvaluator::RhsEvaluator(const Scene& scene, const ParticleSet& particles, Kernel kernel,
                           std::vector<std::unique_ptr<Term>> terms)
    : particles_(particles),
      kernel_(std::move(kernel)),
      terms_(std::move(terms)),
      ghost_builder_(scene, ghost_depth(scene, kernel_.radius())),
      lean_pairs_(scene.neighbor_storage == "candidates"),
      sweep_(scene.force_sweep),
      // The projection walks the pairs of its field refresh (at r*) several times (divergence,
      // assembly, gradient): stored, not lean. Its force terms' f(t, y) is at other positions, so
      // they run in the sweep like WCSPH's.
      stored_pairs_on_refresh_(scene.scheme != "wcsph") {
  // Verlet skin: candidates within 1.15 R; rebuilt when a particle has moved more than 0.075 R.
  skin_ = 0.15 * kernel_.radius();
  if (scene.wall_velocity == "linear" && scene.dimension == 2)
    linear_wall_ = std::make_unique<LinearWallVelocity>(scene, scene.spacing);
  if (scene.wall_velocity == "quadratic" && scene.dimension == 2)
    quadratic_wall_ = std::make_unique<QuadraticWallVelocity>(scene, scene.spacing);
  for (int k = 0; k < scene.dimension; ++k) {
    periodic_[k] = scene.sides[2 * k].kind == SideKind::periodic;
    lo_[k] = scene.min[k];
    len_[k] = scene.max[k] - scene.min[k];
  }
  layout_.n = particles.n;
  layout_.dim = particles.dim;
  layout_.has_density = scene.scheme == "wcsph" && scene.density_mode == "continuity";
  layout_.has_energy = scene.scheme == "wcsph" && scene.equation_of_state == "ideal_gas";
  std::stable_sort(terms_.begin(), terms_.end(),
                   [](const auto& a, const auto& b) { return a->stage() < b->stage(); });
  for (const auto& t : terms_) viscous_.push_back(t->name().rfind("viscosity:", 0) == 0);
  // The pair list is built at every f unless the sweep covers every term that walks neighbours and
  // nothing else reads the pairs afterwards (the projection schemes do).
  pairs_every_eval_ = !sweep_;
  for (const auto& t : terms_)
    if (t->uses_neighbors() && !t->per_particle()) pairs_every_eval_ = true;
  fields_.dim = particles.dim;
  fields_.n_real = particles.n;
  fields_.kernel = &kernel_;
  fields_.nu = scene.viscosity;
  fields_.rho0 = particles.rho0;
  const std::size_t n = particles.n;
  fields_.dudt.assign(n, 0.0);
  fields_.dvdt.assign(n, 0.0);
  fields_.drhodt.assign(n, 0.0);
  if (layout_.has_energy) fields_.dedt.assign(n, 0.0);
}

std::vector<std::string> RhsEvaluator::term_names() const {
  std::vector<std::string> names;
  for (const auto& t : terms_) names.push_back(t->name());
  return names;
}

void RhsEvaluator::permute_particles(const std::vector<std::uint32_t>& from) {
  // The neighbour lists are rebuilt at the next eval anyway: free them first, so that the
  // permutation's temporaries do not add to them at the run's peak of memory.
  candidates_ = CandidateList{};
  fields_.pairs = PairList{};
  cells_ = CellList{};
  permute(particles_, from);
  permute(fields_.rho0, from);
  permute(visc_u_, from);  // IMEX f_I of the last eval, in the new order
  permute(visc_v_, from);
  invalidate_neighbors();
}

void RhsEvaluator::initial_state(double* y) const {
  const std::size_t n = layout_.n;
  for (int k = 0; k < layout_.dim; ++k) {
    std::copy(particles_.init_pos[k].begin(), particles_.init_pos[k].end(), y + layout_.pos(k));
    std::copy(particles_.init_vel[k].begin(), particles_.init_vel[k].end(), y + layout_.vel(k));
  }
  if (layout_.has_density) std::copy(particles_.rho0.begin(), particles_.rho0.begin() + n, y + layout_.rho());
  if (layout_.has_energy) std::fill(y + layout_.energy(), y + layout_.energy() + n, particles_.init_energy);
}

// Real particles' fields from y in one pass over the particles: positions (wrapped back into the
// box on periodic axes: f is invariant under the shift, so y itself is left alone and the
// integrator needs no re-initialisation), velocities (also as the divergence velocities), density;
// p and the time derivatives zeroed. Returns the largest squared displacement since the last
// neighbour rebuild (infinite if there is no list yet).
double RhsEvaluator::load_state(double t, const double* y) {
  FluidFields& f = fields_;
  const std::size_t n = layout_.n;
  const bool two_d = layout_.dim == 2;
  f.t = t;
  // Sized to n (shrinking from n_all keeps the storage: no allocation, no fill); ghosts come later.
  for (auto* v : {&f.x, &f.u, &f.ud, &f.rho, &f.p}) v->resize(n);
  if (two_d)
    for (auto* v : {&f.y, &f.v, &f.vd}) v->resize(n);
  if (layout_.has_energy) f.e.assign(y + layout_.energy(), y + layout_.energy() + n);
  const double* yx = y + layout_.pos(0);
  const double* yy = two_d ? y + layout_.pos(1) : nullptr;
  const double* yu = y + layout_.vel(0);
  const double* yv = two_d ? y + layout_.vel(1) : nullptr;
  const double* yrho = layout_.has_density ? y + layout_.rho() : particles_.rho0.data();  // else: summation
  const bool wrap_x = periodic_[0], wrap_y = two_d && periodic_[1];
  const double lo_x = lo_[0], len_x = len_[0], lo_y = lo_[1], len_y = len_[1];
  const bool have_ref = ref_x_.size() == n;
  double *x = f.x.data(), *u = f.u.data(), *ud = f.ud.data(), *rho = f.rho.data(), *p = f.p.data();
  double *py = two_d ? f.y.data() : nullptr, *v = two_d ? f.v.data() : nullptr, *vd = two_d ? f.vd.data() : nullptr;
  double *dudt = f.dudt.data(), *dvdt = f.dvdt.data(), *drhodt = f.drhodt.data();
  const double *rx = ref_x_.data(), *ry = ref_y_.data();
  double moved2 = 0.0;  // NaN positions compare false: caught by the state checks, not here
#pragma omp parallel for schedule(static) reduction(max : moved2) if (n > kLoadParallelMin)
  for (std::size_t a = 0; a < n; ++a) {
    double xa = yx[a];
    if (wrap_x && (xa < lo_x || xa >= lo_x + len_x)) xa = lo_x + (xa - lo_x) - len_x * std::floor((xa - lo_x) / len_x);
    x[a] = xa;
    u[a] = ud[a] = yu[a];
    rho[a] = yrho[a];
    p[a] = 0.0;
    dudt[a] = dvdt[a] = drhodt[a] = 0.0;
    double dx = have_ref ? xa - rx[a] : 0.0, dy = 0.0;
    if (two_d) {
      double ya = yy[a];
      if (wrap_y && (ya < lo_y || ya >= lo_y + len_y)) ya = lo_y + (ya - lo_y) - len_y * std::floor((ya - lo_y) / len_y);
      py[a] = ya;
      v[a] = vd[a] = yv[a];
      dy = have_ref ? ya - ry[a] : 0.0;
    }
    moved2 = std::max(moved2, dx * dx + dy * dy);
  }
  std::fill(f.dedt.begin(), f.dedt.end(), 0.0);
  return have_ref ? moved2 : std::numeric_limits<double>::infinity();
}

void RhsEvaluator::refresh_ghosts(bool rebuild) {
  FluidFields& f = fields_;
  const std::size_t n = layout_.n;
  const bool two_d = layout_.dim == 2;
  if (rebuild) {
    ghost_builder_.build(f.x.data(), two_d ? f.y.data() : nullptr, n, ghosts_, skin_);
  } else {
    ghost_builder_.update(f.x.data(), two_d ? f.y.data() : nullptr, ghosts_);
  }
  const std::size_t ng = ghosts_.size();
  f.n_all = n + ng;
  // Room for the ghosts without the doubling of a growing vector (about 20 arrays of n_all).
  auto room = [&](auto& field) {
    if (field.capacity() < f.n_all) field.reserve(f.n_all + f.n_all / 64);
  };
  for (auto* field : {&f.x, &f.u, &f.ud, &f.m, &f.rho, &f.p, &f.vol, &f.mu, &f.flip_x}) room(*field);
  if (two_d)
    for (auto* field : {&f.y, &f.v, &f.vd, &f.flip_y}) room(*field);
  room(f.src);
  f.x.insert(f.x.end(), ghosts_.x.begin(), ghosts_.x.end());
  if (two_d) f.y.insert(f.y.end(), ghosts_.y.begin(), ghosts_.y.end());
  for (auto* field : {&f.u, &f.ud, &f.rho, &f.p}) field->resize(f.n_all);  // ghost values: below and at each stage
  if (two_d)
    for (auto* field : {&f.v, &f.vd}) field->resize(f.n_all);
  // Constant between rebuilds (the ghosts keep their sources and places): set only at a rebuild.
  if (rebuild) {
    f.m.assign(particles_.mass.begin(), particles_.mass.end());
    f.m.resize(f.n_all);
    for (std::size_t g = 0; g < ng; ++g) f.m[n + g] = f.m[ghosts_.source[g]];
    f.src.resize(f.n_all);
    for (std::size_t a = 0; a < n; ++a) f.src[a] = static_cast<std::uint32_t>(a);
    for (std::size_t g = 0; g < ng; ++g) f.src[n + g] = ghosts_.source[g];
    f.flip_x.assign(f.n_all, 1.0);
    f.flip_y.assign(two_d ? f.n_all : 0, 1.0);
    for (std::size_t g = 0; g < ng; ++g) {
      f.flip_x[n + g] = ghosts_.place[g][0];
      if (two_d) f.flip_y[n + g] = ghosts_.place[g][1];
    }
  }
  ghost_velocities();
}

// Ghost velocities from their sources' (affine maps), then the wall-velocity extrapolations.
void RhsEvaluator::ghost_velocities() {
  FluidFields& f = fields_;
  const std::size_t n = layout_.n;
  const bool two_d = layout_.dim == 2;
  for (std::size_t g = 0; g < ghosts_.size(); ++g) {
    const std::size_t i = n + g, s = ghosts_.source[g];
    const auto& mv = ghosts_.map[g];
    const auto& md = ghosts_.div_map[g];
    const double us = f.u[s], vs = two_d ? f.v[s] : 0.0;
    f.u[i] = mv[0] * us + mv[2];
    f.ud[i] = md[0] * us + md[2];
    if (two_d) {
      f.v[i] = mv[1] * vs + mv[3];
      f.vd[i] = md[1] * vs + md[3];
    }
  }
  if (linear_wall_) linear_wall_->apply(ghosts_, n, f.x.data(), f.y.data(), f.u.data(), f.v.data());
  if (quadratic_wall_) quadratic_wall_->apply(ghosts_, n, f.x.data(), f.y.data(), f.u.data(), f.v.data());
}

// The viscous terms alone into (au, av); dudt, dvdt are left as they were.
void RhsEvaluator::apply_viscous_terms(std::vector<double>& au, std::vector<double>& av) {
  FluidFields& f = fields_;
  keep_du_.assign(f.dudt.begin(), f.dudt.end());
  keep_dv_.assign(f.dvdt.begin(), f.dvdt.end());
  std::fill(f.dudt.begin(), f.dudt.end(), 0.0);
  std::fill(f.dvdt.begin(), f.dvdt.end(), 0.0);
  for (std::size_t k = 0; k < terms_.size(); ++k)
    if (viscous_[k]) terms_[k]->apply(f);
  au.assign(f.dudt.begin(), f.dudt.end());
  av.assign(f.dvdt.begin(), f.dvdt.end());
  f.dudt.swap(keep_du_);
  f.dvdt.swap(keep_dv_);
}

void RhsEvaluator::implicit_part(double* ydot_i) const {
  std::fill(ydot_i, ydot_i + layout_.size(), 0.0);
  std::copy(visc_u_.begin(), visc_u_.end(), ydot_i + layout_.vel(0));
  if (layout_.dim == 2) std::copy(visc_v_.begin(), visc_v_.end(), ydot_i + layout_.vel(1));
}

void RhsEvaluator::viscous_acceleration(const double* u, const double* v, double* au, double* av) {
  FluidFields& f = fields_;
  const std::size_t n = layout_.n;
  const bool two_d = layout_.dim == 2;
  keep_u_.assign(f.u.begin(), f.u.end());
  keep_v_.assign(f.v.begin(), f.v.end());
  std::copy(u, u + n, f.u.begin());
  if (two_d) std::copy(v, v + n, f.v.begin());
  keep_ud_.assign(f.ud.begin(), f.ud.end());  // ghost_velocities also writes the divergence copies
  keep_vd_.assign(f.vd.begin(), f.vd.end());
  ghost_velocities();
  apply_viscous_terms(probe_u_, probe_v_);
  std::copy(probe_u_.begin(), probe_u_.end(), au);
  if (two_d) std::copy(probe_v_.begin(), probe_v_.end(), av);
  f.u.swap(keep_u_);
  f.v.swap(keep_v_);
  f.ud.swap(keep_ud_);
  f.vd.swap(keep_vd_);
}

void RhsEvaluator::copy_to_ghosts(std::vector<double>& field) {
  const std::size_t n = layout_.n;
  field.resize(fields_.n_all);
  for (std::size_t g = 0; g < ghosts_.size(); ++g) field[n + g] = field[ghosts_.source[g]];
}

// Terms [first, last) particle by particle: each particle's neighbourhood is gathered once (kernel
// values included) into a per-thread buffer and handed to every term in order. Same sums, in the same
// order, as applying the terms one after another over the pair list.
void RhsEvaluator::force_sweep(std::size_t first, std::size_t last) {
  FluidFields& f = fields_;
  const double* x = f.x.data();
  const double* y = layout_.dim == 2 ? f.y.data() : nullptr;
  const std::size_t threads = static_cast<std::size_t>(omp_get_max_threads());
  if (scratch_.size() < threads) scratch_.resize(threads);
  bool with_w = f.correction != FluidFields::Correction::none;
  for (std::size_t k = first; k < last; ++k) with_w = with_w || terms_[k]->reads_kernel_value();
  for (Neighborhood& nb : scratch_) {
    nb.reserve(sweep_room_);
    nb.with_w = with_w;
  }
#pragma omp parallel
  {
    Neighborhood& nb = scratch_[static_cast<std::size_t>(omp_get_thread_num())];
    // Dynamic chunks balance the threads; each particle's sums are the same whatever thread runs it.
#pragma omp for schedule(dynamic, 64)
    for (std::size_t a = 0; a < layout_.n; ++a) {
      gather_neighborhood(candidates_, kernel_, x, y, a, nb);
      for (std::size_t k = first; k < last; ++k) terms_[k]->apply_particle(f, a, nb);
    }
  }
}

// ydot (if not null) from the derivatives of the real particles, in one pass over the particles:
// positions move with the velocities of y. Returns the largest acceleration |(dudt, dvdt)|.
double RhsEvaluator::store_derivatives(const double* y, double* ydot) const {
  const FluidFields& f = fields_;
  const std::size_t n = layout_.n;
  const bool two_d = layout_.dim == 2;
  const double *dudt = f.dudt.data(), *dvdt = f.dvdt.data(), *drhodt = f.drhodt.data();
  const double *yu = y + layout_.vel(0), *yv = two_d ? y + layout_.vel(1) : nullptr;
  double* out_x = ydot ? ydot + layout_.pos(0) : nullptr;
  double* out_y = ydot && two_d ? ydot + layout_.pos(1) : nullptr;
  double* out_u = ydot ? ydot + layout_.vel(0) : nullptr;
  double* out_v = ydot && two_d ? ydot + layout_.vel(1) : nullptr;
  double* out_rho = ydot && layout_.has_density ? ydot + layout_.rho() : nullptr;
  double amax2 = 0;
#pragma omp parallel for schedule(static) reduction(max : amax2) if (n > kLoadParallelMin)
  for (std::size_t a = 0; a < n; ++a) {
    const double ax = dudt[a], ay = two_d ? dvdt[a] : 0.0;
    amax2 = std::max(amax2, ax * ax + ay * ay);
    if (!ydot) continue;
    out_x[a] = yu[a];
    out_u[a] = ax;
    if (two_d) {
      out_y[a] = yv[a];
      out_v[a] = ay;
    }
    if (out_rho) out_rho[a] = drhodt[a];
  }
  if (ydot && layout_.has_energy) std::copy(f.dedt.begin(), f.dedt.end(), ydot + layout_.energy());
  return std::sqrt(amax2);
}

void RhsEvaluator::eval(double t, const double* y, double* ydot) {
  using clock = std::chrono::steady_clock;
  FluidFields& f = fields_;
  const std::size_t n = layout_.n;
  const bool two_d = layout_.dim == 2;
  ++evals_;

  auto t0 = clock::now();
  // Rebuilt when a particle has moved more than half the skin since the last rebuild.
  const bool rebuild = load_state(t, y) > 0.25 * skin_ * skin_;
  refresh_ghosts(rebuild);
  if (rebuild) {
    cells_.build(f.x.data(), two_d ? f.y.data() : nullptr, f.n_all, kernel_.radius() + skin_);
    build_candidates(cells_, f.x.data(), two_d ? f.y.data() : nullptr, n, candidates_);
    cells_ = CellList{};  // needed again only at the next rebuild: ~21 bytes a point less meanwhile
    ref_x_.assign(f.x.begin(), f.x.begin() + n);
    if (two_d) ref_y_.assign(f.y.begin(), f.y.begin() + n);
    sweep_room_ = max_candidates(candidates_);
    ++rebuilds_;
  }
  // Pairs for the terms outside the sweep, for IMEX's viscous probes and for whoever reads fields()
  // after a field refresh (ydot null: diagnostics, the projection); otherwise none are stored.
  // When only a refresh needs them, the lean form (kernel evaluated on each visit, same values):
  // the diagnostics walk them once, and no per-pair arrays are ever allocated (WCSPH).
  if (pairs_every_eval_ || implicit_viscosity_ || !ydot) {
    if (lean_pairs_ || (!pairs_every_eval_ && !implicit_viscosity_ && !stored_pairs_on_refresh_))
      lean_pairs_from_candidates(candidates_, kernel_, f.x.data(), two_d ? f.y.data() : nullptr, f.pairs);
    else
      pairs_from_candidates(candidates_, kernel_, f.x.data(), two_d ? f.y.data() : nullptr, f.pairs);
  } else {
    f.pairs.n_real = 0;  // stale: PairList::for_pairs asserts on it
  }
  timing_.neighbors += seconds_since(t0);

  t0 = clock::now();
  copy_to_ghosts(f.rho);
  copy_to_ghosts(f.p);
  Term::Stage done = Term::Stage::density;
  for (std::size_t k = 0; k < terms_.size();) {
    const auto& term = terms_[k];
    if (term->stage() != done) {  // entering a later stage: ghosts take their sources' new values
      copy_to_ghosts(f.rho);
      copy_to_ghosts(f.p);
      done = term->stage();
      if (done == Term::Stage::force) {
        f.vol.resize(f.n_all);
        f.mu.resize(f.n_all);
#pragma omp parallel for schedule(static) if (f.n_all > kCheapLoopParallelMin)
        for (std::size_t i = 0; i < f.n_all; ++i) {
          f.vol[i] = f.m[i] / f.rho[i];
          f.mu[i] = f.rho[i] * f.nu;
        }
      }
    }
    if (implicit_viscosity_ && viscous_[k]) {  // IMEX: f_I, below
      ++k;
      continue;
    }
    if (sweep_ && term->per_particle()) {  // this term and the per-particle ones after it: one sweep
      std::size_t last = k + 1;
      while (last < terms_.size() && terms_[last]->per_particle() && terms_[last]->stage() == done &&
             !(implicit_viscosity_ && viscous_[last]))
        ++last;
      force_sweep(k, last);
      k = last;
      continue;
    }
    term->apply(f);
    ++k;
  }
  copy_to_ghosts(f.rho);
  copy_to_ghosts(f.p);
  if (implicit_viscosity_) apply_viscous_terms(visc_u_, visc_v_);

  max_accel_ = store_derivatives(y, ydot);
  timing_.terms += seconds_since(t0);
}

}  // namespace arksph
