// Base of the force terms that are sums over one particle's neighbours, written once as
//   template <class Neighbors> void particle(FluidFields& f, std::size_t a, const Neighbors& nb) const
// where nb.for_pairs(body) visits a's neighbours (or, with the pair configuration C below,
//   template <class C, class Neighbors> void particle(...)
// with nb.for_pairs_split(C{}, body): split sums, two pairs at a time for PlainPairs; see
// neighbors/split_sum.hpp). The term then runs either over the stored pair list (apply: one parallel
// loop of its own) or inside the force sweep (rhs/neighbor_cache.hpp) from a gathered Neighborhood
// (apply_particle), with the same arithmetic in the same order.
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
  template <class C, class Body>
  void for_pairs_split(C c, Body&& body) const {
    pairs.for_pairs_split(c, a, static_cast<Body&&>(body));
  }
};

// What a term's pair loop may take as known at compile time. PlainPairs: two dimensions, no kernel
// correction and no pressure reduction (the WCSPH default), so that the loop tests none of them per
// pair; GeneralPairs: tested per pair. Both give the same bits where both apply.
struct GeneralPairs {
  static constexpr bool plain = false;
};
struct PlainPairs {
  static constexpr bool plain = true;
};
// The plain loops where the fields allow them and f.allow_plain_pairs (tests turn it off to compare
// the plain loops with the general ones: same bits expected).
inline bool plain_pairs(const FluidFields& f) {
  return f.allow_plain_pairs && f.dim == 2 && f.correction == FluidFields::Correction::none && f.p_avg.empty();
}
template <class C>
bool two_d(const FluidFields& f) {
  return C::plain || f.dim == 2;
}

template <class Derived>
class ParticleTerm : public Term {
 public:
  Stage stage() const override { return Stage::force; }
  bool per_particle() const override { return true; }
  void apply(FluidFields& f) const override {
#pragma omp parallel for schedule(static)
    for (std::size_t a = 0; a < f.n_real; ++a) run(f, a, PairsOf{f.pairs, a});
  }
  void apply_particle(FluidFields& f, std::size_t a, const Neighborhood& nb) const override { run(f, a, nb); }

 private:
  // A term whose particle() takes the pair configuration (particle<C>) gets the plain one when the
  // fields allow it; the others run as written.
  template <class Neighbors>
  void run(FluidFields& f, std::size_t a, const Neighbors& nb) const {
    const Derived& self = static_cast<const Derived&>(*this);
    if constexpr (requires { self.template particle<PlainPairs>(f, a, nb); }) {
      if (plain_pairs(f))
        self.template particle<PlainPairs>(f, a, nb);
      else
        self.template particle<GeneralPairs>(f, a, nb);
    } else {
      self.particle(f, a, nb);
    }
  }
};

}  // namespace arksph
