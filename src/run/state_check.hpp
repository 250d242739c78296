// Checks the state after every step: NaN/Inf, blow-up (speed beyond a bound) and particles escaping
// through a wall. Throws NumericalFailure naming the time, the particle id and the quantity.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "run/setup.hpp"

namespace arksph {

class StateChecker {
 public:
  StateChecker(const Scene& scene, const Model& model);
  void check(double t, const double* y) const;
  double speed_limit() const { return speed_limit_; }

 private:
  const Scene& scene_;
  const Model& model_;
  double speed_limit_, margin_;
};

// Names entry i of a right-hand side vector in `layout` for a failure message: "particle id 12:
// acceleration ax = nan" (ids: the particle ids in the current order of the state).
std::string describe_rhs_entry(const StateLayout& layout, const std::vector<std::int64_t>& ids, std::size_t i,
                               double value);

}  // namespace arksph
