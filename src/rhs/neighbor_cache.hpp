// The neighbours of the right-hand side. A Verlet list (candidates within R + skin of each real
// particle among all points) is kept while no particle has moved more than half the skin since it
// was built; from it, at each evaluation, the neighbours reach the terms in one of three forms:
//   pair list, kernel values stored per pair   for readers that walk it several times
//                                              (method.neighbor_storage = "pairs");
//   lean pair list, kernel evaluated per visit for a single walk, or always with
//     (same values)                            method.neighbor_storage = "candidates";
//   force sweep                                per-particle terms (method.force_sweep): each
//                                              particle's neighbourhood gathered from its candidates
//                                              into a per-thread buffer, nothing stored per pair.
#pragma once
#include <algorithm>
#include <cstddef>
#include <type_traits>
#include <vector>

#include <omp.h>

#include "core/option.hpp"
#include "core/scene.hpp"
#include "neighbors/cell_list.hpp"
#include "neighbors/neighborhood.hpp"
#include "rhs/fluid_fields.hpp"

namespace arksph {

// method.neighbor_storage: the kernel values stored per pair, or only the candidates (the key is
// declared in io/scene_keys.cpp with these values as its choices).
const Option<NeighborStorage>& neighbor_storages();

// Who reads f.pairs after a neighbour refresh: nobody, one walk, or several walks.
enum class PairUse { none, once, repeated };

class NeighborCache {
 public:
  NeighborCache(const Scene& scene, double support_radius);
  double skin() const { return skin_; }
  // Whether per-particle terms run in the force sweep rather than over the pair list.
  bool sweeps() const { return sweep_; }

  // Real positions at the last rebuild (null before the first, or after invalidate()): the caller
  // measures the displacements since then while it loads the state.
  const double* reference_x(std::size_t n_real) const { return ref_x_.size() == n_real ? ref_x_.data() : nullptr; }
  const double* reference_y() const { return ref_y_.data(); }
  // Whether a largest squared displacement since the last rebuild calls for a new list (more than
  // half the skin).
  bool stale(double moved2) const { return moved2 > 0.25 * skin_ * skin_; }
  // A new list for the real particles of f among all its points (ghosts appended).
  void rebuild(const FluidFields& f);
  // f.pairs for `use` (stored, lean, or marked stale for none) from the current list.
  void provide_pairs(FluidFields& f, PairUse use) const;
  // body(a, nb) for the first `count` real particles a of f (all: count >= f.n_real) with their
  // gathered neighbourhoods nb, in parallel (each a on one thread; its sums do not depend on which).
  // W_ab is gathered only `with_w`.
  template <class Body>
  void sweep(const FluidFields& f, bool with_w, Body&& body, std::size_t count);

  // The next rebuild check finds the list stale (a restart from a checkpoint: same pair order).
  void invalidate() { ref_x_.clear(); }
  // Frees the list (the particles are re-ordered) and invalidates it.
  void release() {
    candidates_ = CandidateList{};
    invalidate();
  }
  long rebuilds() const { return rebuilds_; }

 private:
  double skin_;
  bool lean_;   // method.neighbor_storage = "candidates": no per-pair kernel values stored
  bool sweep_;  // method.force_sweep
  CandidateList candidates_;
  std::vector<double> ref_x_, ref_y_;  // real positions at the last rebuild
  long rebuilds_ = 0;
  std::size_t sweep_room_ = 0;         // the largest candidate row since the last rebuild
  std::vector<Neighborhood> scratch_;  // force sweep: one neighbourhood buffer per thread
};

template <class Body>
void NeighborCache::sweep(const FluidFields& f, bool with_w, Body&& body, std::size_t count) {
  const double* x = f.x.data();
  const double* y = f.dim == 2 ? f.y.data() : nullptr;
  const std::size_t n = std::min(f.n_real, count);
  const std::size_t threads = static_cast<std::size_t>(omp_get_max_threads());
  if (scratch_.size() < threads) scratch_.resize(threads);
  for (Neighborhood& nb : scratch_) {
    nb.reserve(sweep_room_);
    nb.with_w = with_w;
  }
#pragma omp parallel
  {
    Neighborhood& nb = scratch_[static_cast<std::size_t>(omp_get_thread_num())];
    std::remove_reference_t<Body> each = body;  // a copy per thread: its captures stay in registers
    // Dynamic chunks balance the threads; each particle's sums are the same whatever thread runs it.
#pragma omp for schedule(dynamic, 64)
    for (std::size_t a = 0; a < n; ++a) {
      gather_neighborhood(candidates_, *f.kernel, x, y, a, nb);
      each(a, nb);
    }
  }
}

}  // namespace arksph
