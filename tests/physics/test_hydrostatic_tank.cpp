// A closed tank at rest under gravity (walls all round, H = g = rho = 1, 20 x 20 particles).
// With the modified pressure (method.body_force_pressure = "modified", the automatic choice for one
// density: rhs/pressure_gravity.hpp) every projection holds it exactly at rest, disordered and at
// the adaptive step. With gravity in the momentum equation ("split") the pressure must balance
// gravity at the walls too (dp/dn = rho g . n), for every Poisson solver and
// pressure level of scheme isph, for the constrained projection, for isph-gpps, and for WCSPH
// started in hydrostatic balance (initial.hydrostatic). Without the wall condition (the wall points
// carrying their source's pressure) the first rows at the floor and the lid move at a sizable
// fraction of g dt per step and the tank starts to circulate: ISPH blows up within t ~ 0.4.
// The runs over t = 1 go through the binary (process/cli_outcome.hpp), so that
// ARKSPH_TEST_BINARY=<another build> shows what that build does with the same tank.
#include <doctest/doctest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "../process/cli_outcome.hpp"
#include "integrate/erk_integrator.hpp"
#include "io/scene_reader.hpp"
#include "run/setup.hpp"
#include "test_support.hpp"

using namespace arksph;
namespace fs = std::filesystem;

namespace {
const char* kTank = R"toml(
[scene]
name = "tank"
[domain]
min = [0.0, 0.0]
max = [1.0, 1.0]
[boundary]
left   = { kind = "wall" }
right  = { kind = "wall" }
bottom = { kind = "wall" }
top    = { kind = "wall" }
[fluid]
spacing = 0.05
viscosity = 0.01
body_force = ["0", "-1"]
[method]
scheme = "isph"
ppe_pressure_level = "zero_min"
[time]
end = 0.01
integrator = "ARKODE_HEUN_EULER_2_1_2"
dt = 0.01
[output]
every = 0.1
)toml";

// r.m.s. of p - rho g (H - y) over the particles, both at zero mean (the level of a closed box is
// free), relative to the r.m.s. of rho g (H - y) about its mean.
double pressure_deviation(const std::vector<double>& y, const std::vector<double>& p, std::size_t n) {
  double mp = 0, mr = 0;
  for (std::size_t a = 0; a < n; ++a) {
    mp += p[a];
    mr += 1.0 - y[a];
  }
  mp /= static_cast<double>(n);
  mr /= static_cast<double>(n);
  double dev = 0, ref = 0;
  for (std::size_t a = 0; a < n; ++a) {
    const double r = 1.0 - y[a] - mr;
    dev += (p[a] - mp - r) * (p[a] - mp - r);
    ref += r * r;
  }
  return std::sqrt(dev / ref);
}

struct StepResult {
  double deviation = 0, max_speed = 0;
};

StepResult one_step(const std::vector<std::string>& sets) {
  std::ostringstream warnings;
  std::vector<std::string> with_split = sets;
  with_split.push_back("method.body_force_pressure=split");
  const Scene scene = read_scene_text(kTank, "tank", with_split, warnings);
  Model model = build_model(scene);
  std::vector<double> y0;
  const std::vector<double> y1 = testing::one_projected_step(scene, model, y0);
  const StateLayout& L = model.rhs->layout();
  StepResult r;
  for (std::size_t a = 0; a < L.n; ++a)
    r.max_speed = std::max(r.max_speed, std::hypot(y1[L.vel(0) + a], y1[L.vel(1) + a]));
  const std::vector<double> ypos(y1.begin() + static_cast<long>(L.pos(1)), y1.begin() + static_cast<long>(L.pos(1) + L.n));
  r.deviation = pressure_deviation(ypos, model.projection->pressure(), L.n);
  return r;
}

// Largest max_speed of timeseries.csv and its value at the last output, of a CLI run of the tank.
struct RunResult {
  int code = -1;
  double max_speed = 0, last = 0, end = 0;
};

