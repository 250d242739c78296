#include "integrate/viscous_split.hpp"

#include <algorithm>

namespace arksph {

ViscousSplit::ViscousSplit(const Scene& scene, RhsEvaluator& rhs) : rhs_(rhs), jac_(scene, rhs) {
  RhsOptions split = rhs_.options();
  split.imex_split = true;
  rhs_.set_options(split);
}

// True when y matches ref on every row outside the velocity block.
bool ViscousSplit::frozen_equal(const double* y, const std::vector<double>& ref) const {
  if (ref.empty()) return false;
  const StateLayout& L = rhs_.layout();
  const std::size_t v0 = L.vel(0), v1 = L.vel(0) + static_cast<std::size_t>(L.dim) * L.n;
  return std::equal(y, y + v0, ref.begin()) && std::equal(y + v1, y + L.size(), ref.begin() + static_cast<long>(v1));
}

void ViscousSplit::evaluate_at(double t, const double* y) {
  const std::size_t N = rhs_.layout().size();
  fe_.resize(N);
  rhs_.eval(t, y, fe_.data());
  if (constraint_) {
    const StateLayout& L = rhs_.layout();
    fi_.resize(N);
    rhs_.implicit_part(fi_.data());
    constraint_(y, fe_.data(), fi_.data() + L.vel(0), L.dim == 2 ? fi_.data() + L.vel(1) : nullptr);
  }
  y_.assign(y, y + N);
  t_ = t;
  valid_ = true;
}

void ViscousSplit::explicit_rhs(double t, const double* y, double* ydot) {
  if (!(valid_ && t == t_ && std::equal(y, y + y_.size(), y_.begin()))) evaluate_at(t, y);
  std::copy(fe_.begin(), fe_.end(), ydot);
}

void ViscousSplit::implicit_rhs(double t, const double* y, double* ydot) {
  const StateLayout& L = rhs_.layout();
  if (valid_ && frozen_equal(y, y_)) {  // only velocities differ: the viscous terms over the frozen fields
    const std::size_t n = L.n;
    au_.resize(n), av_.resize(n);
    const double* u = y + L.vel(0);
    const double* v = L.dim == 2 ? y + L.vel(1) : u;
    rhs_.viscous_acceleration(u, v, au_.data(), av_.data());
    std::fill(ydot, ydot + L.size(), 0.0);
    std::copy(au_.begin(), au_.end(), ydot + L.vel(0));
    if (L.dim == 2) std::copy(av_.begin(), av_.end(), ydot + L.vel(1));
    return;
  }
  evaluate_at(t, y);
  rhs_.implicit_part(ydot);
}

const SparseCsr& ViscousSplit::jacobian(double t, const double* y) {
  if (jac_last_ && frozen_equal(y, jac_y_)) return *jac_last_;  // same frozen state: same J
  if (!(valid_ && frozen_equal(y, y_))) evaluate_at(t, y);     // fields at the frozen part of y
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

}  // namespace arksph
