// Base of the force terms that are sums over one particle's neighbours, written once as
//   template <class Neighbors> void particle(FluidFields& f, std::size_t a, const Neighbors& nb) const
// where nb.for_pairs(body) visits a's neighbours. The term then runs either over the stored pair list
// (apply: one parallel loop of its own) or inside the evaluator's force sweep from a gathered
// Neighborhood (apply_particle), with the same arithmetic in the same order.
#pragma once
#include "neighbors/neighborhood.hpp"
#include "rhs/term.hpp"

namespace arksph {

// The neighbours of a in the pair list, with the interface of Neighborhood.
struct PairsOf {
  const PairList& pairs;
  std::size_t a;
  template <class Body>
  void for_pairs(Body&& body) const {
    pairs.for_pairs(a, static_cast<Body&&>(body));
  }
  // The lanes of Neighborhood::for_pairs_split, alternating in the same pair order.
  template <class Body>
  void for_pairs_split(Body&& body) const {
    pairs.for_pairs_split(a, static_cast<Body&&>(body));
  }
};

template <class Derived>
class ParticleTerm : public Term {
 public:
  Stage stage() const override { return Stage::force; }
  bool per_particle() const override { return true; }
  void apply(FluidFields& f) const override {
    const Derived& self = static_cast<const Derived&>(*this);
#pragma omp parallel for schedule(static)
    for (std::size_t a = 0; a < f.n_real; ++a) self.particle(f, a, PairsOf{f.pairs, a});
  }
  void apply_particle(FluidFields& f, std::size_t a, const Neighborhood& nb) const override {
    static_cast<const Derived&>(*this).particle(f, a, nb);
  }
};

}  // namespace arksph
