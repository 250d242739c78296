// The steady-state stop (time.steady_tolerance) on a real run: a coarse cavity at Re = 100
// (tests/scenes/cavity_steady.toml, 20 x 20 particles) stops before time.end with the tolerance
// set and not without, records it in summary.json, and a restart measures a new window.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <string>

#include "io/json_reader.hpp"
#include "run_arksph.hpp"
#include "test_support.hpp"

using namespace arksph;
using arksph::testing::read_csv;
using arksph::testing::run_arksph_captured;
using arksph::testing::RunOutcome;
using arksph::testing::ScratchDir;

namespace {

const std::string kCavity = std::string(ARKSPH_SOURCE_DIR) + "/tests/scenes/cavity_steady.toml";
// The coarse cavity's change rate (KE and Ghia centrelines, between outputs 0.5 apart) falls below
// 0.05 per unit time by t ~ 5 and stays below it (0.01-0.035: particle noise); over a window of 2 the
// run is steady by t ~ 6, well before the end time 8.
const std::string kEnd = " --set time.end=8";
const std::string kSteady =
    " --set time.steady_tolerance=0.05 --set time.steady_window=2 --set time.steady_measure=intervals";

double number_at(const JsonValue& j, const std::string& key) {
  const JsonValue* v = j.find(key);
  REQUIRE(v);
  REQUIRE(v->kind == JsonValue::Kind::number);
  return v->number;
}

}  // namespace

TEST_CASE("steady state: a cavity stops at steady state before time.end with the tolerance set, not without") {
  ScratchDir dir("steady");
  const RunOutcome steady = run_arksph_captured("run " + kCavity + " --quiet --out " + (dir / "steady") + kEnd + kSteady,
                                                dir.dir.string());
  CAPTURE(steady.err);
  REQUIRE(steady.code == 0);
  CHECK(steady.out.find("stops at steady state") != std::string::npos);  // the header states the criterion
  CHECK(steady.out.find("arksph: steady state at t = ") != std::string::npos);

  const JsonValue s = read_json_file(dir / "steady/summary.json");
  CHECK(s.find("status")->text == "ok");
  const double t_stop = number_at(s, "final_time");
  CHECK(t_stop < 8.0);
  CHECK(t_stop >= 2.0);  // the window of 2 must be covered by samples first
  const JsonValue* ss = s.find("steady_state");
  REQUIRE(ss);
  CHECK(ss->find("reached")->kind == JsonValue::Kind::boolean);
  CHECK(ss->find("reached")->boolean);
  CHECK(number_at(*ss, "time") == t_stop);
  CHECK(number_at(*ss, "rate") < 0.05);
  CHECK(number_at(*ss, "tolerance") == 0.05);
  CHECK(number_at(*ss, "window") == 2.0);
  CHECK(ss->find("measure")->text == "intervals");
  CHECK(s.find("metrics")->find("ghia_u_linf"));  // the existing keys stay
  CHECK(std::filesystem::exists(dir / "steady/checkpoint.h5"));
  // The last timeseries.csv row is the stop, with the rate of summary.json; the rows before it
  // within the window were not all below the tolerance, or the run would have stopped earlier.
  const auto rows = read_csv(dir / "steady/timeseries.csv");
  REQUIRE(rows.size() >= 3);
  REQUIRE(rows.front().back() == "steady_rate");
  CHECK(std::stod(rows.back().front()) == doctest::Approx(t_stop));
  CHECK(std::stod(rows.back().back()) == doctest::Approx(number_at(*ss, "rate")).epsilon(1e-9));  // CSV: 10 digits
  CHECK(std::stod(rows[rows.size() - 2].back()) >= 0.05);

  const RunOutcome plain = run_arksph_captured("run " + kCavity + " --quiet --out " + (dir / "plain") + kEnd,
                                               dir.dir.string());
  REQUIRE(plain.code == 0);
  CHECK(plain.out.find("steady state") == std::string::npos);
  const JsonValue p = read_json_file(dir / "plain/summary.json");
  CHECK(number_at(p, "final_time") == 8.0);
  CHECK(p.find("steady_state") == nullptr);
  CHECK(read_csv(dir / "plain/timeseries.csv").front().back() != "steady_rate");
}

