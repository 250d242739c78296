#include "integrate/viscous_split.hpp"

#include <algorithm>
#include <cstdint>
#include <stdexcept>

namespace arksph {

bool SplitCache::frozen_equal(const double* y, const std::vector<double>& ref) const {
  const StateLayout L = f_->layout();
  if (ref.size() != L.size()) return false;
  const std::size_t v0 = L.vel(0), v1 = L.vel(0) + static_cast<std::size_t>(L.dim) * L.n;
  return std::equal(y, y + v0, ref.begin()) && std::equal(y + v1, y + L.size(), ref.begin() + static_cast<long>(v1));
}

void SplitCache::evaluate_at(double t, const double* y) {
  const StateLayout L = f_->layout();
  const std::size_t N = L.size();
  fe_.resize(N);
  fi_.resize(N);
  f_->eval(t, y, fe_.data());
  f_->implicit_part(fi_.data());
  if (constraint_) constraint_(y, fe_.data(), fi_.data() + L.vel(0), L.dim == 2 ? fi_.data() + L.vel(1) : nullptr);
  y_.assign(y, y + N);
  t_ = t;
  builds_ = f_->builds();
  valid_ = true;
}

void SplitCache::explicit_rhs(double t, const double* y, double* ydot) {
  const std::size_t N = f_->layout().size();
  const bool same = valid_ && builds_ == f_->builds() && t == t_ && y_.size() == N && std::equal(y, y + N, y_.begin());
  if (!f_->everywhere(same)) evaluate_at(t, y);
  std::copy(fe_.begin(), fe_.end(), ydot);
}

void SplitCache::implicit_rhs(double t, const double* y, double* ydot) {
  const StateLayout L = f_->layout();
  if (cached(y)) {  // only velocities differ: the viscous terms over the frozen fields
    au_.resize(L.n);
    av_.resize(L.n);
    const double* u = y + L.vel(0);
    f_->viscous_acceleration(u, L.dim == 2 ? y + L.vel(1) : u, au_.data(), av_.data());
    std::fill(ydot, ydot + L.size(), 0.0);
    std::copy(au_.begin(), au_.end(), ydot + L.vel(0));
    if (L.dim == 2) std::copy(av_.begin(), av_.end(), ydot + L.vel(1));
    return;
  }
  evaluate_at(t, y);
  std::copy(fi_.begin(), fi_.end(), ydot);
}

namespace {
// One process's evaluator as the split's source.
class EvaluatorSource final : public SplitSource {
 public:
  explicit EvaluatorSource(RhsEvaluator& rhs) : rhs_(rhs) {}
  StateLayout layout() const override { return rhs_.layout(); }
  void eval(double t, const double* y, double* ydot) override { rhs_.eval(t, y, ydot); }
  void implicit_part(double* ydot_i) override { rhs_.implicit_part(ydot_i); }
  void viscous_acceleration(const double* u, const double* v, double* au, double* av) override {
    rhs_.viscous_acceleration(u, v, au, av);
  }
  RhsEvaluator& evaluator() override { return rhs_; }

