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
const std::string kSteady = " --set time.steady_tolerance=0.05 --set time.steady_window=2";

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

TEST_CASE("steady state: a restart measures its window afresh and stops at steady state") {
  ScratchDir dir("steady_restart");
  const std::string out = dir / "run";
  // To t = 5: the window (2) is covered from t = 2 on, the rate is still above 0.01 (the test below
  // uses 0.05 and a window of 2 from the restart on).
  const RunOutcome first = run_arksph_captured("run " + kCavity + " --quiet --out " + out + " --set time.end=5" + kSteady +
                                                   " --set time.steady_tolerance=0.001",
                                               dir.dir.string());
  REQUIRE(first.code == 0);
  const JsonValue a = read_json_file(out + "/summary.json");
  CHECK(number_at(a, "final_time") == 5.0);
  CHECK_FALSE(a.find("steady_state")->find("reached")->boolean);
  CHECK(a.find("steady_state")->find("time")->kind == JsonValue::Kind::null);

  const RunOutcome second = run_arksph_captured("run --quiet --restart " + out + "/checkpoint.h5" + kEnd + kSteady,
                                                dir.dir.string());
  CAPTURE(second.err);
  REQUIRE(second.code == 0);
  CHECK(second.out.find("arksph: steady state at t = ") != std::string::npos);
  const JsonValue b = read_json_file(out + "/summary.json");
  const double t_stop = number_at(b, "final_time");
  CHECK(t_stop < 8.0);
  // The first sample after the restart is at t = 5.5: a window of 2 needs samples from 5.5 to 7.5.
  CHECK(t_stop >= 7.5);
  CHECK(b.find("steady_state")->find("reached")->boolean);
}
