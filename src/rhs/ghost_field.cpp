#include "rhs/ghost_field.hpp"
#include "rhs/pressure_gravity.hpp"

#include <cmath>

#include "core/resize_with_headroom.hpp"
#include "core/scheme.hpp"

namespace arksph {

namespace {
bool any_needs_ghost_gradients(const std::vector<std::unique_ptr<Term>>& terms) {
  for (const auto& t : terms)
    if (t->needs_ghost_velocity_gradients()) return true;
  return false;
}
}  // namespace

GhostField::GhostField(const Scene& scene, double support_radius, const std::vector<std::unique_ptr<Term>>& terms)
    : depth_(ghost_depth(support_radius, any_needs_ghost_gradients(terms))),
      builder_(scene, depth_),
      force_(momentum_body_force(scene), scene),
      hydrostatic_pressure_(scheme_traits(scene.scheme).weakly_compressible && !force_.zero()) {
  if (const auto make = wall_velocity_rules().at(scene.wall_velocity).make; make && scene.dimension == 2)
    wall_rule_ = make(scene, scene.spacing);
}

void GhostField::refresh(FluidFields& f, const std::vector<double>& mass, bool rebuild, double skin) {
  const std::size_t n = f.n_real;
  const bool two_d = f.dim == 2;
  if (rebuild) {
    builder_.build(f.x.data(), two_d ? f.y.data() : nullptr, n, set_, skin);
  } else {
    builder_.update(f.x.data(), two_d ? f.y.data() : nullptr, set_);
  }
  const std::size_t ng = set_.size();
  f.n_all = n + ng;
  n_real_ = n;
  n_all_ = f.n_all;
  // Room for the ghosts without the doubling of a growing vector (about 20 arrays of n_all).
  auto room = [&](auto& field) {
    if (field.capacity() < f.n_all) field.reserve(f.n_all + f.n_all / 64);
  };
  for (auto* field : {&f.x, &f.u, &f.ud, &f.m, &f.rho, &f.p, &f.vol, &f.mu, &f.flip_x}) room(*field);
  if (two_d)
    for (auto* field : {&f.y, &f.v, &f.vd, &f.flip_y}) room(*field);
  room(f.src);
  f.x.insert(f.x.end(), set_.x.begin(), set_.x.end());
  if (two_d) f.y.insert(f.y.end(), set_.y.begin(), set_.y.end());
  for (auto* field : {&f.u, &f.ud, &f.rho, &f.p}) resize_with_headroom(*field, f.n_all);  // ghost values: below and at each stage
  if (two_d)
    for (auto* field : {&f.v, &f.vd}) resize_with_headroom(*field, f.n_all);
  // Constant between rebuilds (the ghosts keep their sources and places): set only at a rebuild.
  if (rebuild) {
    f.m.assign(mass.begin(), mass.end());
    resize_with_headroom(f.m, f.n_all);
    for (std::size_t g = 0; g < ng; ++g) f.m[n + g] = f.m[set_.source[g]];
    resize_with_headroom(f.src, f.n_all);
    for (std::size_t a = 0; a < n; ++a) f.src[a] = static_cast<std::uint32_t>(a);
    for (std::size_t g = 0; g < ng; ++g) f.src[n + g] = set_.source[g];
    f.flip_x.assign(f.n_all, 1.0);
    f.flip_y.assign(two_d ? f.n_all : 0, 1.0);
    for (std::size_t g = 0; g < ng; ++g) {
      f.flip_x[n + g] = set_.place[g][0];
      if (two_d) f.flip_y[n + g] = set_.place[g][1];
    }
  }
  set_velocities(f);
  set_hydrostatic_steps(f);
}

void GhostField::set_hydrostatic_steps(FluidFields& f) const {
  if (force_.zero() || set_.size() == 0) {
    f.ghost_dp.clear();
    return;
  }
  const std::size_t n = f.n_real;
  const bool two_d = f.dim == 2;
  f.ghost_dp.assign(f.n_all, 0.0);
  for (std::size_t g = 0; g < set_.size(); ++g) {
    const std::size_t i = n + g, s = set_.source[g];
    const auto& pl = set_.place[g];
    // Displacement across the walls: along an axis that the position map does not just shift.
    const double dx = pl[0] != 1.0 ? f.x[i] - f.x[s] : 0.0;
    const double dy = two_d && pl[1] != 1.0 ? f.y[i] - f.y[s] : 0.0;
    if (dx == 0.0 && dy == 0.0) continue;
    double acc[2];
    force_.at(f.x[s], two_d ? f.y[s] : 0.0, f.t, acc);
    const double dp = acc[0] * dx + acc[1] * dy;
    // A force that is not finite at a source is that particle's failure, diagnosed there (its own
    // acceleration): its wall points take no step rather than pass it on to their neighbours.
    if (std::isfinite(dp)) f.ghost_dp[i] = dp;
  }
}

// Ghost velocities from their sources' (affine maps), then the wall-velocity extrapolations.
void GhostField::set_velocities(FluidFields& f) const {
  const std::size_t n = f.n_real;
  const bool two_d = f.dim == 2;
  for (std::size_t g = 0; g < set_.size(); ++g) {
    const std::size_t i = n + g, s = set_.source[g];
    const auto& mv = set_.map[g];
    const auto& md = set_.div_map[g];
    const double us = f.u[s], vs = two_d ? f.v[s] : 0.0;
    f.u[i] = mv[0] * us + mv[2];
    f.ud[i] = md[0] * us + md[2];
    if (two_d) {
      f.v[i] = mv[1] * vs + mv[3];
      f.vd[i] = md[1] * vs + md[3];
    }
  }
  if (slip_on_ && f.t != slip_t0_) {
    for (std::size_t g = 0; g < set_.size(); ++g) {
      const std::size_t i = n + g, s = set_.source[g];
      const auto& mv = set_.map[g];
      const auto& md = set_.div_map[g];
      double acc[2];
      force_.walled_at(f.x[s], two_d ? f.y[s] : 0.0, f.t, acc);
      if (!std::isfinite(acc[0]) || !std::isfinite(acc[1])) continue;  // diagnosed at the source
      const double dx = (f.t - slip_t0_) * acc[0], dy = (f.t - slip_t0_) * acc[1];
      f.u[i] += (1.0 - mv[0]) * dx;
      f.ud[i] += (1.0 - md[0]) * dx;
      if (two_d) {
        f.v[i] += (1.0 - mv[1]) * dy;
        f.vd[i] += (1.0 - md[1]) * dy;
      }
    }
  }
  if (wall_rule_) wall_rule_->apply(set_, n, f.x.data(), f.y.data(), f.u.data(), f.v.data());
}

void GhostField::copy(std::vector<double>& field) const {
  resize_with_headroom(field, n_all_);
  for (std::size_t g = 0; g < set_.size(); ++g) field[n_real_ + g] = field[set_.source[g]];
}

void GhostField::copy_pressure(FluidFields& f) const {
  copy(f.p);
  if (!hydrostatic_pressure_ || f.ghost_dp.empty()) return;
  for (std::size_t i = n_real_; i < n_all_; ++i) f.p[i] += f.rho[i] * f.ghost_dp[i];
}

}  // namespace arksph
