// A fast direct solver for the grid Poisson equation of the GPPS (grid_poisson.hpp) when the density
// on the grid is uniform: the five-point (2D) or three-point (1D) cell-centred Laplacian with
// homogeneous Neumann walls or periodic sides is then separable,
//
//   -h^2 rho L = K_x (x) I + I (x) K_y,
//
// K the second-difference matrix of one axis, and each K is diagonalised by a fast transform
// (Schumann & Sweet 1976, "A direct method for the solution of Poisson's equation with Neumann
// boundary conditions on a staggered grid of arbitrary size", J. Comput. Phys. 20, 171-182: the
// cell-centred grid with the wall on the cell faces is their staggered one):
//
//   Neumann axis of n cells (no flux through the walls):  eigenvectors cos(pi k (i + 1/2) / n), the
//     DCT-II; eigenvalues lambda_k = 2 - 2 cos(pi k / n),  k = 0 .. n-1;
//   periodic axis of n cells:                             eigenvectors exp(2 pi i k i' / n), the
//     DFT (held as a real half-complex array); lambda_k = 2 - 2 cos(2 pi k / n).
//
// So p = -h^2 rho T^-1 [ (T s)_kl / (lambda_k + lambda_l) ] with T the 2D transform. The only zero
// eigenvalue is that of the constant (k = l = 0): its coefficient is dropped, which is the same
// null-space treatment as the KLU path's (zero-mean source, zero-mean solution), so both give the
// same discrete solution to round-off.
//
// The DCT-II of length n is computed with one real FFT of length n (Makhoul 1980, "A fast cosine
// transform in one and two dimensions", IEEE Trans. ASSP 28, 27-34: the even-indexed samples
// followed by the odd-indexed ones reversed, then a twiddle exp(-i pi k / 2n)); the FFTs are
// Eigen's (kissfft, any length). Cost O(n log n) a solve against the O(n^1.5) or more of a sparse
// triangular solve with the fill of a 2D grid.
#pragma once
#include <memory>
#include <vector>

#include "projection/grid/grid_poisson.hpp"

namespace arksph {

class GridPoissonTransform {
 public:
  explicit GridPoissonTransform(const GridSpec& grid);
  ~GridPoissonTransform();
  GridPoissonTransform(const GridPoissonTransform&) = delete;
  GridPoissonTransform& operator=(const GridPoissonTransform&) = delete;

  // Solves div((1/rho) grad p) = s for a uniform density rho: p with zero mean, the source's mean
  // ignored (the constant mode dropped). Returns the relative residual ||L p - (s - mean s)|| /
  // ||s - mean s|| (0 for a constant source).
  double solve(const std::vector<double>& source, double rho, std::vector<double>& p);

 private:
  struct Axis;
  GridSpec grid_;
  std::unique_ptr<Axis> x_, y_;  // y_ null in 1D
};

}  // namespace arksph
