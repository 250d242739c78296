// `arksph study work-precision`, the real binary: the tiny Taylor-Green study (CSV columns, errors
// against the exact solution falling with resolution) and bad study files (exit 2, one line).
#include <doctest/doctest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/errors.hpp"
#include "study/work_precision.hpp"
#include "test_support.hpp"

using namespace arksph;
namespace fs = std::filesystem;

namespace {
const std::string kStudies = std::string(ARKSPH_SOURCE_DIR) + "/cases/studies";
}  // namespace

TEST_CASE("work-precision: the tiny Taylor-Green study writes its CSV, errors fall with resolution") {
  testing::ScratchDir scratch("wp_tiny");
  const std::string out = scratch / "out";
  const std::string cmd = std::string("OMP_NUM_THREADS=1 ") + ARKSPH_BINARY + " study work-precision " + kStudies +
                          "/wp_taylor_green_tiny.toml --quiet --out " + out + " >" + (scratch / "stdout.txt") + " 2>&1";
  const int status = std::system(cmd.c_str());
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  const auto rows = testing::read_csv(out + "/work_precision.csv");
  REQUIRE(rows.size() == 7);  // header + 2 schemes x 3 resolutions
  CHECK(rows[0] == std::vector<std::string>{"scheme", "resolution", "particles", "wall_seconds", "steps", "rhs_evals",
                                            "error_l1", "error_l2", "error_linf", "status", "run"});
  for (std::size_t r = 1; r < rows.size(); ++r) CHECK(rows[r][9] == "ok");
  // Against the exact Taylor-Green solution the L2 error falls from 12^2 to 16^2 to 24^2 for both
  // schemes (measured: isph at dt = 5e-4 0.0100, 0.0082, 0.0074; wcsph 0.045, 0.035, 0.021).
  for (std::size_t s : {1u, 4u}) {
    CAPTURE(rows[s][0]);
    const double e12 = std::stod(rows[s][7]), e16 = std::stod(rows[s + 1][7]), e24 = std::stod(rows[s + 2][7]);
    CHECK(e16 < e12);
    CHECK(e24 < e16);
    CHECK(std::stol(rows[s + 2][2]) == 576);
  }
  const std::string text = testing::slurp(scratch / "stdout.txt");
  CHECK(text.find("soonest to L2 error") != std::string::npos);
}

TEST_CASE("work-precision: bad study files are refused with one line naming the key (exit 2)") {
  testing::ScratchDir scratch("wp_bad");
  const std::string head = "[study]\nscene = \"" + kStudies + "/../sweeps/taylor_green_small.toml\"\n";
  const std::string two_res = "[[resolution]]\nset = [\"fluid.spacing=0.1\"]\n[[resolution]]\nset = [\"fluid.spacing=0.05\"]\n";
  const std::string scheme = "[[scheme]]\nname = \"wcsph\"\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"[studdy]\n", "studdy"},
      {"[study]\nreference = \"analytic\"\n", "study.scene"},
      {head + "reference = \"nearby\"\n" + scheme + two_res, "study.reference"},
      {head + "reference = \"analytic\"\n" + scheme + two_res, "study.analytic_velocity"},
      {head + "reference = \"analytic\"\nanalytic_velocity = [\"sin(\", \"0\"]\n" + scheme + two_res, "study.analytic_velocity"},
      {head + "reference = \"run\"\n" + scheme + two_res, "study.reference_set"},
      {head + "reference = \"ghia\"\n" + scheme + "[[resolution]]\nset = [\"fluid.spacing=0.1\"]\n", "resolution"},
      {head + "reference = \"ghia\"\n" + two_res, "scheme"},
      {head + "reference = \"ghia\"\ncolour = 1\n" + scheme + two_res, "study.colour"},
      {head + "reference = \"ghia\"\n[[scheme]]\nset = [\"method.kernel=no_such\"]\n" + two_res, "method.kernel"},
      {head + "reference = \"ghia\"\nset = [\"metrics.ghia_re=100\"]\n" + scheme + scheme + two_res, "repeats"},
      {head + "reference = \"ghia\"\n" + scheme + two_res, "ghia_re"},  // Taylor-Green has no Ghia metric
  };
  for (const auto& [text, key] : cases) {
    CAPTURE(text);
    std::ofstream(scratch / "bad.toml") << text;
    try {
      read_work_precision_study(scratch / "bad.toml", {});
      FAIL("accepted");
    } catch (const InputError& e) {
      CHECK(std::string(e.what()).find(key) != std::string::npos);
    }
  }
  // The command: exit 2, a single line on stderr, nothing run.
  std::ofstream(scratch / "bad.toml") << cases[2].first;
  const std::string err = scratch / "err.txt";
  const int status = std::system((std::string(ARKSPH_BINARY) + " study work-precision " + (scratch / "bad.toml") +
                                  " --out " + (scratch / "out") + " >/dev/null 2>" + err).c_str());
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 2);
  const std::string msg = testing::slurp(err);
  CHECK(std::count(msg.begin(), msg.end(), '\n') == 1);
  CHECK(msg.find("study.reference") != std::string::npos);
  CHECK_FALSE(fs::exists(scratch / "out"));
}