 private:
  RhsEvaluator& rhs_;
};
}  // namespace

std::unique_ptr<SplitSource> evaluator_source(RhsEvaluator& rhs) {
  RhsOptions split = rhs.options();
  split.imex_split = true;
  rhs.set_options(split);
  return std::make_unique<EvaluatorSource>(rhs);
}

ViscousSplit::ViscousSplit(const Scene& scene, RhsEvaluator& rhs)
    : SplitCache(evaluator_source(rhs)), rhs_(rhs), jac_(scene, rhs) {}

const SparseCsr& ViscousSplit::jacobian(double t, const double* y) {
  if (jac_last_ && frozen_equal(y, jac_y_)) return *jac_last_;  // same frozen state: same J
  if (!cached(y)) evaluate_at(t, y);                             // fields at the frozen part of y
  jac_last_ = &jac_.evaluate();
  jac_y_.assign(y, y + rhs_.layout().size());
  return *jac_last_;
}

ImexFunctions ViscousSplit::functions() {
  ImexFunctions f;
  f.explicit_rhs = [this](double t, const double* y, double* yd) { explicit_rhs(t, y, yd); };
  f.implicit_rhs = [this](double t, const double* y, double* yd) { implicit_rhs(t, y, yd); };
  f.jacobian = [this](double t, const double* y) -> const SparseCsr& { return jacobian(t, y); };
  return f;
}

KrylovViscousSplit::KrylovViscousSplit(const Scene& scene, std::unique_ptr<SplitSource> source, PeriodicAxes axes)
    : SplitCache(std::move(source)), axes_(axes) {
  if (scene.dimension != 2) throw std::logic_error("KrylovViscousSplit: 2D only");
  radius_ = viscous_dependency_radius(scene, this->source().evaluator().ghost_depth());
}

// The fields at the frozen part of y, and the affine part (zero velocities at every point).
void KrylovViscousSplit::linearize(double t, const double* y) {
  if (!cached(y)) evaluate_at(t, y);
  RhsEvaluator& rhs = source().evaluator();
  const std::size_t all = rhs.layout().n;
  pu_.assign(all, 0.0);
  pv_.assign(all, 0.0);
  bu_.resize(all);
  bv_.resize(all);
  rhs.viscous_acceleration(pu_.data(), pv_.data(), bu_.data(), bv_.data());
}

void KrylovViscousSplit::times(const double* v, double* Jv) {
  const StateLayout L = source().layout();
  au_.resize(L.n);
  av_.resize(L.n);
  source().viscous_acceleration(v + L.vel(0), v + L.vel(1), au_.data(), av_.data());
  std::fill(Jv, Jv + L.size(), 0.0);
  for (std::size_t a = 0; a < L.n; ++a) {
    Jv[L.vel(0) + a] = au_[a] - bu_[a];
    Jv[L.vel(1) + a] = av_[a] - bv_[a];
  }
}

// Greedy distance-1 colouring of the evaluator's points over R_dep at the frozen positions; one
// probe per colour and velocity component.
void KrylovViscousSplit::diagonal(double* d) {
  const StateLayout L = source().layout();
  RhsEvaluator& rhs = source().evaluator();
  const FluidFields& ff = rhs.fields();
  const std::size_t all = rhs.layout().n;
  const std::vector<std::vector<std::uint32_t>> near =
      dependency_pattern(ff.x.data(), ff.y.data(), all, radius_, axes_);
  int colours = 0;
  const std::vector<int> colour = greedy_colouring(near, false, colours);
  std::fill(d, d + L.size(), 0.0);
  qu_.resize(all);
  qv_.resize(all);
  for (int k = 0; k < 2; ++k)
    for (int c = 0; c < colours; ++c) {
      pu_.assign(all, 0.0);
      pv_.assign(all, 0.0);
      std::vector<double>& probe = k == 0 ? pu_ : pv_;
      for (std::size_t j = 0; j < all; ++j)
        if (colour[j] == c) probe[j] = 1.0;
      rhs.viscous_acceleration(pu_.data(), pv_.data(), qu_.data(), qv_.data());
      const std::vector<double>& q = k == 0 ? qu_ : qv_;
      const std::vector<double>& b = k == 0 ? bu_ : bv_;
      for (std::size_t a = 0; a < L.n; ++a)
        if (colour[a] == c) d[L.vel(k) + a] = q[a] - b[a];
    }
}

ImexFunctions KrylovViscousSplit::functions() {
  ImexFunctions f;
  f.explicit_rhs = [this](double t, const double* y, double* yd) { explicit_rhs(t, y, yd); };
  f.implicit_rhs = [this](double t, const double* y, double* yd) { implicit_rhs(t, y, yd); };
  f.krylov.linearize = [this](double t, const double* y) { linearize(t, y); };
  f.krylov.times = [this](const double* v, double* Jv) { times(v, Jv); };
  f.krylov.diagonal = [this](double* d) { diagonal(d); };
  return f;
}

}  // namespace arksph