RunResult run_tank(const std::string& name, const std::string& sets, const std::string& steps = "--set time.dt=0.002") {
  const fs::path dir = fs::temp_directory_path() / ("arksph_tank_" + std::to_string(getpid()) + "_" + name);
  fs::create_directories(dir);
  const fs::path scene = dir / "scene.toml";
  std::ofstream(scene) << kTank;
  const testing::CliOutcome o =
      testing::run_cli("run " + scene.string() + " --quiet --out " + (dir / "out").string() +
                       " --set time.end=1 " + steps + " " + sets);
  RunResult r;
  r.code = o.code;
  const auto rows = testing::read_csv((dir / "out" / "timeseries.csv").string());
  std::size_t col = 0;
  if (!rows.empty())
    for (std::size_t k = 0; k < rows[0].size(); ++k)
      if (rows[0][k] == "max_speed") col = k;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const double s = std::stod(rows[i][col]);
    r.max_speed = std::max(r.max_speed, s);
    r.last = s;
    r.end = std::stod(rows[i][0]);
  }
  fs::remove_all(dir);
  return r;
}
}  // namespace

// One step of g dt = 0.01 from rest, gravity in the momentum equation ("split"). Measured with the wall condition: pressure deviation 3.8e-4
// (isph, every solver and level), 3.8e-5 (isph-gpps); max speed 8e-5 to 1.4e-4 (isph), 7e-16
// (isph-gpps). Without it the wall rows move at a fair fraction of g dt and the pressure has a
// boundary layer along each wall.
TEST_CASE("hydrostatic tank: one projected step returns p = rho g (H - y) and leaves the fluid at rest") {
  const double kDeviation = 2e-3;    // r.m.s. relative pressure deviation: five times the measured
  const double kSpeed = 0.03 * 0.01;  // 3 % of g dt: twice the measured
  for (const std::string solver : {"auto", "klu", "cg", "cg_ic", "cg_amg"})
    for (const std::string level : {"zero_mean", "zero_min"}) {
      const StepResult r = one_step({"method.ppe_solver=" + solver, "method.ppe_pressure_level=" + level});
      MESSAGE(solver, " ", level, ": pressure deviation ", r.deviation, ", max speed ", r.max_speed);
      CHECK(r.deviation < kDeviation);
      CHECK(r.max_speed < kSpeed);
    }
  const StepResult grid = one_step({"method.scheme=isph-gpps"});
  MESSAGE("isph-gpps: pressure deviation ", grid.deviation, ", max speed ", grid.max_speed);
  CHECK(grid.deviation < kDeviation);
  CHECK(grid.max_speed < kSpeed);
}

// t = 1 (about one gravity-wave period sqrt(H/g)), dt = 0.002 (WCSPH 0.001), outputs every 0.1: the
// largest speed at any output against sqrt(g H) = 1 (isph with the default solver and klu; the one
// step above covers every solver). Measured: isph 2.6e-5 (auto, klu and cg alike),
// constrained projection 7.3e-5 (with beta = 50: at the default relaxation the fluid slowly sinks,
// growing ~4 /s), isph-gpps 5e-16, wcsph with the hydrostatic start 7.9e-4. Without the wall
// condition isph ends in a blow-up (exit 3) before t = 0.5.
TEST_CASE("hydrostatic tank: every scheme holds the tank at rest over t = 1") {
  const double kBound = 2e-3;  // 2e-3 sqrt(gH), the acceptance bound of cases/hydrostatic_tank at every output
  const std::string split = " --set method.body_force_pressure=split";
  const std::vector<std::pair<std::string, std::string>> runs = {
      {"isph_auto", split},
      {"isph_klu", "--set method.ppe_solver=klu" + split},
      {"isph_constrained", "--set method.projection=constrained --set method.constraint_relaxation=50" + split},
      {"isph_gpps", "--set method.scheme=isph-gpps" + split},
      {"wcsph", "--set method.scheme=wcsph --set initial.hydrostatic=true --set time.dt=0.001"},
  };
  for (const auto& [name, sets] : runs) {
    const RunResult r = run_tank(name, sets);
    MESSAGE(name, ": exit ", r.code, ", max speed over the outputs ", r.max_speed, ", at t = ", r.end, ": ", r.last);
    CHECK(r.code == 0);
    CHECK(r.end == doctest::Approx(1.0));
    CHECK(r.max_speed < kBound);
  }
}

