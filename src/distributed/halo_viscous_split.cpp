#include "distributed/halo_viscous_split.hpp"

#include <algorithm>

#include "integrate/dependency_pattern.hpp"
#include "integrate/viscous_jacobian.hpp"

namespace arksph::distributed {

HaloViscousSplit::HaloViscousSplit(const Scene& scene, HaloRhs& f, const RankParticles& mine,
                                   const parallel::Communicator& comm)
    : f_(f), mine_(mine), comm_(comm) {
  f_.set_imex_split(true);
  radius_ = viscous_dependency_radius(scene, f_.evaluator().ghost_depth());
}

// True when y matches the cached state on every row outside the velocity block.
bool HaloViscousSplit::frozen_equal(const double* y) const {
  const StateLayout L = mine_.layout();
  if (y_.size() != L.size()) return false;
  const std::size_t v0 = L.vel(0), v1 = L.vel(0) + static_cast<std::size_t>(L.dim) * L.n;
  return std::equal(y, y + v0, y_.begin()) && std::equal(y + v1, y + L.size(), y_.begin() + static_cast<long>(v1));
}

bool HaloViscousSplit::cached(const double* y) const {
  return everywhere(valid_ && builds_ == f_.builds() && frozen_equal(y));
}

void HaloViscousSplit::evaluate_at(double t, const double* y) {
  const std::size_t N = mine_.layout().size();
  fe_.resize(N);
  fi_.resize(N);
  f_.eval(t, y, fe_.data());
  f_.implicit_part(fi_.data());
  if (constraint_) {
    const StateLayout L = mine_.layout();
    constraint_(y, fe_.data(), fi_.data() + L.vel(0), fi_.data() + L.vel(1));
  }
  y_.assign(y, y + N);
  t_ = t;
  builds_ = f_.builds();
  valid_ = true;
}

void HaloViscousSplit::explicit_rhs(double t, const double* y, double* ydot) {
  const std::size_t N = mine_.layout().size();
  const bool same = valid_ && builds_ == f_.builds() && t == t_ && y_.size() == N && std::equal(y, y + N, y_.begin());
  if (!everywhere(same)) evaluate_at(t, y);
  std::copy(fe_.begin(), fe_.end(), ydot);
}

void HaloViscousSplit::implicit_rhs(double t, const double* y, double* ydot) {
  const StateLayout L = mine_.layout();
  if (cached(y)) {  // only velocities differ: the viscous terms over the frozen fields
    au_.resize(L.n);
    av_.resize(L.n);
    f_.viscous_acceleration(y + L.vel(0), y + L.vel(1), au_.data(), av_.data());
    std::fill(ydot, ydot + L.size(), 0.0);
    std::copy(au_.begin(), au_.end(), ydot + L.vel(0));
    std::copy(av_.begin(), av_.end(), ydot + L.vel(1));
    return;
  }
  evaluate_at(t, y);
  std::copy(fi_.begin(), fi_.end(), ydot);
}

// The fields at the frozen part of y, and the affine part (zero velocities, halo included).
void HaloViscousSplit::linearize(double t, const double* y) {
  if (!cached(y)) evaluate_at(t, y);
  const std::size_t all = f_.evaluator().layout().n;
  pu_.assign(all, 0.0);
  pv_.assign(all, 0.0);
  bu_.resize(all);
  bv_.resize(all);
  f_.evaluator().viscous_acceleration(pu_.data(), pv_.data(), bu_.data(), bv_.data());
}

void HaloViscousSplit::times(const double* v, double* Jv) {
  const StateLayout L = mine_.layout();
  au_.resize(L.n);
  av_.resize(L.n);
  f_.viscous_acceleration(v + L.vel(0), v + L.vel(1), au_.data(), av_.data());
  std::fill(Jv, Jv + L.size(), 0.0);
  for (std::size_t a = 0; a < L.n; ++a) {
    Jv[L.vel(0) + a] = au_[a] - bu_[a];
    Jv[L.vel(1) + a] = av_[a] - bv_[a];
  }
}

// Greedy distance-1 colouring of the evaluator's particles (the rank's, then the halo copies) over
// R_dep at the frozen positions; one probe per colour and velocity component.
void HaloViscousSplit::diagonal(double* d) {
  const StateLayout L = mine_.layout();
  RhsEvaluator& rhs = f_.evaluator();
  const FluidFields& ff = rhs.fields();
  const std::size_t all = rhs.layout().n;
  const std::vector<std::vector<std::uint32_t>> near =
      dependency_pattern(ff.x.data(), ff.y.data(), all, radius_, PeriodicAxes{});
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

ImexFunctions HaloViscousSplit::functions() {
  ImexFunctions f;
  f.explicit_rhs = [this](double t, const double* y, double* yd) { explicit_rhs(t, y, yd); };
  f.implicit_rhs = [this](double t, const double* y, double* yd) { implicit_rhs(t, y, yd); };
  f.krylov.linearize = [this](double t, const double* y) { linearize(t, y); };
  f.krylov.times = [this](const double* v, double* Jv) { times(v, Jv); };
  f.krylov.diagonal = [this](double* d) { diagonal(d); };
  return f;
}

}  // namespace arksph::distributed
