// How much memory a run will need, so that a run no machine could hold is refused as bad input
// (exit 2) before anything large is allocated, instead of failing inside an allocation
// (std::bad_alloc) after minutes of set-up. The limit: core/memory_limit.hpp.
//
// The estimate is a lower bound of the peak memory of a run, from the particle count, the
// neighbour pairs within the kernel radius and the cells of the isph-gpps grid, with per-item
// costs measured on 2D runs (peak resident memory of 10,000 and 40,000 particles, default keys):
// about 200 bytes a particle, 16 bytes a neighbour pair (stored kernel values and gradients), a
// further 40 bytes a pair for isph (PPE matrix and its factors) and 1,500 bytes a grid cell for
// isph-gpps (grid matrix and its KLU factors).
#pragma once
#include <string>

#include "core/scene.hpp"

namespace arksph {

struct MemoryEstimate {
  double bytes = 0;
  double particles = 0, pairs = 0, grid_cells = 0;
  std::string key;  // the scene key that sets the largest part ("fluid.spacing", "method.gpps_spacing")
};

MemoryEstimate estimate_run_memory(const Scene& scene);

// Throws InputError "<source>: <key>: the run needs at least X (...), more than the memory limit Y
// (...)" when the estimate exceeds the limit.
void check_run_memory(const Scene& scene);

}  // namespace arksph
