// The closed options of the projection's keys (projection/projection.cpp declares the keys, with
// these values as their choices).
#pragma once
#include "core/option.hpp"
#include "core/option_values.hpp"  // the enumerators (Scene members)

namespace arksph {

struct ProjectionOptions {
  Option<PpeOperator> ppe_operator;            // method.ppe_operator
  Option<PpeDivergence> ppe_divergence;        // method.ppe_divergence
  Option<PressureLevel> ppe_pressure_level;    // method.ppe_pressure_level
  Option<ProjectionPoints> projection_points;  // method.projection_points
};
const ProjectionOptions& projection_options();

}  // namespace arksph
