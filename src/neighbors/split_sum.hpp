// Two-way split sums over a particle's neighbours (used by Neighborhood and PairList).
#pragma once
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <vector>

namespace arksph {

// Two-way split sums over a particle's neighbours. A sum accumulated pair after pair is one chain of
// dependent floating-point additions, and the loop runs at the adder's latency, not its throughput.
// for_pairs_split hands pair k with the tag Lane<k % 2>; a term adds into s[lane] of a SplitSum, and
// the two chains overlap. The total s[0] + s[1] depends only on the order of the pairs, which is the
// same in the pair list and in the gathered neighbourhood, so both give the same bits.
//
// The two lanes are those of one SSE2 vector (Two). A plain pair loop (rhs/particle_term.hpp) is
// handed pairs k and k + 1 together, tagged BothLanes, with every per-pair value as a Two and the
// neighbour indices as TwoIndices; one vector instruction then does the arithmetic of both lanes.
// The operations of each lane are those of the one-pair form, so the bits are the same. A term
// writes its pair body once, generic in the value type (double or Two), reading neighbour fields
// through at(field, b).
using Two = double __attribute__((vector_size(16)));
template <int L>
using Lane = std::integral_constant<int, L>;
struct BothLanes {};
struct TwoIndices {
  std::uint32_t b0, b1;
};

inline double at(const std::vector<double>& field, std::uint32_t b) { return field[b]; }
inline Two at(const std::vector<double>& field, TwoIndices b) { return Two{field[b.b0], field[b.b1]}; }
inline Two load_two(const double* p) {
  Two t;
  std::memcpy(&t, p, sizeof t);
  return t;
}

struct SplitSum {
  Two s{0.0, 0.0};
  template <int L>
  struct LaneRef {
    Two& s;
    void operator+=(double x) { s[L] += x; }
    void operator-=(double x) { s[L] -= x; }
  };
  template <int L>
  LaneRef<L> operator[](Lane<L>) { return {s}; }
  Two& operator[](BothLanes) { return s; }
  double total() const { return s[0] + s[1]; }
};

// Four-way split sums, for a sum with few operations per pair: pair k adds into s[k % 4], and the
// total is (s0 + s2) + (s1 + s3). Four is one AVX vector where the build has AVX (two SSE2 vectors
// otherwise); the arithmetic of each lane is that of the one-pair form, so the bits are the same.
// No function takes or returns a Four by value: without AVX that would change the calling convention
// (GCC's -Wpsabi), so values are loaded in place (load_four(p, t)).
using Four = double __attribute__((vector_size(32)));
inline void load_four(const double* p, Four& t) { std::memcpy(&t, p, sizeof t); }
struct Quad {
  Four s{0.0, 0.0, 0.0, 0.0};
  double total() const { return (s[0] + s[2]) + (s[1] + s[3]); }
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

// visit_two(k) for k = begin, begin + 2, ... while k + 1 < end (pairs k and k + 1 in lanes 0 and 1),
// then visit_one(Lane<0>{}, k) for a last odd pair: the same lanes as visit_in_lanes.
template <class VisitTwo, class VisitOne>
inline void visit_two_at_a_time(std::size_t begin, std::size_t end, VisitTwo&& visit_two, VisitOne&& visit_one) {
  std::size_t k = begin;
  for (; k + 1 < end; k += 2) visit_two(k);
  if (k < end) visit_one(Lane<0>{}, k);
}

}  // namespace arksph
