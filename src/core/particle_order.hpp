// Particle order: permutations of the particle index, and the cell order used to re-sort particles
// at sync points of a run (method.reorder_every), so that particles close in space are close in
// memory and the neighbour loops read the fields (x, y, u, v, rho, p, m, ...) from few cache lines.
//
// A permutation `from` maps new index i to old index from[i]: after permute(v, from), v_new[i] =
// v_old[from[i]]. Every per-particle array of the run must follow the same permutation; particles
// keep their `id`, which output and tests use to follow a particle across frames.
#pragma once
#include <cstdint>
#include <vector>

#include "core/particles.hpp"

namespace arksph {

using Permutation = std::vector<std::uint32_t>;

// Row-major cell order: the cell index of each particle on a grid of side `side` anchored at
// (x0, y0) (y null in 1D: the x cell), particles sorted by it, stable within a cell (so the order
// is a deterministic function of the positions and the current order). O(n) counting sort.
Permutation cell_order(const double* x, const double* y, std::size_t n, double x0, double y0, double side);
// The row-major cell index of every particle on the same grid (the key cell_order sorts by).
std::vector<std::uint64_t> cell_keys(const double* x, const double* y, std::size_t n, double x0, double y0,
                                     double side);

// v_new[i] = v_old[from[i]] for a vector of n entries.
template <class T>
void permute(std::vector<T>& v, const Permutation& from) {
  if (v.size() != from.size()) return;  // not a per-particle array (empty, or not in use)
  std::vector<T> out(v.size());
  for (std::size_t i = 0; i < from.size(); ++i) out[i] = v[from[i]];
  v.swap(out);
}

// The same for a block of n values at p.
void permute_block(double* p, const Permutation& from);

// Every per-particle array of the set (mass, rho0, id, phase, initial positions and velocities).
void permute(ParticleSet& ps, const Permutation& from);

// Every block of a state vector y in `layout` (positions, velocities, density, energy).
void permute_state(const StateLayout& layout, double* y, const Permutation& from);

// The permutation taking the particles ordered by `current` ids to the order of `target` ids
// (target[i] = current[from[i]]); empty if `target` is not a permutation of `current`.
Permutation permutation_to(const std::vector<std::int64_t>& current, const std::vector<std::int64_t>& target);

// A pseudo-random permutation of n (Fisher-Yates with a fixed-seed 64-bit generator, the same on
// every platform): fluid.shuffle_initial_order, which emulates the memory order of a long mixed run.
Permutation shuffled_order(std::size_t n, std::uint64_t seed);

}  // namespace arksph
