#include "rhs/neighbor_cache.hpp"

#include "kernels/kernel.hpp"

namespace arksph {

const Option<NeighborStorage>& neighbor_storages() {
  static const Option<NeighborStorage> o("method.neighbor_storage", {
      {"pairs", NeighborStorage::pairs}, {"candidates", NeighborStorage::candidates}});
  return o;
}

NeighborCache::NeighborCache(const Scene& scene, double support_radius)
    // Verlet skin: candidates within 1.15 R; rebuilt when a particle has moved more than 0.075 R.
    : skin_(0.15 * support_radius),
      lean_(scene.neighbor_storage == NeighborStorage::candidates),
      sweep_(scene.force_sweep) {}

void NeighborCache::rebuild(const FluidFields& f) {
  const std::size_t n = f.n_real;
  const double* y = f.dim == 2 ? f.y.data() : nullptr;
  {
    // Needed only during a rebuild: not kept in between (~21 bytes a point less meanwhile).
    CellList cells;
    cells.build(f.x.data(), y, f.n_all, f.kernel->radius() + skin_);
    build_candidates(cells, f.x.data(), y, n, candidates_);
  }
  ref_x_.assign(f.x.begin(), f.x.begin() + static_cast<long>(n));
  if (y) ref_y_.assign(f.y.begin(), f.y.begin() + static_cast<long>(n));
  sweep_room_ = max_candidates(candidates_);
  ++rebuilds_;
}

// The lean form for a single walk: the diagnostics walk the pairs once, and no per-pair arrays are
// ever allocated (WCSPH); stored for several walks unless the storage is lean.
void NeighborCache::provide_pairs(FluidFields& f, PairUse use) const {
  const double* y = f.dim == 2 ? f.y.data() : nullptr;
  if (use == PairUse::none)
    f.pairs.n_real = 0;  // stale: PairList::for_pairs asserts on it
  else if (lean_ || use == PairUse::once)
    lean_pairs_from_candidates(candidates_, *f.kernel, f.x.data(), y, f.pairs);
  else
    pairs_from_candidates(candidates_, *f.kernel, f.x.data(), y, f.pairs);
}

}  // namespace arksph
