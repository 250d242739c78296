// Transfers between particles and the cell-centred auxiliary grid of the GPPS (Szewc et al. 2012
// §4.2): bilinear (cloud-in-cell) weights of a point with respect to the four nearest cell centres.
// Between a wall and the first cell centre the index is clamped (constant extrapolation); periodic
// axes wrap around.
//   to the grid:      q_i = sum_a w_ia V_a q_a / sum_a w_ia V_a   (volume-weighted, Shepard-normalised)
//   to the particles: q_a = sum_i w_ia q_i                         (bilinear interpolation)
#pragma once
#include <array>
#include <vector>

#include "projection/grid/grid_poisson.hpp"

namespace arksph {

struct CellWeights {
  std::size_t cell[4];
  double w[4];
};

// Weights of the point (x, y) (y ignored in 1D, ny = 1).
CellWeights cell_weights(const GridSpec& g, double x, double y);

struct GridDeposit {
  std::vector<double> value;   // the weighted mean per cell (fallback where no particle contributes)
  std::vector<double> weight;  // sum_a w_ia V_a per cell
};

// What a deposit is made of, per cell, before the division: sum_a w_ia V_a q_a, sum_a w_ia V_a, and
// (with extremes) the smallest and largest q of the contributing particles. The sums of disjoint
// sets of particles (the ranks of a decomposed run) combine into the sums of their union by adding
// value and weight and taking the minimum of lo and the maximum of hi.
struct DepositSums {
  std::vector<double> value, weight, lo, hi;  // lo, hi empty without extremes
};

DepositSums deposit_sums(const GridSpec& g, std::size_t n, const double* x, const double* y, const double* volume,
                         const double* q, bool extremes = true);
// value / weight per cell; with extremes, exactly lo where lo == hi; the fallback where the weight is 0.
GridDeposit finish_deposit(DepositSums&& sums, double fallback);

// Volume-weighted mean of q over the particles near each cell. A cell whose contributing particles
// all carry the same value gets exactly that value (so that a uniform density field is reproduced
// bit for bit and the grid matrix is not refactorised for rounding noise).
GridDeposit deposit(const GridSpec& g, std::size_t n, const double* x, const double* y, const double* volume,
                    const double* q, double fallback);

// The smallest box of cells {i0, i1, j0, j1} that holds every cell the weights of the n points touch
// (an axis whose points wrap around a periodic side: the whole axis); {0, -1, 0, -1} for no points.
std::array<int, 4> cell_box(const GridSpec& g, std::size_t n, const double* x, const double* y);

// Bilinear interpolation of a cell field at the particles.
std::vector<double> interpolate(const GridSpec& g, std::size_t n, const double* x, const double* y,
                                const std::vector<double>& field);
// The same for several fields, the weights computed once a particle.
std::vector<std::vector<double>> interpolate_fields(const GridSpec& g, std::size_t n, const double* x, const double* y,
                                                    const std::vector<const std::vector<double>*>& fields);

}  // namespace arksph
