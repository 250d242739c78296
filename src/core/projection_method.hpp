// The projections of isph (method.projection): after each step (Cummins & Rudman 1999), or the
// pressure inside f(t, y), on the particles (constrained) or on a coarse pressure space (orthogonal);
// docs/methods/isph.md. In core because Scene::pressure_in_f() asks it; the key is declared with the
// projection's keys (projection/projection.cpp).
#pragma once
#include "core/option.hpp"

namespace arksph {

enum class ProjectionMethod { cummins_rudman, constrained, orthogonal };

const Option<ProjectionMethod>& projection_methods();

}  // namespace arksph
