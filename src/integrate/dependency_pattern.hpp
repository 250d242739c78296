// The dependency graph of the implicit viscous term (see viscous_jacobian.hpp): for each of n
// particles, every particle b (itself included) whose minimum-image distance is <= radius, sorted by
// index. Found with a cell list (cell side >= radius); on a periodic axis the particles within reach
// of either end are copied one period over before binning, so a pair across the seam is found
// through the copy and then tested with the same minimum-image expression as the brute force
// (an image within the radius implies the minimum image is). O(n) instead of O(n^2) distance tests.
#pragma once
#include <cstdint>
#include <vector>

namespace arksph {

struct PeriodicAxes {
  bool periodic[2] = {false, false};
  double len[2] = {1, 1};  // period on a periodic axis
};

// y null in 1D.
std::vector<std::vector<std::uint32_t>> dependency_pattern(const double* x, const double* y, std::size_t n,
                                                           double radius, const PeriodicAxes& axes);

// The same by all-pairs distance tests (the reference for the cell-list search).
std::vector<std::vector<std::uint32_t>> dependency_pattern_brute(const double* x, const double* y, std::size_t n,
                                                                 double radius, const PeriodicAxes& axes);

// Greedy colouring of the graph `near` (symmetric, each vertex its own neighbour), vertices in
// index order, each taking the smallest colour free: at distance 1 no two neighbours share a
// colour; at distance 2 neither do two vertices with a common neighbour (the columns of a colour
// then share no row: the probes of the viscous Jacobian). Returns each vertex's colour; `colours`
// is set to their number.
std::vector<int> greedy_colouring(const std::vector<std::vector<std::uint32_t>>& near, bool distance2, int& colours);

}  // namespace arksph
