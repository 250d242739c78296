// The ghost points of the right-hand side (boundary/ghosts.hpp) as the terms see them in
// FluidFields: appended after the real particles [n_real, n_all) with their positions, masses,
// sources and reflection signs; velocities from their sources' by the affine maps of the ghost set,
// then the wall-velocity rule of the scene (boundary.wall_velocity, 2D: linear or quadratic
// extrapolation, Basa et al. 2008 §6.1.2); density and pressure copied from their sources.
//
// Under a body force each wall point also gets its hydrostatic pressure step (FluidFields::ghost_dp).
// WCSPH adds it to the copied pressure (copy_pressure): a mirror image carrying its source's
// pressure makes dp/dn = 0 at the wall, and under gravity the fluid next to a floor then lacks the
// support rho g of the hydrostatic gradient. The projection schemes read it as the Neumann data of
// their pressure equation. Scenes without body force are left exactly as they were.
#pragma once
#include <memory>
#include <vector>

#include "boundary/wall_velocity_rules.hpp"
#include "boundary/ghosts.hpp"
#include "core/scene.hpp"
#include "rhs/body_force_field.hpp"
#include "rhs/fluid_fields.hpp"
#include "rhs/term.hpp"

namespace arksph {

class GhostField {
 public:
  // Layers as deep as the terms need (ghost_depth): the support radius, or twice that when a term
  // needs the velocity gradient at the ghosts.
  GhostField(const Scene& scene, double support_radius, const std::vector<std::unique_ptr<Term>>& terms);
  double depth() const { return depth_; }

  // Appends the ghosts of the f.n_real real particles, whose positions and velocities are loaded, to
  // f and sets f.n_all. With `rebuild`, a new ghost set reaching `skin` further than the layer depth
  // (so that it stays valid while the particles move less than that), with masses (of the real
  // particles: `mass`), sources and reflection signs; otherwise the same images moved with their
  // sources. Velocities as set_velocities; rho and p sized to n_all, ghost values left to copy().
  void refresh(FluidFields& f, const std::vector<double>& mass, bool rebuild, double skin);
  // The ghosts' velocities (momentum and divergence copies) from the real particles' in f.
  void set_velocities(FluidFields& f) const;
  // With `on`, the wall images of the momentum and divergence velocities take the body force's
  // increment since t0 unreflected: u' = M(u - d) + d with d = (t - t0) g(r_src), M the image's map.
  // The stages of a projection step carry d = (t - t0) g, which the projection removes at the end
  // of the step; a mirror image u' = 2w - u would read it as slip at the wall (and the viscous term
  // would brake it there), whereas u* of a pressure-correction step is w + dt grad(p)/rho at the
  // wall (Kim & Moin 1985 §2), i.e. w + d where the pressure balances g. No effect without body force.
  void set_slip_origin(bool on, double t0) {
    slip_on_ = on && !force_.zero();
    slip_t0_ = t0;
  }
  // f.ghost_dp at f.t (cleared without body force).
  void set_hydrostatic_steps(FluidFields& f) const;
  // field[ghost] = field[its source] for a field of all points (sized to n_all).
  void copy(std::vector<double>& field) const;
  // f.p[ghost] = f.p[source], plus rho_ghost ghost_dp under WCSPH with a body force (f.rho's ghosts
  // copied first).
  void copy_pressure(FluidFields& f) const;

 private:
  double depth_;
  GhostBuilder builder_;
  GhostSet set_;
  std::size_t n_real_ = 0, n_all_ = 0;  // of the last refresh
  std::unique_ptr<WallVelocityRule> wall_rule_;
  BodyForceField force_;
  bool hydrostatic_pressure_;  // WCSPH: ghost pressures take the hydrostatic step
  bool slip_on_ = false;       // set_slip_origin
  double slip_t0_ = 0;  // the scene's boundary.wall_velocity rule (none for "mirror")
};

}  // namespace arksph
