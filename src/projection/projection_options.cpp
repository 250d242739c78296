#include "projection/projection_options.hpp"

namespace arksph {

const ProjectionOptions& projection_options() {
  static const ProjectionOptions o{
      {"method.ppe_operator", {{"approximate", PpeOperator::approximate}, {"exact", PpeOperator::exact}}},
      {"method.ppe_divergence", {{"cummins_rudman", PpeDivergence::cummins_rudman}, {"difference", PpeDivergence::difference}}},
      {"method.ppe_pressure_level", {{"zero_mean", PressureLevel::zero_mean}, {"zero_min", PressureLevel::zero_min}}},
      {"method.projection_points", {{"step", ProjectionPoints::step}, {"stages", ProjectionPoints::stages}}},
  };
  return o;
}

}  // namespace arksph
