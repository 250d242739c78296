// The closed options of the projection's keys (projection/projection.cpp declares the keys, with
// these values as their choices).
#pragma once
#include "core/option.hpp"

namespace arksph {

enum class PpeOperator { approximate, exact };             // the Laplacian of the PPE: C&R eq. 19 or eq. 18
enum class PpeDivergence { cummins_rudman, difference };   // its source: C&R eq. 17 or Szewc et al. 2012 eq. 19
enum class PressureLevel { zero_mean, zero_min };          // the free level of P of the Neumann problem
enum class ProjectionPoints { step, stages };              // after each accepted step, or also after every ERK stage

struct ProjectionOptions {
  Option<PpeOperator> ppe_operator;            // method.ppe_operator
  Option<PpeDivergence> ppe_divergence;        // method.ppe_divergence
  Option<PressureLevel> ppe_pressure_level;    // method.ppe_pressure_level
  Option<ProjectionPoints> projection_points;  // method.projection_points
};
const ProjectionOptions& projection_options();

}  // namespace arksph
