#include "rhs/evaluator.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <omp.h>

#include "core/particle_order.hpp"

namespace arksph {

namespace {
// Loops of a few operations per particle run on one thread below this size: waking the other
// threads (futex, with passive waiting) costs more than the loop itself.
constexpr std::size_t kCheapLoopParallelMin = 20000;

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

void RhsEvaluator::load_state(double t, const double* y) {
  FluidFields& f = fields_;
  const std::size_t n = layout_.n;
  f.t = t;
  // Positions and velocities of real particles; ghosts are appended afterwards.
  f.x.assign(y + layout_.pos(0), y + layout_.pos(0) + n);
  f.u.assign(y + layout_.vel(0), y + layout_.vel(0) + n);
  if (layout_.dim == 2) {
    f.y.assign(y + layout_.pos(1), y + layout_.pos(1) + n);
    f.v.assign(y + layout_.vel(1), y + layout_.vel(1) + n);
  }
  // Periodic axes: positions in y may drift out of the box; the fields see them wrapped back in.
  // f is invariant under the shift, so y itself is left alone (no integrator re-initialisation).
  for (int k = 0; k < layout_.dim; ++k) {
    if (!periodic_[k]) continue;
    std::vector<double>& c = k == 0 ? f.x : f.y;
    const double lo = lo_[k], len = len_[k];
    double* v = c.data();
#pragma omp parallel for schedule(static) if (n > kCheapLoopParallelMin)
    for (std::size_t a = 0; a < n; ++a)
      if (v[a] < lo || v[a] >= lo + len) v[a] = lo + (v[a] - lo) - len * std::floor((v[a] - lo) / len);
  }
  if (layout_.has_density)
    f.rho.assign(y + layout_.rho(), y + layout_.rho() + n);
  else
    f.rho.assign(particles_.rho0.begin(), particles_.rho0.end());  // replaced by summation if enabled
  f.p.assign(n, 0.0);
  if (layout_.has_energy) f.e.assign(y + layout_.energy(), y + layout_.energy() + n);
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
  f.u.resize(f.n_all);
  f.v.resize(two_d ? f.n_all : 0);
  f.ud.resize(f.n_all);
  f.vd.resize(two_d ? f.n_all : 0);
  std::copy(f.u.begin(), f.u.begin() + n, f.ud.begin());
  if (two_d) std::copy(f.v.begin(), f.v.begin() + n, f.vd.begin());
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

bool RhsEvaluator::needs_rebuild() const {
  const std::size_t n = layout_.n;
  if (ref_x_.size() != n) return true;
  const double limit2 = 0.25 * skin_ * skin_;  // moved more than skin / 2
  const FluidFields& f = fields_;
  const bool two_d = layout_.dim == 2;
  double moved2 = 0.0;  // NaN positions compare false: caught by the state checks, not here
#pragma omp parallel for schedule(static) reduction(max : moved2) if (n > kCheapLoopParallelMin)
  for (std::size_t a = 0; a < n; ++a) {
    const double dx = f.x[a] - ref_x_[a], dy = two_d ? f.y[a] - ref_y_[a] : 0.0;
    moved2 = std::max(moved2, dx * dx + dy * dy);
  }
  return moved2 > limit2;
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

void RhsEvaluator::eval(double t, const double* y, double* ydot) {
  using clock = std::chrono::steady_clock;
  FluidFields& f = fields_;
  const std::size_t n = layout_.n;
  const bool two_d = layout_.dim == 2;
  ++evals_;

  auto t0 = clock::now();
  load_state(t, y);
  const bool rebuild = needs_rebuild();
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
  std::fill(f.dudt.begin(), f.dudt.end(), 0.0);
  std::fill(f.dvdt.begin(), f.dvdt.end(), 0.0);
  std::fill(f.drhodt.begin(), f.drhodt.end(), 0.0);
  std::fill(f.dedt.begin(), f.dedt.end(), 0.0);
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

  double amax2 = 0;
#pragma omp parallel for schedule(static) reduction(max : amax2) if (n > kCheapLoopParallelMin)
  for (std::size_t a = 0; a < n; ++a) {
    const double ax = f.dudt[a], ay = two_d ? f.dvdt[a] : 0.0;
    amax2 = std::max(amax2, ax * ax + ay * ay);
  }
  max_accel_ = std::sqrt(amax2);

  if (ydot) {
    for (int k = 0; k < layout_.dim; ++k) {
      std::copy(y + layout_.vel(k), y + layout_.vel(k) + n, ydot + layout_.pos(k));
    }
    std::copy(f.dudt.begin(), f.dudt.end(), ydot + layout_.vel(0));
    if (two_d) std::copy(f.dvdt.begin(), f.dvdt.end(), ydot + layout_.vel(1));
    if (layout_.has_density) std::copy(f.drhodt.begin(), f.drhodt.end(), ydot + layout_.rho());
    if (layout_.has_energy) std::copy(f.dedt.begin(), f.dedt.end(), ydot + layout_.energy());
  }
  timing_.terms += seconds_since(t0);
}

}  // namespace arksph
