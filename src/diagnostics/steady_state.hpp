// Steady-state detection (time.steady_tolerance, time.steady_window): a run may stop once the flow
// has stopped changing. At every output time the run takes a sample: the kinetic energy KE and, with
// metrics.ghia_re, the centreline velocities at Ghia's points divided by the lid speed U (u on
// x = 0.5, v on y = 0.5; src/diagnostics/ghia.hpp). Between two samples a (earlier) and b the
// change rate is
//
//   r(a, b) = max( |KE_b - KE_a| / (KE_b (t_b - t_a)),  max_i |c_i,b - c_i,a| / (t_b - t_a) )
//
// (1/s: a relative rate for the energy, lid speeds per unit time for the centrelines; without
// centrelines only the energy term). r is 0 when nothing changed, also at KE = 0, and infinite when
// KE_b = 0 but KE_a is not. The window rate at sample k is the largest r over the output intervals
// from sample j to sample k, where j is the latest earlier sample with t_j <= t_k - W
// (W = time.steady_window; W = 0: the latest interval only). The flow is steady at sample k when
// such a j exists (the window is covered by samples of this run) and the window rate is below the
// tolerance.
#pragma once
#include <deque>
#include <limits>
#include <vector>

#include "core/parameter.hpp"

namespace arksph {

struct SteadySample {
  double t = 0;
  double kinetic_energy = 0;
  std::vector<double> centreline;  // velocities / U at fixed points; empty without centrelines
};

// r(a, b) above; a.t < b.t and equal centreline lengths.
double steady_change_rate(const SteadySample& a, const SteadySample& b);

class SteadyStateMonitor {
 public:
  SteadyStateMonitor(double tolerance, double window) : tolerance_(tolerance), window_(window) {}
  bool enabled() const { return tolerance_ > 0; }
  // Adds the sample of an output time (later than the previous one); returns steady().
  bool add(SteadySample s);
  // The window rate at the latest sample (NaN before the second sample).
  double rate() const { return rate_; }
  // The window is covered and its rate is below the tolerance (at the latest sample).
  bool steady() const { return steady_; }

 private:
  double tolerance_, window_;
  std::deque<SteadySample> samples_;  // from the window's first sample j to the latest
  double rate_ = std::numeric_limits<double>::quiet_NaN();
  bool steady_ = false;
};

// The [time] keys of the steady-state stop.
const std::vector<Param>& steady_state_params();

}  // namespace arksph
