// Checks the state after every step: NaN/Inf, blow-up (speed beyond time.blowup_speed, or by default
// 100 times the scene's largest speed scale) and particles escaping through a wall. Throws
// NumericalFailure naming the time, the particle id and the quantity.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "run/setup.hpp"

namespace arksph {

class StateChecker {
 public:
  StateChecker(const Scene& scene, const Model& model);
  // The same with the largest acceleration at t = 0 given (a decomposed run: from rank 0's whole
  // model) instead of read from model.rhs.
  StateChecker(const Scene& scene, const Model& model, double max_acceleration);
  void check(double t, const double* y) const;
  // The same for a state y in `layout` whose particles have the ids `ids` (one rank's particles of a
  // decomposed run).
  void check(double t, const double* y, const StateLayout& layout, const std::vector<std::int64_t>& ids) const;
  double speed_limit() const { return speed_limit_; }

 private:
  const Scene& scene_;
  const Model& model_;
  double speed_limit_, margin_;
};

// Adaptive mode: steps that t + dt can barely or no longer resolve, several in a row, mean the run
// will never reach time.end. Throws NumericalFailure when step dt at t is the tenth such in a row;
// `tiny`: the count so far.
void check_step_size(double t, double dt, double end, int& tiny);

// Names entry i of a right-hand side vector in `layout` for a failure message: "particle id 12:
// acceleration ax = nan" (ids: the particle ids in the current order of the state).
std::string describe_rhs_entry(const StateLayout& layout, const std::vector<std::int64_t>& ids, std::size_t i,
                               double value);

}  // namespace arksph