TEST_CASE("steady state: a restart continues the windows of the run it continues (samples in the checkpoint)") {
  // The default window means, window 1, tolerance 0.01: the uninterrupted run stops near t = 8.
  // The same run stopped at t = 5 and restarted from its checkpoint must stop at the same output
  // time with the same rates: the checkpoint carries the samples of the windows (without them the
  // restart would need two fresh windows, up to t = 7, before its first covered rate). Both runs
  // re-initialise the integrator at t = 5 (checkpoint_every = 5), so their states agree bit for bit.
  ScratchDir dir("steady_restart");
  const std::string steady =
      " --set time.steady_tolerance=0.01 --set time.steady_window=1 --set output.checkpoint_every=5";
  const std::string whole = dir / "whole", parts = dir / "parts";
  REQUIRE(run_arksph_captured("run " + kCavity + " --quiet --out " + whole + " --set time.end=16" + steady,
                              dir.dir.string()).code == 0);
  const RunOutcome first = run_arksph_captured("run " + kCavity + " --quiet --out " + parts + " --set time.end=5" + steady,
                                               dir.dir.string());
  REQUIRE(first.code == 0);
  const JsonValue a = read_json_file(parts + "/summary.json");
  CHECK(number_at(a, "final_time") == 5.0);
  CHECK_FALSE(a.find("steady_state")->find("reached")->boolean);
  CHECK(a.find("steady_state")->find("time")->kind == JsonValue::Kind::null);

  const RunOutcome second = run_arksph_captured("run --quiet --restart " + parts + "/checkpoint.h5 --set time.end=16" + steady,
                                                dir.dir.string());
  CAPTURE(second.err);
  REQUIRE(second.code == 0);
  CHECK(second.out.find("arksph: steady state at t = ") != std::string::npos);
  const JsonValue w = read_json_file(whole + "/summary.json");
  const JsonValue b = read_json_file(parts + "/summary.json");
  const double t_stop = number_at(w, "final_time");
  CHECK(t_stop > 5.0);
  CHECK(t_stop < 16.0);
  CHECK(number_at(b, "final_time") == t_stop);
  CHECK(b.find("steady_state")->find("reached")->boolean);
  CHECK(number_at(*b.find("steady_state"), "rate") == number_at(*w.find("steady_state"), "rate"));
  // Every row, the steady_rate column included, as the uninterrupted run wrote it.
  CHECK(read_csv(parts + "/timeseries.csv") == read_csv(whole + "/timeseries.csv"));
}

TEST_CASE("steady state: the default window means stop the cavity once the means of two windows agree") {
  // Window 1 at outputs 0.5 apart: each mean holds two samples; the rate of the means falls below
  // 0.01 per unit time by t ~ 8 on this cavity (about 0.03 at t = 5), so the stop lies between the
  // first covered sample (t = 2W = 2) and time.end = 16.
  ScratchDir dir("steady_means");
  const std::string out = dir / "run";
  const RunOutcome r = run_arksph_captured("run " + kCavity + " --quiet --out " + out +
                                               " --set time.end=16 --set time.steady_tolerance=0.01 --set time.steady_window=1",
                                           dir.dir.string());
  CAPTURE(r.err);
  REQUIRE(r.code == 0);
  CHECK(r.out.find("the means of two windows of 1") != std::string::npos);
  const JsonValue s = read_json_file(out + "/summary.json");
  const double t_stop = number_at(s, "final_time");
  CHECK(t_stop > 2.0);
  CHECK(t_stop < 16.0);
  const JsonValue* ss = s.find("steady_state");
  REQUIRE(ss);
  CHECK(ss->find("measure")->text == "window_means");
  CHECK(ss->find("reached")->boolean);
  // The rate recorded at every output before the stop was at or above the tolerance, NaN until the
  // two windows are covered by samples (t = 0, 0.5: one window not yet filled).
  const auto rows = read_csv(out + "/timeseries.csv");
  REQUIRE(rows.size() >= 6);
  CHECK(std::isnan(std::stod(rows[1].back())));
  CHECK(std::stod(rows.back().back()) < 0.01);
  for (std::size_t i = 3; i + 1 < rows.size(); ++i) CHECK(std::stod(rows[i].back()) >= 0.01);
}
