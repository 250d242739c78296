// The neighbours of one particle, gathered from its Verlet candidates into a small scratch buffer
// that stays in the first-level cache: index b, r_ab, r_ab^2, W_ab and F_ab = (dW/dr)/r, in candidate
// order. The force sweep (rhs/evaluator.cpp) fills one per particle and hands it to every force
// term in turn, so each pair's kernel is evaluated once per f(t, y) and no per-pair array is stored.
// The values are those of PairList (same order, same floating-point operations), so a term gives
// bit-identical results from either.
#pragma once
#include <cstdint>
#include <vector>

#include "neighbors/cell_list.hpp"

namespace arksph {

struct alignas(64) Neighborhood {  // one per thread, on its own cache lines (no false sharing of count)
  std::size_t count = 0;
  std::vector<std::uint32_t> b;
  std::vector<double> rx, ry, r2, w, f;

  // Room for cap neighbours; only grows (no allocation once sized for the largest candidate row).
  void reserve(std::size_t cap) {
    if (b.size() >= cap) return;
    for (auto* v : {&rx, &ry, &r2, &w, &f}) v->resize(cap);
    b.resize(cap);
  }
  // body(b, rx, ry, r2, W_ab, F_ab) for every neighbour, as PairList::for_pairs.
  template <class Body>
  void for_pairs(Body&& body) const {
    const std::uint32_t* pb = b.data();
    const double *px = rx.data(), *py = ry.data(), *pr2 = r2.data(), *pw = w.data(), *pf = f.data();
    for (std::size_t k = 0; k < count; ++k) body(pb[k], px[k], py[k], pr2[k], pw[k], pf[k]);
  }
  // body(lane, b, rx, ry, r2, W_ab, F_ab), lane = Lane<k % 2> for the k-th neighbour (see SplitSum).
  template <class Body>
  void for_pairs_split(Body&& body) const {
    const std::uint32_t* pb = b.data();
    const double *px = rx.data(), *py = ry.data(), *pr2 = r2.data(), *pw = w.data(), *pf = f.data();
    visit_in_lanes(0, count, [&](auto lane, std::size_t k) { body(lane, pb[k], px[k], py[k], pr2[k], pw[k], pf[k]); });
  }
};

// The neighbours of real particle a among its candidates (x, y: all points; y null in 1D). nb must
// have room for cand.count[a] entries.
void gather_neighborhood(const CandidateList& cand, const Kernel& kernel, const double* x, const double* y,
                         std::size_t a, Neighborhood& nb);

// The largest candidate row: the room a Neighborhood needs.
std::size_t max_candidates(const CandidateList& cand);

}  // namespace arksph
