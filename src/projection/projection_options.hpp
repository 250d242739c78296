// The closed options of the projection's keys (projection/projection.cpp declares the keys, with
// these values as their choices).
#pragma once
#include "core/option.hpp"
#include "core/option_values.hpp"  // PpeOperator, ProjectionPoints (Scene members)

namespace arksph {

enum class PpeDivergence { cummins_rudman, difference };   // its source: C&R eq. 17 or Szewc et al. 2012 eq. 19
enum class PressureLevel { zero_mean, zero_min };          // the free level of P of the Neumann problem

struct ProjectionOptions {
  Option<PpeOperator> ppe_operator;            // method.ppe_operator
  Option<PpeDivergence> ppe_divergence;        // method.ppe_divergence
  Option<PressureLevel> ppe_pressure_level;    // method.ppe_pressure_level
  Option<ProjectionPoints> projection_points;  // method.projection_points
};
const ProjectionOptions& projection_options();

}  // namespace arksph
