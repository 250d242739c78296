#include "core/projection_method.hpp"

namespace arksph {

const Option<ProjectionMethod>& projection_methods() {
  static const Option<ProjectionMethod> o("method.projection", {
      {"cummins_rudman", ProjectionMethod::cummins_rudman},
      {"constrained", ProjectionMethod::constrained},
      {"orthogonal", ProjectionMethod::orthogonal}});
  return o;
}

}  // namespace arksph
