#include "integrate/viscous_jacobian.hpp"

#include <algorithm>
#include <cmath>

#include "boundary/wall_velocity_rules.hpp"
#include "integrate/dependency_pattern.hpp"

namespace arksph {

double viscous_dependency_radius(const Scene& scene, double Rs) {
  const double dx = scene.spacing;
  bool no_slip_wall = false;
  for (int s = 0; s < 2 * scene.dimension; ++s)
    no_slip_wall |= scene.sides[s].kind == SideKind::wall && scene.sides[s].slip == SlipKind::no_slip;
  const bool extrapolated = no_slip_wall && scene.dimension == 2 &&
                            wall_velocity_rules().at(scene.wall_velocity).make != nullptr;
  return extrapolated ? std::max(Rs, std::hypot(Rs + dx, std::max(Rs, 3.0 * dx))) : Rs;
}

ViscousJacobian::ViscousJacobian(const Scene& scene, RhsEvaluator& rhs) : rhs_(rhs) {
  // Rs: the support radius, or twice that for the two-pass model
  radius_ = viscous_dependency_radius(scene, rhs.ghost_depth());
  skin_ = 0.5 * scene.spacing;
  for (int k = 0; k < scene.dimension; ++k) {
    periodic_[k] = scene.sides[2 * k].kind == SideKind::periodic;
    len_[k] = scene.max[k] - scene.min[k];
  }
}

bool ViscousJacobian::pattern_stale() const {
  const FluidFields& f = rhs_.fields();
  if (ref_x_.size() != f.n_real) return true;
  const double limit2 = 0.25 * skin_ * skin_;
  for (std::size_t a = 0; a < f.n_real; ++a) {
    const double dx = f.x[a] - ref_x_[a], dy = f.dim == 2 ? f.y[a] - ref_y_[a] : 0.0;
    if (dx * dx + dy * dy > limit2) return true;
  }
  return false;
}

void ViscousJacobian::build_pattern() {
  const FluidFields& f = rhs_.fields();
  const std::size_t n = f.n_real;
  const bool two_d = f.dim == 2;
  ref_x_.assign(f.x.begin(), f.x.begin() + n);
  ref_y_.assign(two_d ? f.y.begin() : f.x.begin(), two_d ? f.y.begin() + n : f.x.begin());
  PeriodicAxes axes;
  for (int k = 0; k < 2; ++k) {
    axes.periodic[k] = periodic_[k];
    axes.len[k] = len_[k];
  }
  pat_ = dependency_pattern(f.x.data(), two_d ? f.y.data() : nullptr, n, radius_ + skin_, axes);
  // Greedy distance-2 colouring: two columns share a colour only if no row holds both.
  color_ = greedy_colouring(pat_, true, ncolors_);
  of_color_.assign(static_cast<std::size_t>(ncolors_), {});
  for (std::size_t j = 0; j < n; ++j) of_color_[static_cast<std::size_t>(color_[j])].push_back(static_cast<std::uint32_t>(j));
  slot_.assign(n * static_cast<std::size_t>(ncolors_), -1);
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t t = 0; t < pat_[a].size(); ++t)
      slot_[a * static_cast<std::size_t>(ncolors_) + static_cast<std::size_t>(color_[pat_[a][t]])] = static_cast<int>(t);
  // CSR of the whole state: velocity rows hold (component, column) for every pattern column; every
  // other row its diagonal only.
  const StateLayout& L = rhs_.layout();
  const long N = static_cast<long>(L.size());
  const int dim = L.dim;
  J_.n = N;
  J_.ptr.assign(static_cast<std::size_t>(N) + 1, 0);
  J_.idx.clear();
  for (long r = 0; r < N; ++r) {
    const auto ru = static_cast<std::size_t>(r);
    const bool vel_row = ru >= L.vel(0) && ru < L.vel(0) + static_cast<std::size_t>(dim) * n;
    if (vel_row) {
      const std::size_t a = (ru - L.vel(0)) % n;
      for (int kk = 0; kk < dim; ++kk)
        for (std::uint32_t j : pat_[a]) J_.idx.push_back(static_cast<long>(L.vel(kk) + j));
    } else {
      J_.idx.push_back(r);
    }
    J_.ptr[static_cast<std::size_t>(r) + 1] = static_cast<long>(J_.idx.size());
  }
  J_.val.assign(J_.idx.size(), 0.0);
  ++J_.pattern_version;
  ++builds_;
}

const SparseCsr& ViscousJacobian::evaluate() {
  if (pattern_stale()) build_pattern();
  const StateLayout& L = rhs_.layout();
  const std::size_t n = L.n;
  const int dim = L.dim;
  std::vector<double> u(n, 0.0), v(n, 0.0), bu(n), bv(n), au(n), av(n);
  rhs_.viscous_acceleration(u.data(), v.data(), bu.data(), bv.data());  // the affine part
  const auto nc = static_cast<std::size_t>(ncolors_);
  for (int kk = 0; kk < dim; ++kk) {
    std::vector<double>& probe = kk == 0 ? u : v;
    for (std::size_t c = 0; c < nc; ++c) {
      for (std::uint32_t j : of_color_[c]) probe[j] = 1.0;
      rhs_.viscous_acceleration(u.data(), v.data(), au.data(), av.data());
      for (std::uint32_t j : of_color_[c]) probe[j] = 0.0;
      for (std::size_t a = 0; a < n; ++a) {
        const int t = slot_[a * nc + c];
        if (t < 0) continue;
        const std::size_t width = pat_[a].size(), off = static_cast<std::size_t>(kk) * width + static_cast<std::size_t>(t);
        J_.val[static_cast<std::size_t>(J_.ptr[L.vel(0) + a]) + off] = au[a] - bu[a];
        if (dim == 2) J_.val[static_cast<std::size_t>(J_.ptr[L.vel(1) + a]) + off] = av[a] - bv[a];
      }
    }
  }
  return J_;
}

}  // namespace arksph
