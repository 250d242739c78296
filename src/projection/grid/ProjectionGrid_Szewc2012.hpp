// The grid-projected Poisson solver (GPPS) of Szewc et al. 2012 §4.2: the source of the pressure
// Poisson equation (eq. 32), div(u*)/dt computed on the particles, is projected onto a regular
// cell-centred auxiliary grid (grid_transfer.hpp), the equation div((1/rho) grad p) = div(u*)/dt is
// solved there (grid_poisson.hpp: five-point flux form, Neumann walls or periodic sides; fast
// transforms for a uniform density, otherwise KLU factorised once and refactorised only when the
// density on the grid changes), and the acceleration (1/rho) grad p is interpolated back to the
// particles, where the velocity correction of eq. 30 uses it.
// Optional volume relaxation (method.gpps_volume_relaxation = beta > 0; not in Szewc): the grid source
// becomes div(u*)/dt - beta (phi_i - 1)/dt^2 with phi_i = sum_a w_ia V_a / h^d the particle volume
// deposited in cell i, so that over-full cells expand and empty ones fill (the particle
// clustering that the smooth grid correction does not resist otherwise).
// Under a body force g the source comes from u* - dt g (projection.cpp) and each wall face carries
// the flux (1/rho) dp/dn = g . n of the increment dt g instead (projection/body_force_split.hpp):
// the grid pressure of a tank at rest is then rho g (H - y) + const and (1/rho) grad p = g exactly.
// The density on the grid is the volume-weighted mean of the particles' phase densities, so for one
// phase it is uniform and the matrix never changes.
// On the ranks of a decomposed run each rank deposits its own particles; the cell sums of all ranks
// are combined (CellCombine) before the division, so that every rank holds the deposit of the whole
// flow, solves the same grid problem and interpolates it at its own particles. For one phase (every
// particle's rho0 the scene's density) the density deposit is not made and two arrays of cells are
// combined (the source sums and weights); with several phases three sums and two extremes.
#pragma once
#include "core/parameter.hpp"
#include <functional>
#include <vector>

#include "core/scene.hpp"
#include "projection/grid/grid_poisson.hpp"
#include "rhs/body_force_field.hpp"
#include "rhs/fluid_fields.hpp"

namespace arksph {

// The keys of the grid projection (isph-gpps), in the order of the scene file.
const std::vector<Param>& grid_projection_params();

// The auxiliary grid of a scene: cells of method.gpps_spacing (0: fluid.spacing) over the domain.
GridSpec gpps_grid(const Scene& scene);

struct GridCorrection {
  std::vector<double> ax, ay;    // (1/rho) grad p at the real particles
  std::vector<double> pressure;  // p interpolated at the real particles
  double residual = 0;           // relative residual of the grid solve
  bool refactorised = false;
};

// Combines per-cell arrays over the processes that share a grid, in place: `sums` element by
// element added, `maxima` element by element the largest. Every process must end with the same
// arrays (an all-reduce).
using CellCombine = std::function<void(std::vector<double>& sums, std::vector<double>& maxima)>;

class GridProjection {
 public:
  explicit GridProjection(const Scene& scene);
  // The correction for the particles of f (at r*), from their velocity divergence div(u*).
  GridCorrection solve(const FluidFields& f, const std::vector<double>& divergence, double dt) {
    return solve(f, f.n_real, divergence, dt, {});
  }
  // The same for the first n particles of f, the grid deposit combined with the other processes'
  // by `combine` (empty: no other process).
  GridCorrection solve(const FluidFields& f, std::size_t n, const std::vector<double>& divergence, double dt,
                       const CellCombine& combine);
  long factorisations() const { return poisson_.factorisations(); }
  const GridSpec& grid() const { return poisson_.grid(); }

 private:
  GridPoisson poisson_;
  double fallback_density_;
  double volume_relaxation_;
  BodyForceField force_;
  bool wall_flux_;  // a body force and a wall: the wall faces carry g . n
  // rhs_i -= sum over the wall faces of cell i of (g . n_out) / h, g at the face centre at time t.
  void add_wall_flux(std::vector<double>& rhs, double t) const;
};

}  // namespace arksph
