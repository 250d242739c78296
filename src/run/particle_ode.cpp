#include "run/particle_ode.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <string>

#include "core/errors.hpp"
#include "integrate/viscous_split.hpp"
#include "run/particle_reorder.hpp"

namespace arksph {

namespace {
// The name of block b of the layout, for messages.
const char* block_name(const StateLayout& L, std::size_t b) {
  static const char* const two[] = {"x", "y", "u", "v"};
  static const char* const one[] = {"x", "u"};
  const std::size_t d = static_cast<std::size_t>(L.dim);
  if (b < 2 * d) return L.dim == 2 ? two[b] : one[b];
  if (L.has_density && b == 2 * d) return "rho";
  return "energy";
}
}  // namespace

ParticleOde::ParticleOde(const Scene& scene) : scene_(scene), model_(build_model(scene_)) {
  RhsEvaluator& rhs = *model_.rhs;
  const StateLayout& L = rhs.layout();
  // The set-up of `arksph run` (run/simulation.cpp): initial state, cell order at t = 0, a field
  // refresh, the constrained projection's divergence-free start.
  std::vector<double> y(L.size());
  rhs.initial_state(y.data());
  if (scene_.reorder_every > 0) {
    std::vector<double> unused;
    ParticleReorder(scene_, model_).sort(y.data(), unused);
  }
  rhs.eval(0.0, y.data(), nullptr);
  if (model_.projection) model_.projection->project_initial(0.0, y.data());

  // The outside order: increasing id.
  const std::vector<std::int64_t>& inside_ids = model_.particles.id;
  std::vector<std::uint32_t> by_id(L.n);
  std::iota(by_id.begin(), by_id.end(), 0u);
  std::sort(by_id.begin(), by_id.end(), [&](std::uint32_t a, std::uint32_t b) { return inside_ids[a] < inside_ids[b]; });
  from_.resize(L.n);
  ids_.resize(L.n);
  for (std::size_t k = 0; k < L.n; ++k) {
    from_[by_id[k]] = static_cast<std::uint32_t>(k);
    ids_[k] = inside_ids[by_id[k]];
  }
  y0_.resize(L.size());
  to_outside(y, y0_.data());
}

ParticleOde::~ParticleOde() = default;

const StateLayout& ParticleOde::layout() const { return model_.rhs->layout(); }
long ParticleOde::evaluations() const { return model_.rhs->evaluations(); }
bool ParticleOde::has_projection() const { return model_.projection != nullptr; }
bool ParticleOde::projection_is_constrained() const { return model_.projection && model_.projection->constrained(); }

// Copies y (outside order) into the inside order; a NaN or infinite entry is bad input.
void ParticleOde::to_inside(const double* y, std::vector<double>& inside) const {
  const StateLayout& L = layout();
  const std::size_t n = L.n, blocks = n ? L.size() / n : 0;
  inside.resize(L.size());
  for (std::size_t b = 0; b < blocks; ++b) {
    const double* src = y + b * n;
    double* dst = inside.data() + b * n;
    for (std::size_t i = 0; i < n; ++i) dst[i] = src[from_[i]];
  }
  for (std::size_t k = 0; k < L.size(); ++k)
    if (!std::isfinite(y[k]))
      throw InputError("y[" + std::to_string(k) + "] is " + (std::isnan(y[k]) ? "NaN" : "infinite") + " (block " +
                       block_name(L, k / n) + ", particle id " + std::to_string(ids_[k % n]) + ")");
}

void ParticleOde::to_outside(const std::vector<double>& inside, double* y) const {
  const StateLayout& L = layout();
  const std::size_t n = L.n, blocks = n ? L.size() / n : 0;
  for (std::size_t b = 0; b < blocks; ++b) {
    const double* src = inside.data() + b * n;
    double* dst = y + b * n;
    for (std::size_t i = 0; i < n; ++i) dst[from_[i]] = src[i];
  }
}

// f as the run's integrator sees it (run/time_stepper.cpp): the terms, then the constraint.
void ParticleOde::rhs(double t, const double* y, double* ydot) {
  to_inside(y, y_in_);
  f_in_.resize(y_in_.size());
  model_.rhs->eval(t, y_in_.data(), f_in_.data());
  if (projection_is_constrained()) model_.projection->constrain(y_in_.data(), f_in_.data());
  to_outside(f_in_, ydot);
}

void ParticleOde::project(double t_start, const double* y_start, double t, double* y) {
  if (!model_.projection || model_.projection->constrained())
    throw InputError("project: the scene has no projection after a step (method.scheme " + scene_.scheme +
                     ", method.projection " + projection_methods().name(scene_.projection) + "); f already holds the pressure");
  if (!(t > t_start)) throw InputError("project: t must be after t_start");
  to_inside(y_start, y_start_in_);
  to_inside(y, y_in_);
  model_.projection->begin_step(t_start, y_start_in_.data());
  model_.projection->project(t, y_in_.data());
  to_outside(y_in_, y);
}

// The split evaluates a model of its own (it switches its evaluator to the split sums), with the
// particles in the same order as the main one.
ViscousSplit& ParticleOde::split() {
  if (split_) return *split_;
  if (model_.projection && !model_.projection->constrained())
    throw InputError("the IMEX split needs a scheme without a projection after the step (wcsph, or isph with "
                     "method.projection = \"constrained\")");
  imex_model_ = std::make_unique<Model>(build_model(scene_));
  adopt_particle_order(*imex_model_, model_.particles.id);
  split_ = std::make_unique<ViscousSplit>(scene_, *imex_model_->rhs);
  if (Projection* p = imex_model_->projection.get())
    split_->set_constraint([p](const double* y, double* fe, const double* au, const double* av) {
      p->constrain(y, fe, au, av);
    });
  return *split_;
}

void ParticleOde::explicit_rhs(double t, const double* y, double* ydot) {
  ViscousSplit& s = split();
  to_inside(y, y_in_);
  f_in_.resize(y_in_.size());
  s.explicit_rhs(t, y_in_.data(), f_in_.data());
  to_outside(f_in_, ydot);
}

void ParticleOde::implicit_rhs(double t, const double* y, double* ydot) {
  ViscousSplit& s = split();
  to_inside(y, y_in_);
  f_in_.resize(y_in_.size());
  s.implicit_rhs(t, y_in_.data(), f_in_.data());
  to_outside(f_in_, ydot);
}

void ParticleOde::implicit_jvp(double t, const double* y, const double* v, double* w) {
  ViscousSplit& s = split();
  to_inside(y, y_in_);
  to_inside(v, v_in_);
  const SparseCsr& J = s.jacobian(t, y_in_.data());
  f_in_.assign(y_in_.size(), 0.0);
  for (long r = 0; r < J.n; ++r) {
    double sum = 0;
    for (long k = J.ptr[r]; k < J.ptr[r + 1]; ++k) sum += J.val[k] * v_in_[static_cast<std::size_t>(J.idx[k])];
    f_in_[static_cast<std::size_t>(r)] = sum;
  }
  to_outside(f_in_, w);
}

double ParticleOde::seconds_per_inside_rhs(double t, const double* y, int repeats) {
  to_inside(y, y_in_);
  f_in_.resize(y_in_.size());
  const auto start = std::chrono::steady_clock::now();
  for (int r = 0; r < repeats; ++r) {
    model_.rhs->eval(t, y_in_.data(), f_in_.data());
    if (projection_is_constrained()) model_.projection->constrain(y_in_.data(), f_in_.data());
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / std::max(repeats, 1);
}

double ParticleOde::stable_step(const double* y) {
  to_inside(y, y_in_);
  return arksph::stable_step(scene_, model_, max_speed(layout(), y_in_.data()), model_.rhs->max_acceleration());
}

}  // namespace arksph
