// Two-way split sums over a particle's neighbours (used by Neighborhood and PairList).
#pragma once
#include <cstddef>
#include <type_traits>

namespace arksph {

// Two-way split sums over a particle's neighbours. A sum accumulated pair after pair is one chain of
// dependent floating-point additions, and the loop runs at the adder's latency, not its throughput.
// for_pairs_split hands pair k with the tag Lane<k % 2>; a term adds into s[lane] of a SplitSum, and
// the two chains overlap. The total s[0] + s[1] depends only on the order of the pairs, which is the
// same in the pair list and in the gathered neighbourhood, so both give the same bits.
template <int L>
using Lane = std::integral_constant<int, L>;
struct SplitSum {
  double s[2] = {0.0, 0.0};
  template <int L>
  double& operator[](Lane<L>) { return s[L]; }
  double total() const { return s[0] + s[1]; }
};

// visit(Lane<(k - begin) % 2>{}, k) for k = begin .. end - 1, unrolled by two: the one place where
// the lanes are assigned for a stored row (Neighborhood, PairList).
template <class Visit>
inline void visit_in_lanes(std::size_t begin, std::size_t end, Visit&& visit) {
  std::size_t k = begin;
  for (; k + 1 < end; k += 2) {
    visit(Lane<0>{}, k);
    visit(Lane<1>{}, k + 1);
  }
  if (k < end) visit(Lane<0>{}, k);
}

}  // namespace arksph
