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
// KE_b = 0 but KE_a is not. W = time.steady_window; the flow is steady at sample k once the run's
// samples reach back far enough for the measure (the window is covered) and its rate is below the
// tolerance. time.steady_measure chooses the rate at sample k (time t):
//
//   window_means: r(A, B), A and B the means of the samples in the two latest windows,
//                 B over t - W < t_j <= t and A over t - 2W < t_j <= t - W, placed at t and t - W
//                 (so the rate is the change of the mean per unit time); covered once a sample at or
//                 before t - 2W exists. Averaging over a window removes the particle noise that
//                 keeps the change between two single samples of an SPH run at a few per cent per
//                 unit time (Szewc's cavity at Re = 1000: the energy's window means settle to
//                 1e-4 per unit time, its single samples never below 1e-2). W must then be 0 or
//                 at least output.every, so that both windows hold a sample.
//   intervals:    the largest r over the output intervals from sample j to sample k, where j is the
//                 latest earlier sample with t_j <= t - W; covered once such a j exists.
//
// With W = 0 both are the rate of the latest interval.
#pragma once
#include <deque>
#include <limits>
#include <string>
#include <vector>

#include "core/option.hpp"
#include "core/option_values.hpp"  // SteadyMeasure (a Scene member)
#include "core/parameter.hpp"

namespace arksph {

struct SteadySample {
  double t = 0;
  double kinetic_energy = 0;
  std::vector<double> centreline;  // velocities / U at fixed points; empty without centrelines
};

// r(a, b) above; a.t < b.t and equal centreline lengths.
double steady_change_rate(const SteadySample& a, const SteadySample& b);

// time.steady_measure's values (the choices of the key).
const Option<SteadyMeasure>& steady_measures();

class SteadyStateMonitor {
 public:
  SteadyStateMonitor(double tolerance, double window, SteadyMeasure measure = SteadyMeasure::window_means)
      : tolerance_(tolerance), window_(window), measure_(measure) {}
  bool enabled() const { return tolerance_ > 0; }
  // Adds the sample of an output time (later than the previous one); returns steady().
  bool add(SteadySample s);
  // The window rate at the latest sample (NaN before the second sample).
  double rate() const { return rate_; }
  // The window is covered and its rate is below the tolerance (at the latest sample).
  bool steady() const { return steady_; }
  // The samples the measure still reads (a checkpoint stores them; add() them back in order on
  // restart to continue the same windows).
  const std::deque<SteadySample>& samples() const { return samples_; }

 private:
  double means_rate(double t) const;
  double intervals_rate() const;

  double tolerance_, window_;
  SteadyMeasure measure_;
  std::deque<SteadySample> samples_;  // from the latest sample at or before the measure's reach to the latest
  double rate_ = std::numeric_limits<double>::quiet_NaN();
  bool steady_ = false;
};

// The [time] keys of the steady-state stop.
const std::vector<Param>& steady_state_params();

}  // namespace arksph
