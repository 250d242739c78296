// What a run that ARKODE gave up on can still say about where: the particle with the largest
// acceleration and the one with the largest speed at the last accepted state.
#pragma once
#include <string>

#include "core/particles.hpp"
#include "core/scene.hpp"
#include "rhs/evaluator.hpp"

namespace arksph {

// "; at t = T the largest acceleration is A (particle id N at (x, y)), the largest speed U
// (particle id M at (x, y))", from f(t, y) evaluated once (the implicit partition included under
// IMEX). "" if the evaluation itself fails: the caller's message stands alone then.
std::string failure_diagnosis(RhsEvaluator& rhs, const ParticleSet& particles, double t, const double* y);

// What a failed run (exit 3) adds to its message where the scene is a combination known to fail
// in violent flows: a projection scheme at a free surface (docs/methods/free-surface.md, "Not
// yet"), with the scheme that runs them. "" otherwise.
std::string known_limit(const Scene& scene);

}  // namespace arksph
