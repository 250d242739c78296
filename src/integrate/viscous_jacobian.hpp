// J = d f_I / d y for the implicit viscous term (time.imex): the Jacobian of the viscous acceleration
// of every real particle with respect to every real velocity, at frozen positions, densities and
// kernel corrections. Zero outside the velocity block; each row keeps its diagonal entry, so that
// ARKODE's Newton matrix M = I - gamma J has the identity on the position, density and energy rows.
//
// Every viscous model (Basa et al. 2008 models A-E, eqs. 27-35; Szewc eq. 24), with any kernel
// correction and wall-velocity rule, is affine in the velocities once the positions are frozen, so J
// is obtained exactly (to round-off) by probing: one evaluation of the viscous terms per colour of a
// distance-2 colouring of the dependency graph (Curtis, Powell & Reid 1974), for each velocity
// component, minus the evaluation at zero velocity (wall velocities, the affine part).
//
// The dependency graph links particles closer than R_dep + skin (minimum image on periodic axes):
// R_dep = R (kernel support) for one-pass models, 2R for the two-pass model B (Basa eq. 29); with
// the linear or quadratic wall velocity a ghost's velocity comes from the fluid particles nearest to
// the wall in its bin (up to 3 dx from the wall, 1 dx along it), so R_dep = |(R_s + dx, max(R_s, 3 dx))|.
// The pattern, the colouring and J's sparsity are rebuilt only when a particle has moved more than
// skin / 2 = dx / 4 since the last build (a Verlet rule); between rebuilds the pattern, and so the
// KLU symbolic analysis, stay the same. Pattern build: a cell-list search (dependency_pattern.hpp).
#pragma once
#include <cstdint>
#include <vector>

#include "core/scene.hpp"
#include "integrate/imex_integrator.hpp"
#include "rhs/evaluator.hpp"

namespace arksph {

// R_dep above for the scene, with the viscous terms' reach `ghost_depth` (RhsEvaluator::ghost_depth).
double viscous_dependency_radius(const Scene& scene, double ghost_depth);

class ViscousJacobian {
 public:
  ViscousJacobian(const Scene& scene, RhsEvaluator& rhs);
  // J at the fields of the last rhs.eval().
  const SparseCsr& evaluate();
  int colors() const { return ncolors_; }
  long pattern_builds() const { return builds_; }
  double dependency_radius() const { return radius_; }
  // Forces a new pattern (and so a new KLU symbolic analysis) at the next evaluate(): after the
  // particles were re-ordered, when the old pattern's indices name other particles.
  void invalidate() { ref_x_.clear(); }

 private:
  bool pattern_stale() const;
  void build_pattern();
  RhsEvaluator& rhs_;
  double radius_ = 0, skin_ = 0;
  bool periodic_[2] = {false, false};
  double len_[2] = {1, 1};
  std::vector<std::vector<std::uint32_t>> pat_;  // per particle: sorted neighbours in the graph, self included
  std::vector<int> color_;
  int ncolors_ = 0;
  std::vector<std::vector<std::uint32_t>> of_color_;
  std::vector<int> slot_;  // slot_[a * ncolors_ + c]: index in pat_[a] of its column of colour c, or -1
  std::vector<double> ref_x_, ref_y_;
  long builds_ = 0;
  SparseCsr J_;
};

}  // namespace arksph
