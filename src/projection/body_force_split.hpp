// The body force in the projection's pressure equation next to walls.
//
// Under a body force g the intermediate velocity u* = u^n + dt (g + ...) carries the increment dt g,
// whose divergence vanishes but whose normal flux through a resting wall does not: the pressure has
// to take it up through its wall condition, dp/dn = rho g . n (the hydrostatic p = rho g (H - y) of
// a closed tank at rest). The wall points of the particle PPE (Cummins & Rudman 1999 §2.5) carry
// their source's pressure, dp/dn = 0, and the source C&R eq. 17 leaves them out: for a uniform u* it
// is not zero but a layer of sources one kernel radius thick along each wall, the cut support's
// stand-in for the flux. In 1D (cases/hydrostatic_1d, one step) that layer makes the interior
// profile straight. But inside the layer P keeps dP/dn = 0, so the gradient of C&R eq. 11, whose
// wall points also mirror P, misses rho g there: the first rows above a floor sink and those below
// a lid are pulled down, in 2D the corners take two such layers at once, and the approximate
// projection (L != D G) does not remove what it adds: a closed tank at rest starts to circulate
// and blows up within t ~ 0.4 (H = g = 1, any solver), the grid solver (Neumann faces, no flux) and
// the constrained projection (wall images reflecting a*) alike.
//
// The split here: the source is the divergence of u* - dt g (plus dt div g for a force that varies
// in space, with g at every point's own place, ghosts included), and the flux of g goes into the
// Neumann data: each wall point's pressure is its source's plus rho g . d (FluidFields::ghost_dp,
// d the displacement across the wall), in the PPE's matrix rows (ppe_assembly.hpp: neumann_source)
// and in the velocity correction; on the grid, each wall face carries the flux g . n. For the tank
// at rest the PPE then has the exact solution P = rho g (H - y) + const on the lattice, and the
// correction gives back u = u^n up to the lattice's error in the gradient of a linear field.
// All of this concerns the components of g along axes bounded by walls, which a mean pressure
// gradient can balance; a force along a periodic axis (a channel) is left in u* as before. Nothing
// changes without a body force or without walls.
#pragma once
#include <vector>

#include "core/scene.hpp"
#include "rhs/body_force_field.hpp"
#include "rhs/fluid_fields.hpp"

namespace arksph {

class BodyForceSplit {
 public:
  explicit BodyForceSplit(const Scene& scene);
  // A body force and at least one wall: the split applies.
  bool active() const { return active_; }
  const BodyForceField& force() const { return force_; }
  // g at n points (x, y) (y null in 1D) at time t, its components along the walled axes only
  // (BodyForceField::walled_at: along a periodic axis, as in a channel, g is left to u*).
  void at(std::size_t n, const double* x, const double* y, double t, std::vector<double>& gx,
          std::vector<double>& gy) const;
  // div g at the real particles of f, difference form over real neighbours and all ghosts with g at
  // each point's own position (zeros for a force uniform in space).
  std::vector<double> divergence(const FluidFields& f) const;
  // Before the fields at r* of a projection: u <- u - dt g at the n particles (x, y) (y, v null in
  // 1D), the velocities kept; restore_velocities puts them back once the fields are refreshed.
  void remove_step(std::size_t n, const double* x, const double* y, double t, double dt, double* u, double* v);
  void restore_velocities(double* u, double* v) const;

 private:
  BodyForceField force_;
  bool active_ = false;
  std::vector<double> gx_, gy_, saved_u_, saved_v_;
};

}  // namespace arksph
