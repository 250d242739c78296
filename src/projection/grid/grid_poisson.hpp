// The Poisson equation of the projection, div((1/rho) grad p) = s (Szewc et al. 2012 eq. 32), on a
// regular cell-centred auxiliary grid: the grid part of the grid-projected Poisson solver (GPPS,
// Szewc §4.2). Second-order five-point (2D) or three-point (1D) stencil in flux form,
//
//   sum_faces c_f (p_nb - p_i) / h^2 = s_i,   c_f = 2 / (rho_i + rho_nb)   (1/rho at the face),
//
// with homogeneous Neumann walls (a wall face carries no flux) and periodic sides wrapped around.
// The null space (constants) is removed as for the particle PPE: the source is shifted to zero mean,
// cell 0 is pinned (row and column, so that the matrix -h^2 L stays symmetric positive definite),
// and the solution is shifted to zero mean.
//
// The matrix depends only on the grid and the cell densities. Where the density is the same in every
// cell (one phase) the operator is separable and is solved by fast transforms
// (grid_poisson_transform.hpp: DCT-II along a walled axis, DFT along a periodic one), with the same
// discrete solution to round-off. Otherwise it is factorised once by KLU and the factorisation is
// reused for every solve until set_density sees a different density field.
#pragma once
#include <array>
#include <memory>
#include <vector>

namespace arksph {

struct GridSpec {
  int nx = 1, ny = 1;          // cells (ny = 1 in 1D)
  double x0 = 0, y0 = 0;       // lower-left corner of the grid (the domain's)
  double h = 1;                // cell size
  std::array<bool, 2> periodic{false, false};
  std::size_t cells() const { return static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny); }
  std::size_t index(int i, int j) const { return static_cast<std::size_t>(j) * nx + i; }
};

class GridPoissonTransform;

class GridPoisson {
 public:
  // automatic: the transforms for a uniform density, KLU otherwise; klu: KLU always.
  enum class Solver { automatic, klu };
  explicit GridPoisson(const GridSpec& grid, Solver solver = Solver::automatic);
  ~GridPoisson();
  GridPoisson(const GridPoisson&) = delete;
  GridPoisson& operator=(const GridPoisson&) = delete;

  const GridSpec& grid() const { return grid_; }
  // Cell densities (size cells()). Sets the solver up again (a KLU factorisation, or the transforms
  // for a uniform density) when they differ (bit for bit) from the current ones; returns true if it did.
  bool set_density(const std::vector<double>& rho);
  // The same density in every cell, without comparing a field.
  bool set_density(double rho);
  // Solves for p (size cells(), zero mean). The source is shifted to zero mean first (solvability).
  // Returns the relative residual: of the pinned system (KLU), of the equation with the zero-mean
  // source (transforms).
  double solve(const std::vector<double>& source, std::vector<double>& p);
  // (1/rho) grad p at the cell centres: the mean of the face fluxes c_f (p_nb - p_i)/h on the two
  // sides of each axis; at a wall only the interior face counts (the wall flux is the Neumann
  // condition of the solve, not a property of p near the wall).
  void acceleration(const std::vector<double>& p, std::vector<double>& ax, std::vector<double>& ay) const {
    acceleration(p, ax, ay, {0, grid_.nx - 1, 0, grid_.ny - 1});
  }
  // The same in the cells i0 <= i <= i1, j0 <= j <= j1 of box = {i0, i1, j0, j1} only (0 elsewhere).
  void acceleration(const std::vector<double>& p, std::vector<double>& ax, std::vector<double>& ay,
                    const std::array<int, 4>& box) const;
  // The discrete operator applied to p (for tests): (L p)_i.
  std::vector<double> apply(const std::vector<double>& p) const;
  // Set-ups: KLU factorisations and switches to the transforms.
  long factorisations() const { return factorisations_; }
  // Whether the current density is solved by the transforms.
  bool uses_transform() const { return uniform_; }

 private:
  // Neighbour across face k (0: -x, 1: +x, 2: -y, 3: +y), or -1 at a wall.
  long neighbour(int i, int j, int k) const;
  void factorise();

  GridSpec grid_;
  std::vector<double> rho_;
  struct Klu;
  std::unique_ptr<Klu> klu_;
  Solver solver_;
  bool uniform_ = false;
  std::unique_ptr<GridPoissonTransform> transform_;
  long factorisations_ = 0;
};

}  // namespace arksph
