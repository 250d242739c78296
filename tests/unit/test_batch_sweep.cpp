// `arksph batch` without running it: the sweep file reader (Cartesian product, linked keys, run
// names, bad files) and the JSON reader that reads summary.json back. The real binary on the CI
// sweep: process/test_batch_runs.cpp.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "core/errors.hpp"
#include "io/json_reader.hpp"
#include "study/sweep.hpp"

using namespace arksph;
namespace fs = std::filesystem;

namespace {
const std::string kSweepDir = std::string(ARKSPH_SOURCE_DIR) + "/cases/sweeps";

std::string sweep_text(const std::string& body) {
  return "[sweep]\nscene = \"taylor_green_small.toml\"\n" + body;
}
}  // namespace

TEST_CASE("batch: the sweep is the Cartesian product, first axis slowest, with deterministic names") {
  const Sweep sw = read_sweep_text(sweep_text("set = [\"time.end=0.01\"]\n"
                                              "[[vary]]\nkey = \"method.kernel\"\nvalues = [\"cubic_spline\", \"wendland_quintic\"]\n"
                                              "[[vary]]\nkey = \"fluid.spacing\"\nvalues = [0.0625, 0.05, 0.1]\n"),
                                   kSweepDir + "/test.toml");
  REQUIRE(sw.runs.size() == 6);
  CHECK(sw.runs[0].name == "0_kernel-cubic_spline_spacing-0.0625");
  CHECK(sw.runs[1].name == "1_kernel-cubic_spline_spacing-0.05");
  CHECK(sw.runs[3].name == "3_kernel-wendland_quintic_spacing-0.0625");
  CHECK(sw.runs[5].sets == std::vector<std::string>{"time.end=0.01", "method.kernel=wendland_quintic", "fluid.spacing=0.1"});
  CHECK(sw.output == "runs/test");
  CHECK(fs::path(sw.scene).filename() == "taylor_green_small.toml");
}

TEST_CASE("batch: linked keys vary together as one axis") {
  const Sweep sw = read_sweep_text(sweep_text("[[vary]]\nkey = [\"fluid.spacing\", \"method.h_over_dx\"]\n"
                                              "values = [[0.0625, 1.5], [0.05, 2]]\n"
                                              "[[vary]]\nkey = \"method.kernel\"\nvalues = [\"cubic_spline\", \"wendland_quintic\"]\n"),
                                   kSweepDir + "/test.toml");
  REQUIRE(sw.runs.size() == 4);
  CHECK(sw.columns == std::vector<std::string>{"fluid.spacing", "method.h_over_dx", "method.kernel"});
  CHECK(sw.runs[2].name == "2_spacing-0.05_h_over_dx-2_kernel-cubic_spline");
  CHECK(sw.runs[2].values == std::vector<std::string>{"0.05", "2", "cubic_spline"});
  CHECK_THROWS_AS(read_sweep_text(sweep_text("[[vary]]\nkey = [\"a\", \"b\"]\nvalues = [[1, 2], [3]]\n"), "x.toml"),
                  InputError);
}

TEST_CASE("batch: bad sweep files are refused with one line naming the key") {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"[[vary]]\nkey = \"method.kernel\"\nvalues = [\"cubic_spline\"]\n", "sweep"},  // no [sweep]
      {sweep_text("jobs = 0\n[[vary]]\nkey = \"a\"\nvalues = [1]\n"), "sweep.jobs"},
      {sweep_text("colour = 1\n[[vary]]\nkey = \"a\"\nvalues = [1]\n"), "sweep.colour"},
      {sweep_text(""), "vary"},
      {sweep_text("[[vary]]\nkey = \"a\"\nvalues = []\n"), "vary[0].values"},
      {sweep_text("[[vary]]\nkey = \"a\"\nvalues = [1]\n[[vary]]\nkey = \"a\"\nvalues = [2]\n"), "vary[1].key"},
      {"[sweep]\nscene = \"nonexistent.toml\"\n[[vary]]\nkey = \"a\"\nvalues = [1]\n", "sweep.scene"},
      {"[sweep\n", ":1:"},
  };
  for (const auto& [text, key] : cases) {
    CAPTURE(text);
    try {
      read_sweep_text(text, kSweepDir + "/bad.toml");
      FAIL("accepted");
    } catch (const InputError& e) {
      const std::string msg = e.what();
      CHECK(msg.find(key) != std::string::npos);
      CHECK(msg.find('\n') == std::string::npos);
    }
  }
}

TEST_CASE("batch: the JSON reader reads back what summary.json holds") {
  const JsonValue j = parse_json(R"({"status": "ok", "steps": 12, "wall_seconds": 1.5e-1,
      "metrics": {"cv": 0.25, "bad": null}, "terms": ["a\"b", "c\\d"], "flag": true})", "inline");
  CHECK(j.find("status")->text == "ok");
  CHECK(j.find("steps")->number == 12);
  CHECK(j.find("wall_seconds")->number == 0.15);
  REQUIRE(j.find("metrics")->members.size() == 2);
  CHECK(j.find("metrics")->members[0].first == "cv");
  CHECK(j.find("metrics")->find("bad")->kind == JsonValue::Kind::null);
  CHECK(j.find("terms")->items[0].text == "a\"b");
  CHECK(j.find("terms")->items[1].text == "c\\d");
  CHECK(j.find("flag")->boolean);
  CHECK_THROWS_AS(parse_json("{\"a\": 1", "inline"), InputError);
  CHECK_THROWS_AS(parse_json("{\"a\": 1} x", "inline"), InputError);
}
