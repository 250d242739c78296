// Histogram of the distance from each particle to its nearest real neighbour, in units of the
// initial spacing (Szewc et al. 2012 Figs. 7 and 18: clustering shows as a peak at small distances).
#pragma once
#include <vector>

#include "rhs/fluid_fields.hpp"

namespace arksph {

struct Histogram {
  double bin_width = 0;
  std::vector<long> counts;  // bin k covers [k w, (k + 1) w); the last bin also takes larger values
};

Histogram nearest_neighbor_histogram(const FluidFields& f, double dx, double bin_width = 0.025, double max_ratio = 1.5);
// The same over the real particles [0, n) of f only (their neighbours: every real point of f).
// Counts over disjoint sets of particles add up.
Histogram nearest_neighbor_histogram_of(const FluidFields& f, std::size_t n, double dx, double bin_width = 0.025,
                                        double max_ratio = 1.5);

}  // namespace arksph
