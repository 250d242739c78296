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

bool SteadyStateMonitor::add(SteadySample s) {
  samples_.push_back(std::move(s));
  const double t = samples_.back().t;
  // Output times are scheduled as k * output.every: allow for their round-off against t - W.
  const double start = t - window_ + 1e-9 * std::max(1.0, std::abs(t));
  // Keep the latest earlier sample at or before t - W (the window's first) and what follows it.
  while (samples_.size() >= 3 && samples_[1].t <= start) samples_.pop_front();
  const bool covered = samples_.size() >= 2 && samples_.front().t <= start;
  rate_ = std::numeric_limits<double>::quiet_NaN();
  if (samples_.size() >= 2) {
    rate_ = 0;
    for (std::size_t i = 1; i < samples_.size(); ++i)
      rate_ = std::max(rate_, steady_change_rate(samples_[i - 1], samples_[i]));
  }
  steady_ = enabled() && covered && rate_ < tolerance_;
  return steady_;
}

const std::vector<Param>& steady_state_params() {
  static const std::vector<Param> params = {
      number("time.steady_tolerance", 0.0).in(at_least(0)).unit("1/s")
          .doc("stop before time.end once the flow is steady: at an output time, the change rate "
               "max(|dKE|/(KE dt), max |d(u/U)|/dt at Ghia's centreline points with metrics.ghia_re) between "
               "consecutive output times, the largest over time.steady_window, is below this (0: off; needs "
               "output.every > 0)")
          .to(&Scene::steady_tolerance),
      number("time.steady_window", 0.0).in(at_least(0)).unit("s")
          .doc("simulated time over which the steady-state change rate must stay below time.steady_tolerance "
               "(0: the latest output interval); starts anew on restart")
          .to(&Scene::steady_window),
  };
  return params;
}

}  // namespace arksph
