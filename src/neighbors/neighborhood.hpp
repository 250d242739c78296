// The neighbours of one particle, gathered from its Verlet candidates into a small scratch buffer
// that stays in the first-level cache: index b, r_ab and F_ab = (dW/dr)/r in candidate order, and
// W_ab when some term reads it (with_w). The force sweep (rhs/neighbor_cache.hpp) fills one per particle
// and hands it to every force term in turn, so each pair's kernel is evaluated once per f(t, y) and
// no per-pair array is stored. r_ab^2 is recomputed on each visit (as PairList does), so the values
// are those of PairList (same order, same floating-point operations), and a term gives
// bit-identical results from either.
#pragma once
#include <cstdint>
#include <limits>
#include <vector>

#include "neighbors/cell_list.hpp"

namespace arksph {

struct alignas(64) Neighborhood {  // one per thread, on its own cache lines (no false sharing of count)
  std::size_t count = 0;
  bool with_w = true;  // W_ab gathered; otherwise w holds NaN (a term that reads it fails the tests)
  std::vector<std::uint32_t> b;
  std::vector<double> rx, ry, w, f;

  // Room for cap neighbours; only grows (no allocation once sized for the largest candidate row).
  void reserve(std::size_t cap) {
    if (b.size() >= cap) return;
    for (auto* v : {&rx, &ry, &f}) v->resize(cap);
    w.assign(cap, std::numeric_limits<double>::quiet_NaN());
    b.resize(cap);
  }
  // body(b, rx, ry, r2, W_ab, F_ab) for every neighbour, as PairList::for_pairs.
  template <class Body>
  void for_pairs(Body&& body) const {
    const std::uint32_t* pb = b.data();
    const double *px = rx.data(), *py = ry.data(), *pw = w.data(), *pf = f.data();
    for (std::size_t k = 0; k < count; ++k) body(pb[k], px[k], py[k], px[k] * px[k] + py[k] * py[k], pw[k], pf[k]);
  }
  // body(lane, b, rx, ry, r2, W_ab, F_ab), lane = Lane<k % 2> for the k-th neighbour (see SplitSum).
  // With C::plain (rhs/particle_term.hpp), pairs come two at a time: body(BothLanes, TwoIndices,
  // Two rx, ...), and a last odd one alone in lane 0.
  template <class C, class Body>
  void for_pairs_split(C, Body&& body) const {
    const std::uint32_t* pb = b.data();
    const double *px = rx.data(), *py = ry.data(), *pw = w.data(), *pf = f.data();
    auto one = [&](auto lane, std::size_t k) {
      body(lane, pb[k], px[k], py[k], px[k] * px[k] + py[k] * py[k], pw[k], pf[k]);
    };
    if constexpr (C::plain) {
      visit_two_at_a_time(0, count, [&](std::size_t k) {
        const Two x2 = load_two(px + k), y2 = load_two(py + k);
        body(BothLanes{}, TwoIndices{pb[k], pb[k + 1]}, x2, y2, x2 * x2 + y2 * y2, load_two(pw + k), load_two(pf + k));
      }, one);
    } else {
      visit_in_lanes(0, count, one);
    }
  }
};

// The neighbours of real particle a among its candidates (x, y: all points; y null in 1D). nb must
// have room for cand.count[a] entries.
void gather_neighborhood(const CandidateList& cand, const Kernel& kernel, const double* x, const double* y,
                         std::size_t a, Neighborhood& nb);

// The largest candidate row: the room a Neighborhood needs.
std::size_t max_candidates(const CandidateList& cand);

}  // namespace arksph
