// Two-way split sums over a particle's neighbours (used by Neighborhood and PairList).
#pragma once
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

}  // namespace arksph
