// The steady-state criterion (diagnostics/steady_state.hpp) on hand-made sample series, against
// rates computed by hand.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

#include "diagnostics/steady_state.hpp"

using namespace arksph;

namespace {
// Rates here are ratios of short decimals: equal to the hand value up to a few rounding errors.
constexpr double kRoundOff = 1e-12;
}  // namespace

TEST_CASE("steady state: change rate between two samples is the larger of the energy and centreline rates") {
  // KE 0.0400 -> 0.0410 over dt = 0.5: |dKE| / (KE_b dt) = 0.001 / (0.041 * 0.5) = 0.0487804878...
  // centreline: largest |dc| = |0.30 - 0.32| = 0.02 over 0.5 = 0.04 (below the energy rate).
  const SteadySample a{2.0, 0.0400, {0.10, -0.20, 0.32}};
  const SteadySample b{2.5, 0.0410, {0.11, -0.20, 0.30}};
  CHECK(steady_change_rate(a, b) == doctest::Approx(0.001 / (0.041 * 0.5)).epsilon(kRoundOff));
  // A larger centreline change wins: |0.35 - 0.30| / 0.5 = 0.1.
  const SteadySample c{3.0, 0.0410, {0.11, -0.20, 0.35}};
  CHECK(steady_change_rate(b, c) == doctest::Approx(0.1).epsilon(kRoundOff));
  // No centrelines: the energy alone; the relative change uses the later energy.
  const SteadySample d{0.0, 2.0, {}}, e{0.25, 1.0, {}};
  CHECK(steady_change_rate(d, e) == doctest::Approx(1.0 / (1.0 * 0.25)).epsilon(kRoundOff));
  // A fluid at rest that stays at rest does not change; one that comes to rest from motion changes
  // infinitely fast relative to its energy; one that starts from rest changes at 1 / dt.
  CHECK(steady_change_rate({0, 0, {}}, {1, 0, {}}) == 0.0);
  CHECK(std::isinf(steady_change_rate({0, 1, {}}, {1, 0, {}})));
  CHECK(steady_change_rate({0, 0, {}}, {0.5, 3, {}}) == doctest::Approx(2.0).epsilon(kRoundOff));
  CHECK_THROWS_AS(steady_change_rate(b, a), std::invalid_argument);
  CHECK_THROWS_AS(steady_change_rate(a, {3, 1, {0.1}}), std::invalid_argument);
}

TEST_CASE("steady state, intervals: the window rate is the largest interval rate over the window, once it is covered") {
  constexpr SteadyMeasure kIntervals = SteadyMeasure::intervals;
  // KE approaches 1 as 1 - 0.5^k at t = k (k = 1, 2, ...): interval rates (KE_k - KE_{k-1}) / KE_k =
  // 0.5^k / (1 - 0.5^k): k = 2: 1/3, 3: 1/7, 4: 1/15, 5: 1/31, 6: 1/63.
  const auto ke = [](int k) { return 1 - std::pow(0.5, k); };
  SUBCASE("window 0: the latest interval only") {
    SteadyStateMonitor m(0.1, 0.0, kIntervals);
    CHECK_FALSE(m.add({1, ke(1), {}}));
    CHECK(std::isnan(m.rate()));  // one sample: no rate yet
    CHECK_FALSE(m.add({2, ke(2), {}}));
    CHECK(m.rate() == doctest::Approx(1.0 / 3).epsilon(kRoundOff));
    CHECK_FALSE(m.add({3, ke(3), {}}));
    CHECK(m.rate() == doctest::Approx(1.0 / 7).epsilon(kRoundOff));
    CHECK(m.add({4, ke(4), {}}));  // 1/15 < 0.1
    CHECK(m.rate() == doctest::Approx(1.0 / 15).epsilon(kRoundOff));
    CHECK(m.steady());
  }
  SUBCASE("window 2: the two latest intervals; steady one sample later than with window 0") {
    SteadyStateMonitor m(0.1, 2.0, kIntervals);
    m.add({1, ke(1), {}});
    CHECK_FALSE(m.add({2, ke(2), {}}));  // t - W = 0: no sample that early, the window is not covered
    CHECK(m.rate() == doctest::Approx(1.0 / 3).epsilon(kRoundOff));
    CHECK_FALSE(m.add({3, ke(3), {}}));  // intervals (1, 2), (2, 3): max(1/3, 1/7)
    CHECK(m.rate() == doctest::Approx(1.0 / 3).epsilon(kRoundOff));
    CHECK_FALSE(m.add({4, ke(4), {}}));  // (2, 3), (3, 4): max(1/7, 1/15) = 1/7 > 0.1
    CHECK(m.rate() == doctest::Approx(1.0 / 7).epsilon(kRoundOff));
    CHECK(m.add({5, ke(5), {}}));  // (3, 4), (4, 5): 1/15
    CHECK(m.rate() == doctest::Approx(1.0 / 15).epsilon(kRoundOff));
  }
  SUBCASE("a window that is not a whole number of intervals reaches back to the interval containing t - W") {
    SteadyStateMonitor m(0.1, 1.5, kIntervals);
    m.add({1, ke(1), {}});
    m.add({2, ke(2), {}});
    CHECK_FALSE(m.steady());  // t - W = 0.5: not covered
    CHECK_FALSE(m.add({3, ke(3), {}}));  // t - W = 1.5: from t = 1, max(1/3, 1/7)
    CHECK(m.rate() == doctest::Approx(1.0 / 3).epsilon(kRoundOff));
  }
  SUBCASE("an oscillation that returns to the same value over the window is not steady") {
    // KE alternates 1, 2, 1, 2 at t = 0, 1, 2, 3: the end points of a window of 2 agree, but every
    // interval changes by 1: rates 1/2 (up) and 1/1 (down).
    SteadyStateMonitor m(0.1, 2.0, kIntervals);
    m.add({0, 1, {}});
    m.add({1, 2, {}});
    CHECK_FALSE(m.add({2, 1, {}}));
    CHECK(m.rate() == doctest::Approx(1.0).epsilon(kRoundOff));
    CHECK_FALSE(m.add({3, 2, {}}));
    CHECK(m.rate() == doctest::Approx(1.0).epsilon(kRoundOff));
  }
  SUBCASE("tolerance 0: never steady, the rate is still measured") {
    SteadyStateMonitor m(0.0, 0.0, kIntervals);
    CHECK_FALSE(m.enabled());
    m.add({0, 1, {0.5}});
    CHECK_FALSE(m.add({1, 1, {0.5}}));
    CHECK(m.rate() == 0.0);
  }
}

