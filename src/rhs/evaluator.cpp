#include "rhs/evaluator.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "core/particle_order.hpp"
#include "core/resize_with_headroom.hpp"
#include "core/scheme.hpp"
#include "core/seconds_since.hpp"
#include "rhs/term_registry.hpp"

namespace arksph {

namespace {
// Loops of a few operations per particle run on one thread below this size: waking the other
// threads (futex, with passive waiting) costs more than the loop itself.
constexpr std::size_t kCheapLoopParallelMin = 20000;
// The passes that load the state and store the derivatives: about ten arrays each, in parallel
// from this size on (BM_RhsEval, N = 2,500, 2 threads: faster than with these passes serial).
constexpr std::size_t kLoadParallelMin = 2000;
}  // namespace

RhsEvaluator::RhsEvaluator(const Scene& scene, const ParticleSet& particles, Kernel kernel,
                           std::vector<std::unique_ptr<Term>> terms, RhsOptions options)
    : particles_(particles),
      kernel_(std::move(kernel)),
      terms_(std::move(terms)),
      ghosts_(scene, kernel_.radius(), terms_),
      neighbors_(scene, kernel_.radius()) {
  for (int k = 0; k < scene.dimension; ++k) {
    periodic_[k] = scene.sides[2 * k].kind == SideKind::periodic && !scene.sides[2 * k].halo;
    lo_[k] = scene.min[k];
    len_[k] = scene.max[k] - scene.min[k];
  }
  layout_.n = particles.n;
  layout_.dim = particles.dim;
  // State blocks beyond positions and velocities: those the scene's parts add under WCSPH.
  const bool wcsph = scheme_traits(scene.scheme).weakly_compressible;
  layout_.has_density = wcsph && density_modes().at(scene.density_mode).traits.adds_state("density");
  layout_.has_energy = wcsph && equations_of_state().at(scene.equation_of_state).traits.adds_state("energy");
  std::stable_sort(terms_.begin(), terms_.end(),
                   [](const auto& a, const auto& b) { return a->stage() < b->stage(); });
  for (const auto& t : terms_) {
    implicit_.push_back(t->can_be_implicit());
    moves_particles_ = moves_particles_ || t->moves_particles();
  }
  // The projection walks the pairs of its field refresh (at r*) several times (divergence,
  // assembly, gradient): stored, not lean. Its force terms' f(t, y) is at other positions, so they
  // run in the sweep like WCSPH's.
  pairs_for_refresh_ = scheme_traits(scene.scheme).projection ? PairUse::repeated : PairUse::once;
  fields_.dim = particles.dim;
  fields_.n_real = particles.n;
  fields_.kernel = &kernel_;
  fields_.nu = scene.viscosity;
  fields_.rho0 = particles.rho0;
  set_options(options);
}

void RhsEvaluator::set_options(const RhsOptions& options) {
  options_ = options;
  // Force terms of one partition that one pair loop can serve (Term::take_over): the one taken over
  // runs no more. Without the IMEX split every term is of the one partition.
  taken_.assign(terms_.size(), 0);
  for (auto& t : terms_) t->give_back();
  for (std::size_t i = 0; i < terms_.size(); ++i)
    for (std::size_t j = 0; j < terms_.size(); ++j) {
      const bool pairable = i != j && !taken_[i] && !taken_[j] && terms_[i]->stage() == Term::Stage::force &&
                            terms_[j]->stage() == Term::Stage::force && terms_[i]->per_particle() &&
                            terms_[j]->per_particle() && (!options_.imex_split || implicit_[i] == implicit_[j]);
      if (pairable && terms_[i]->take_over(*terms_[j])) taken_[j] = 1;
    }
  fields_.allow_plain_pairs = options.plain_pair_loops;
  // The pair list is built at every f when some term walks it: a term outside the sweep, or with
  // the IMEX split an implicit term (it runs over the pairs, and the Jacobian's probes walk them
  // many times).
  pairs_for_terms_ = options_.pairs_at_every_f ? PairUse::repeated : PairUse::none;
  for (std::size_t k = 0; k < terms_.size(); ++k) {
    const Term& t = *terms_[k];
    const bool outside_sweep = !neighbors_.sweeps() || !t.per_particle() || (options_.imex_split && implicit_[k]);
    if (t.uses_neighbors() && outside_sweep) pairs_for_terms_ = PairUse::repeated;
  }
}

double RhsEvaluator::max_step() const {
  double dt = std::numeric_limits<double>::infinity();
  for (const auto& t : terms_) dt = std::min(dt, t->max_step());
  return dt;
}

std::vector<std::string> RhsEvaluator::term_names() const {
  std::vector<std::string> names;
  for (const auto& t : terms_) names.push_back(t->name());
  return names;
}

void RhsEvaluator::permute_particles(const std::vector<std::uint32_t>& from) {
  // The neighbour lists are rebuilt at the next eval anyway: free them first, so that the
  // permutation's temporaries do not add to them at the run's peak of memory.
  neighbors_.release();
  fields_.pairs = PairList{};
  permute(particles_, from);
  permute(fields_.rho0, from);
  permute(implicit_u_, from);  // IMEX f_I of the last eval, in the new order
  permute(implicit_v_, from);
}

void RhsEvaluator::initial_state(double* y) const {
  const std::size_t n = layout_.n;
  for (int k = 0; k < layout_.dim; ++k) {
    std::copy(particles_.init_pos[k].begin(), particles_.init_pos[k].end(), y + layout_.pos(k));
    std::copy(particles_.init_vel[k].begin(), particles_.init_vel[k].end(), y + layout_.vel(k));
  }
  if (layout_.has_density) {
    const std::vector<double>& rho = particles_.init_rho.empty() ? particles_.rho0 : particles_.init_rho;
    std::copy(rho.begin(), rho.begin() + static_cast<long>(n), y + layout_.rho());
  }
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
  for (auto* v : {&f.x, &f.u, &f.ud, &f.rho, &f.p}) resize_with_headroom(*v, n);
  if (two_d)
    for (auto* v : {&f.y, &f.v, &f.vd}) resize_with_headroom(*v, n);
  // The derivatives of the real particles only: sized at the first evaluation (an evaluator that
  // is never evaluated holds nothing per particle but its copy of the particle set).
  for (auto* v : {&f.dudt, &f.dvdt, &f.drhodt}) v->resize(n);
  if (layout_.has_energy) f.dedt.resize(n);
  if (layout_.has_energy) f.e.assign(y + layout_.energy(), y + layout_.energy() + n);
  const double* yx = y + layout_.pos(0);
  const double* yy = two_d ? y + layout_.pos(1) : nullptr;
  const double* yu = y + layout_.vel(0);
  const double* yv = two_d ? y + layout_.vel(1) : nullptr;
  const double* yrho = layout_.has_density ? y + layout_.rho() : particles_.rho0.data();  // else: summation
  const bool wrap_x = periodic_[0], wrap_y = two_d && periodic_[1];
  const double lo_x = lo_[0], len_x = len_[0], lo_y = lo_[1], len_y = len_[1];
  const double* rx = neighbors_.reference_x(n);
  const double* ry = neighbors_.reference_y();
  const bool have_ref = rx != nullptr;
  double *x = f.x.data(), *u = f.u.data(), *ud = f.ud.data(), *rho = f.rho.data(), *p = f.p.data();
  double *py = two_d ? f.y.data() : nullptr, *v = two_d ? f.v.data() : nullptr, *vd = two_d ? f.vd.data() : nullptr;
  double *dudt = f.dudt.data(), *dvdt = f.dvdt.data(), *drhodt = f.drhodt.data();
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
  if (moves_particles_) {
    f.shift_u.assign(n, 0.0);
    f.shift_v.assign(two_d ? n : 0, 0.0);
  }
  return have_ref ? moved2 : std::numeric_limits<double>::infinity();
}

// The implicit partition alone into (au, av), each term over the stored pairs at the fields as they
// are; dudt, dvdt are left as they were.
void RhsEvaluator::implicit_acceleration(std::vector<double>& au, std::vector<double>& av) {
  with_implicit_terms(false, [&](const FluidFields& f) {
    au.assign(f.dudt.begin(), f.dudt.end());
    av.assign(f.dvdt.begin(), f.dvdt.end());
  });
}

// The implicit partition's acceleration alone in f.dudt, f.dvdt while `use` reads it, those of the
// evaluation restored afterwards. `taken_too`: also the terms another term runs in its own loop.
template <class Use>
void RhsEvaluator::with_implicit_terms(bool taken_too, Use&& use) {
  FluidFields& f = fields_;
  keep_du_.assign(f.dudt.begin(), f.dudt.end());
  keep_dv_.assign(f.dvdt.begin(), f.dvdt.end());
  std::fill(f.dudt.begin(), f.dudt.end(), 0.0);
  std::fill(f.dvdt.begin(), f.dvdt.end(), 0.0);
  for (std::size_t k = 0; k < terms_.size(); ++k)
    if (implicit_[k] && (taken_too || !taken_[k])) terms_[k]->apply(f);
  use(static_cast<const FluidFields&>(f));
  f.dudt.swap(keep_du_);
  f.dvdt.swap(keep_dv_);
}

void RhsEvaluator::implicit_part(double* ydot_i) const {
  std::fill(ydot_i, ydot_i + layout_.size(), 0.0);
  std::copy(implicit_u_.begin(), implicit_u_.end(), ydot_i + layout_.vel(0));
  if (layout_.dim == 2) std::copy(implicit_v_.begin(), implicit_v_.end(), ydot_i + layout_.vel(1));
}

void RhsEvaluator::viscous_acceleration(const double* u, const double* v, double* au, double* av) {
  FluidFields& f = fields_;
  const std::size_t n = layout_.n;
  const bool two_d = layout_.dim == 2;
  keep_u_.assign(f.u.begin(), f.u.end());
  keep_v_.assign(f.v.begin(), f.v.end());
  std::copy(u, u + n, f.u.begin());
  if (two_d) std::copy(v, v + n, f.v.begin());
  keep_ud_.assign(f.ud.begin(), f.ud.end());  // set_velocities also writes the divergence copies
  keep_vd_.assign(f.vd.begin(), f.vd.end());
  ghosts_.set_velocities(f);
  implicit_acceleration(probe_u_, probe_v_);
  std::copy(probe_u_.begin(), probe_u_.end(), au);
  if (two_d) std::copy(probe_v_.begin(), probe_v_.end(), av);
  f.u.swap(keep_u_);
  f.v.swap(keep_v_);
  f.ud.swap(keep_ud_);
  f.vd.swap(keep_vd_);
}

double RhsEvaluator::viscous_power(std::size_t count) {
  const std::size_t n = std::min(count, layout_.n);
  const bool two_d = layout_.dim == 2;
  double power = 0;
  with_implicit_terms(true, [&](const FluidFields& f) {
    for (std::size_t a = 0; a < n; ++a)
      power += f.m[a] * (f.u[a] * f.dudt[a] + (two_d ? f.v[a] * f.dvdt[a] : 0.0));
  });
  return power;
}

// Terms [first, last) particle by particle, for the first `count` real particles: each particle's
// neighbourhood is gathered once (kernel values included) and handed to every term in order. Same
// sums, in the same order, as applying the terms one after another over the pair list.
void RhsEvaluator::sweep(std::size_t first, std::size_t last, std::size_t count) {
  FluidFields& f = fields_;
  bool with_w = f.correction != FluidFields::Correction::none;
  for (std::size_t k = first; k < last; ++k) with_w = with_w || (!taken_[k] && terms_[k]->reads_kernel_value());
  const std::unique_ptr<Term>* terms = terms_.data();
  const char* taken = taken_.data();
  neighbors_.sweep(
      f, with_w,
      [&f, terms, taken, first, last](std::size_t a, const Neighborhood& nb) {
        for (std::size_t k = first; k < last; ++k)
          if (!taken[k]) terms[k]->apply_particle(f, a, nb);
      },
      count);
}

// Adds the terms of `part` to the derivatives in stage order. On entering a stage the ghosts take
// their sources' new rho and p (and V = m / rho, mu = rho nu are refreshed for the force stage),
// whether or not the partition has terms there. Consecutive per-particle terms of one stage run in
// one sweep when the neighbour cache sweeps.
void RhsEvaluator::sum_stages(Partition part) {
  FluidFields& f = fields_;
  ghosts_.copy(f.rho);
  ghosts_.copy_pressure(f);
  Term::Stage done = Term::Stage::density;
  for (std::size_t k = 0; k < terms_.size();) {
    const auto& term = terms_[k];
    if (term->stage() != done) {  // entering a later stage: ghosts take their sources' new values
      if (between_phases_) between_phases_();
      ghosts_.copy(f.rho);
      ghosts_.copy_pressure(f);
      done = term->stage();
      if (done == Term::Stage::force) {
        resize_with_headroom(f.vol, f.n_all);
        resize_with_headroom(f.mu, f.n_all);
#pragma omp parallel for schedule(static) if (f.n_all > kCheapLoopParallelMin)
        for (std::size_t i = 0; i < f.n_all; ++i) {
          f.vol[i] = f.m[i] / f.rho[i];
          f.mu[i] = f.rho[i] * f.nu;
        }
      }
    }
    if (!in(part, k) || taken_[k]) {
      ++k;
      continue;
    }
    if (neighbors_.sweeps() && term->per_particle()) {  // this term and the per-particle ones after it
      std::size_t last = k + 1;
      while (last < terms_.size() && terms_[last]->per_particle() && terms_[last]->stage() == done && in(part, last))
        ++last;
      sweep(k, last, done == Term::Stage::force ? options_.derivative_count : f.n_real);
      k = last;
      continue;
    }
    term->apply(f);
    ++k;
  }
  ghosts_.copy(f.rho);
  ghosts_.copy_pressure(f);
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
  // The regularisation velocity, if any: dr/dt = u + du_s.
  const double* su = f.shift_u.empty() ? nullptr : f.shift_u.data();
  const double* sv = f.shift_v.empty() ? nullptr : f.shift_v.data();
  double amax2 = 0;
#pragma omp parallel for schedule(static) reduction(max : amax2) if (n > kLoadParallelMin)
  for (std::size_t a = 0; a < n; ++a) {
    const double ax = dudt[a], ay = two_d ? dvdt[a] : 0.0;
    amax2 = std::max(amax2, ax * ax + ay * ay);
    if (!ydot) continue;
    out_x[a] = su ? yu[a] + su[a] : yu[a];
    out_u[a] = ax;
    if (two_d) {
      out_y[a] = sv ? yv[a] + sv[a] : yv[a];
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
  ++evals_;

  auto t0 = clock::now();
  const bool rebuild = neighbors_.stale(load_state(t, y));
  ghosts_.refresh(f, particles_.mass, rebuild, neighbors_.skin());
  if (between_phases_) between_phases_();
  if (rebuild) neighbors_.rebuild(f);
  if (between_phases_) between_phases_();
  // Pairs for the terms that walk them, and for whoever reads fields() after a field refresh (ydot
  // null: diagnostics, the projection); otherwise none are stored.
  neighbors_.provide_pairs(f, ydot ? pairs_for_terms_ : std::max(pairs_for_terms_, pairs_for_refresh_));
  timing_.neighbors += seconds_since(t0);
  if (between_phases_) between_phases_();

  t0 = clock::now();
  if (options_.imex_split) {
    sum_stages(Partition::explicit_terms);
    implicit_acceleration(implicit_u_, implicit_v_);
  } else {
    sum_stages(Partition::all);
  }
  max_accel_ = store_derivatives(y, ydot);
  timing_.terms += seconds_since(t0);
}

}  // namespace arksph
