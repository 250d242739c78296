#include "diagnostics/steady_state.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/param_builder.hpp"

namespace arksph {

double steady_change_rate(const SteadySample& a, const SteadySample& b) {
  const double dt = b.t - a.t;
  if (!(dt > 0)) throw std::invalid_argument("steady_change_rate: samples not in time order");
  if (a.centreline.size() != b.centreline.size())
    throw std::invalid_argument("steady_change_rate: centreline samples of different lengths");
  const double dke = std::abs(b.kinetic_energy - a.kinetic_energy);
  double rate = dke == 0 ? 0.0 : b.kinetic_energy == 0 ? INFINITY : dke / (std::abs(b.kinetic_energy) * dt);
  for (std::size_t i = 0; i < a.centreline.size(); ++i)
    rate = std::max(rate, std::abs(b.centreline[i] - a.centreline[i]) / dt);
  return rate;
}

const Option<SteadyMeasure>& steady_measures() {
  static const Option<SteadyMeasure> o("time.steady_measure", {
      {"window_means", SteadyMeasure::window_means}, {"intervals", SteadyMeasure::intervals}});
  return o;
}

namespace {
// Output times are scheduled as k * output.every: allow for their round-off against t - W.
double slack(double t) { return 1e-9 * std::max(1.0, std::abs(t)); }

// The mean of the samples with lo < t_j <= hi (with round-off slack), placed at time `at`; count 0 when
// no sample falls there.
struct Mean {
  SteadySample sample;
  int count = 0;
};
Mean mean_between(const std::deque<SteadySample>& samples, double lo, double hi, double at) {
  Mean m;
  m.sample.t = at;
  for (const SteadySample& s : samples) {
    if (s.t <= lo + slack(lo) || s.t > hi + slack(hi)) continue;
    if (m.count == 0) m.sample.centreline.assign(s.centreline.size(), 0.0);
    m.sample.kinetic_energy += s.kinetic_energy;
    for (std::size_t i = 0; i < s.centreline.size() && i < m.sample.centreline.size(); ++i)
      m.sample.centreline[i] += s.centreline[i];
    ++m.count;
  }
  if (m.count > 0) {
    m.sample.kinetic_energy /= m.count;
    for (double& c : m.sample.centreline) c /= m.count;
  }
  return m;
}
}  // namespace

double SteadyStateMonitor::intervals_rate() const {
  double rate = 0;
  for (std::size_t i = 1; i < samples_.size(); ++i) rate = std::max(rate, steady_change_rate(samples_[i - 1], samples_[i]));
  return rate;
}

double SteadyStateMonitor::means_rate(double t) const {
  const Mean later = mean_between(samples_, t - window_, t, t);
  const Mean earlier = mean_between(samples_, t - 2 * window_, t - window_, t - window_);
  if (later.count == 0 || earlier.count == 0) return std::numeric_limits<double>::quiet_NaN();
  return steady_change_rate(earlier.sample, later.sample);
}

bool SteadyStateMonitor::add(SteadySample s) {
  samples_.push_back(std::move(s));
  const double t = samples_.back().t;
  const bool means = measure_ == SteadyMeasure::window_means && window_ > 0;
  // The earliest time the measure reads: t - W for the intervals, t - 2W for the window means.
  const double reach = t - (means ? 2 : 1) * window_;
  const double start = reach + slack(t);
  // Keep the latest sample at or before the reach (it shows the window is covered) and what follows.
  while (samples_.size() >= 3 && samples_[1].t <= start) samples_.pop_front();
  const bool covered = samples_.size() >= 2 && samples_.front().t <= start;
  rate_ = std::numeric_limits<double>::quiet_NaN();
  if (samples_.size() >= 2) rate_ = means ? means_rate(t) : intervals_rate();
  // isless: a quiet comparison, since the rate is NaN until both windows hold samples.
  steady_ = enabled() && covered && std::isless(rate_, tolerance_);
  return steady_;
}

const std::vector<Param>& steady_state_params() {
  static const std::vector<Param> params = {
      number("time.steady_tolerance", 0.0).in(at_least(0)).unit("1/s")
          .doc("stop before time.end once the flow is steady: at an output time, the change rate "
               "max(|dKE|/(KE dt), max |d(u/U)|/dt at Ghia's centreline points with metrics.ghia_re), measured as "
               "time.steady_measure says, is below this (0: off; needs "
               "output.every > 0)")
          .to(&Scene::steady_tolerance),
      number("time.steady_window", 0.0).in(at_least(0)).unit("s")
          .doc("simulated time of the steady-state window (time.steady_measure); the samples start anew on "
               "restart (0: the latest output interval)")
          .to(&Scene::steady_window),
      choice("time.steady_measure", "window_means").choices(steady_measures().names())
          .doc("the steady-state change rate: window_means compares the mean samples of the two latest windows of "
               "time.steady_window (robust to particle noise; the window must be 0 or at least output.every), "
               "intervals takes the largest change between consecutive output times within one window")
          .to(&Scene::steady_measure, steady_measures()),
  };
  return params;
}

}  // namespace arksph
