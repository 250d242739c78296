// The energy budget across a restart (metrics.energy_budget, tests/scenes/vortex_tank.toml): the
// checkpoint carries the viscous dissipation W_visc, and the restarted run's timeseries.csv continues
// the uninterrupted run's column; a checkpoint of a run without the budget cannot continue one.
#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "io/checkpoint.hpp"
#include "run_arksph.hpp"
#include "test_support.hpp"

using namespace arksph;
using arksph::testing::run_arksph;
using arksph::testing::ScratchDir;

namespace {

// The column `name` of a timeseries.csv (empty if missing).
std::vector<double> csv_column(const std::string& path, const std::string& name) {
  const auto rows = testing::read_csv(path);
  std::vector<double> out;
  if (rows.empty()) return out;
  for (std::size_t k = 0; k < rows[0].size(); ++k)
    if (rows[0][k] == name)
      for (std::size_t i = 1; i < rows.size(); ++i) out.push_back(std::stod(rows[i].at(k)));
  return out;
}

}  // namespace

// Run to t2 = 0.3; run to t1 = 0.15 and restart to t2 (t1 is an output time, so a stop time of
// both). Tolerance 1e-9 relative: the CSV holds 10 digits, and the restarted run computes the
// power at t1 over a neighbour list built anew, which differs from the uninterrupted run's in the
// order of its sums (round-off). A restart that began W_visc again at 0 would be off by W(t1), 0.013.
TEST_CASE("energy budget: a restarted run continues the viscous dissipation of its checkpoint") {
  ScratchDir dir("energy_restart");
  const std::string scene = dir / "tank.toml", log = dir / "log.txt";
  std::ofstream(scene) << testing::test_scene("vortex_tank.toml");
  const std::string full = dir / "full", half = dir / "half";
  REQUIRE(run_arksph("run " + scene + " --quiet --out " + full + " --set time.end=0.3", log) == 0);
  REQUIRE(run_arksph("run " + scene + " --quiet --out " + half + " --set time.end=0.15", log) == 0);
  const Checkpoint first = read_checkpoint(half + "/checkpoint.h5");
  REQUIRE(first.has_viscous_dissipation);
  const std::vector<double> before = csv_column(half + "/timeseries.csv", "viscous_dissipation");
  REQUIRE(before.size() == 4);  // t = 0, 0.05, 0.1, 0.15
  CHECK(first.viscous_dissipation > 0);
  CHECK(first.viscous_dissipation == doctest::Approx(before.back()).epsilon(1e-9));
  REQUIRE(run_arksph("run --restart " + half + "/checkpoint.h5 --quiet --set time.end=0.3", log) == 0);
  const std::vector<double> expected = csv_column(full + "/timeseries.csv", "viscous_dissipation");
  const std::vector<double> continued = csv_column(half + "/timeseries.csv", "viscous_dissipation");
  const std::vector<double> total_expected = csv_column(full + "/timeseries.csv", "total_energy");
  const std::vector<double> total = csv_column(half + "/timeseries.csv", "total_energy");
  REQUIRE(expected.size() == 7);
  REQUIRE(continued.size() == expected.size());
  REQUIRE(total.size() == expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    CAPTURE(i);
    CHECK(continued[i] == doctest::Approx(expected[i]).epsilon(1e-9));
    CHECK(total[i] == doctest::Approx(total_expected[i]).epsilon(1e-9));
  }
  CHECK(continued.back() > before.back());
  CHECK(read_checkpoint(half + "/checkpoint.h5").viscous_dissipation ==
        doctest::Approx(continued.back()).epsilon(1e-9));
}

TEST_CASE("energy budget: a checkpoint without the viscous dissipation cannot continue a budget") {
  ScratchDir dir("energy_restart_refused");
  const std::string scene = dir / "tank.toml", log = dir / "log.txt", out = dir / "out";
  std::ofstream(scene) << testing::test_scene("vortex_tank.toml");
  REQUIRE(run_arksph("run " + scene + " --quiet --out " + out + " --set time.end=0.05 --set metrics.energy_budget=false",
                     log) == 0);
  CHECK_FALSE(read_checkpoint(out + "/checkpoint.h5").has_viscous_dissipation);
  CHECK(run_arksph("run --restart " + out + "/checkpoint.h5 --quiet --set time.end=0.1 --set metrics.energy_budget=true",
                   log) == 2);
  CHECK(testing::slurp(log).find("holds no viscous_dissipation") != std::string::npos);
  // Without the budget the same checkpoint continues.
  CHECK(run_arksph("run --restart " + out + "/checkpoint.h5 --quiet --set time.end=0.1 --set metrics.energy_budget=false",
                   log) == 0);
}