TEST_CASE("steady state, window means: the change of the mean over the two latest windows, per unit time") {
  const auto ke = [](int k) { return 1 - std::pow(0.5, k); };
  SUBCASE("window 2 on 1 - 0.5^k: covered once a sample at or before t - 4 exists") {
    SteadyStateMonitor m(0.1, 2.0);  // window_means is the default measure
    m.add({0, ke(0), {}});
    m.add({1, ke(1), {}});
    m.add({2, ke(2), {}});
    CHECK_FALSE(m.add({3, ke(3), {}}));  // t - 2W = -1: no sample that early
    // t = 4: later window (2, 4] = {3, 4}, earlier (0, 2] = {1, 2}: means 0.90625 and 0.625, rate
    // (0.90625 - 0.625) / (0.90625 * 2) = 0.155..., above 0.1, though the window is now covered.
    CHECK_FALSE(m.add({4, ke(4), {}}));
    CHECK(m.rate() == doctest::Approx(0.28125 / (0.90625 * 2)).epsilon(kRoundOff));
    // t = 5: (3, 5] = {4, 5}: 0.953125; (1, 3] = {2, 3}: 0.8125; rate 0.140625 / (0.953125 * 2) = 0.0738 < 0.1.
    CHECK(m.add({5, ke(5), {}}));
    CHECK(m.rate() == doctest::Approx(0.140625 / (0.953125 * 2)).epsilon(kRoundOff));
  }
  SUBCASE("noise about a steady value: steady by the window means, never by the intervals") {
    // A centreline value 0.3 +- 0.05 alternating at every output (particle noise), energy constant:
    // the means of windows of 4 outputs agree exactly, every single interval changes by 0.1.
    SteadyStateMonitor means(0.01, 4.0), intervals(0.01, 4.0, SteadyMeasure::intervals);
    bool means_steady = false, intervals_steady = false;
    for (int k = 0; k <= 20; ++k) {
      const SteadySample s{double(k), 0.04, {0.3 + (k % 2 ? 0.05 : -0.05)}};
      means_steady = means.add(s) || means_steady;
      intervals_steady = intervals.add(s) || intervals_steady;
      if (k == 7) CHECK_FALSE(means.steady());  // t - 2W = -1: not covered yet
    }
    CHECK(means_steady);
    CHECK(means.rate() == doctest::Approx(0.0).epsilon(kRoundOff));
    CHECK_FALSE(intervals_steady);
    CHECK(intervals.rate() == doctest::Approx(0.1).epsilon(kRoundOff));
  }
  SUBCASE("window 0: the latest interval, as the intervals measure") {
    SteadyStateMonitor m(0.1, 0.0);
    m.add({1, ke(1), {0.2}});
    CHECK_FALSE(m.add({2, ke(2), {0.25}}));  // max(1/3, 0.05)
    CHECK(m.rate() == doctest::Approx(1.0 / 3).epsilon(kRoundOff));
    m.add({3, ke(3), {0.25}});
    CHECK(m.add({4, ke(4), {0.26}}));  // max(1/15, 0.01)
    CHECK(m.rate() == doctest::Approx(1.0 / 15).epsilon(kRoundOff));
  }
  SUBCASE("the measure's names") {
    CHECK(steady_measures().at("window_means") == SteadyMeasure::window_means);
    CHECK(steady_measures().at("intervals") == SteadyMeasure::intervals);
    CHECK(steady_measures().name(SteadyMeasure::intervals) == "intervals");
    CHECK_THROWS_AS(steady_measures().at("mean"), std::out_of_range);
  }
}