// The modified pressure P = p - rho0 g . r (rhs/pressure_gravity.hpp), the default for one density:
// the particles disordered by up to 0.004 = 0.08 dx, t = 1 at the adaptive step (the viscous limit,
// 0.1 here), every projection. At rest P is constant, so no particle moves at all: max speed 0 at
// every output, measured. The same disordered tank with gravity in the momentum equation ("split")
// at the same defaults moved at 0.044 (C&R) and 0.085 (constrained) by t = 2 (the SPH gradient's
// error for the hydrostatic p, which the approximate projection leaves), and the orthogonal
// projection refuses it.
TEST_CASE("hydrostatic tank: with the modified pressure every projection holds a disordered tank at rest, adaptive step") {
  const double kBound = 1e-12;  // round-off of a state that is at rest exactly
  const std::string disorder =
      " --set 'initial.offset=[\"0.004*sin(97*x*y+1)\", \"0.004*cos(89*x+71*y)\"]'";
  for (const std::string projection : {"cummins_rudman", "constrained", "orthogonal"}) {
    const RunResult r = run_tank("modified_" + projection, "--set method.projection=" + projection + disorder,
                                 "--set time.dt=0");
    MESSAGE(projection, ": exit ", r.code, ", max speed over the outputs ", r.max_speed);
    CHECK(r.code == 0);
    CHECK(r.end == doctest::Approx(1.0));
    CHECK(r.max_speed < kBound);
  }
  const RunResult grid = run_tank("modified_gpps", "--set method.scheme=isph-gpps" + disorder, "--set time.dt=0");
  CHECK(grid.code == 0);
  CHECK(grid.max_speed < kBound);
  // The split at the same defaults moves: the check above can fail. Bound: a twentieth of the speed
  // measured at t = 2 (0.044), reached well before t = 1.
  const RunResult split = run_tank("split_cr", "--set method.body_force_pressure=split" + disorder, "--set time.dt=0");
  MESSAGE("split, C&R: max speed over the outputs ", split.max_speed);
  CHECK(split.max_speed > 2e-3);
}

// The pressure the frames carry with the modified pressure: p = P + rho0 g . r at the level of the
// highest particle, rho g (y_top - y) on the lattice to round-off.
TEST_CASE("hydrostatic tank: the modified pressure reports the hydrostatic p") {
  std::ostringstream warnings;
  const Scene scene = read_scene_text(kTank, "tank", {}, warnings);
  REQUIRE(scene.body_force_pressure == BodyForcePressure::modified);
  Model model = build_model(scene);
  std::vector<double> y0;
  const std::vector<double> y1 = testing::one_projected_step(scene, model, y0);
  const StateLayout& L = model.rhs->layout();
  const std::vector<double>& p = model.projection->pressure();
  REQUIRE(p.size() == L.n);
  double top = -1;
  for (std::size_t a = 0; a < L.n; ++a) top = std::max(top, y1[L.pos(1) + a]);
  double worst = 0;
  for (std::size_t a = 0; a < L.n; ++a) worst = std::max(worst, std::abs(p[a] - (top - y1[L.pos(1) + a])));
  MESSAGE("largest |p - rho g (y_top - y)| ", worst);
  CHECK(worst < 1e-12);  // round-off of values of order rho g H = 1
}
