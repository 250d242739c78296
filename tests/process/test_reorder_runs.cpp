// Re-sorting particles by cell at sync points (method.reorder_every, run/particle_reorder.hpp), on
// runs of the binary: a run with re-sorts against the same run without, particle by particle
// matched by id; the order after a re-sort; and a checkpoint restart across re-sorts against the
// run that never stopped.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <unordered_map>

#include "run/particle_reorder.hpp"
#include "io/checkpoint.hpp"
#include "io/scene_reader.hpp"
#include "run_arksph.hpp"
#include "test_support.hpp"

using namespace arksph;
using arksph::testing::run_arksph;
using arksph::testing::ScratchDir;
using arksph::testing::slurp;

namespace {

// The largest difference of any state component between two final checkpoints, particles matched
// by id, relative to the largest magnitude of that block (x, y, u, v, rho, e).
double state_mismatch(const Checkpoint& a, const Checkpoint& b) {
  REQUIRE(a.n == b.n);
  REQUIRE(a.state.size() == b.state.size());
  std::unordered_map<std::int64_t, std::size_t> where;
  for (std::size_t i = 0; i < b.n; ++i) where[b.id[i]] = i;
  const std::size_t n = a.n, blocks = a.state.size() / n;
  double worst = 0;
  for (std::size_t k = 0; k < blocks; ++k) {
    double diff = 0, scale = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const auto it = where.find(a.id[i]);
      REQUIRE(it != where.end());
      const double va = a.state[k * n + i], vb = b.state[k * n + it->second];
      diff = std::max(diff, std::abs(va - vb));
      scale = std::max(scale, std::abs(va));
    }
    worst = std::max(worst, diff / std::max(scale, 1e-300));
  }
  return worst;
}

// Sorted by id, the final checkpoint's constant data must be the same too.
bool same_particles(const Checkpoint& a, const Checkpoint& b) {
  std::map<std::int64_t, std::tuple<double, double, std::int32_t>> ma, mb;
  for (std::size_t i = 0; i < a.n; ++i) ma[a.id[i]] = {a.mass[i], a.rho0[i], a.phase[i]};
  for (std::size_t i = 0; i < b.n; ++i) mb[b.id[i]] = {b.mass[i], b.rho0[i], b.phase[i]};
  return ma == mb;
}

// The largest difference between two timeseries.csv files with the same columns, relative to the
// largest magnitude of its column (flow metrics at each output time: kinetic energy, speeds, the
// C&R density variation cv against the number density at t = 0, which must follow the particle
// order, and the case metrics).
double timeseries_mismatch(const std::string& a, const std::string& b) {
  const auto table = [](const std::string& path, std::string& header) {
    std::istringstream in(slurp(path));
    std::getline(in, header);
    std::vector<std::vector<double>> rows;
    for (std::string line; std::getline(in, line);) {
      std::istringstream r(line);
      rows.emplace_back();
      for (std::string cell; std::getline(r, cell, ',');) rows.back().push_back(std::stod(cell));
    }
    return rows;
  };
  std::string ha, hb;
  const auto ta = table(a, ha), tb = table(b, hb);
  REQUIRE(ha == hb);
  REQUIRE(ta.size() == tb.size());
  REQUIRE(ta.size() >= 2);
  double worst = 0;
  for (std::size_t c = 0; c < ta[0].size(); ++c) {
    double diff = 0, scale = 1e-300;
    for (std::size_t r = 0; r < ta.size(); ++r) {
      REQUIRE(ta[r].size() == tb[r].size());
      diff = std::max(diff, std::abs(ta[r][c] - tb[r][c]));
      scale = std::max(scale, std::abs(ta[r][c]));
    }
    worst = std::max(worst, diff / scale);
  }
  return worst;
}

bool is_identity(const std::vector<std::int64_t>& id) {
  for (std::size_t i = 1; i < id.size(); ++i)
    if (id[i] < id[i - 1]) return false;
  return true;
}

}  // namespace

// Same scene with and without re-sorting (every 4 steps, from a shuffled start, so the first
// re-sort moves almost every particle): fixed step, so both take the same steps. Particles matched
// by id must agree to round-off: the re-sort changes only the order of the neighbour sums.
// Tolerance 1e-10 relative per block: summation-order round-off (~1e-16) amplified over 60 steps
// of a pressure-driven system stays far below it (measured: see MESSAGE); a particle mixed up with
// another, a stale neighbour list or a per-particle array left in the old order gives O(1e-3..1).
TEST_CASE("reorder: a run with re-sorts equals the run without, particle by particle (walled, periodic, isph, imex)") {
  ScratchDir dir("reorder_same");
  const std::string log = dir / "log.txt";
  const std::string tg = dir / "tg.toml";
  std::ofstream(tg) << arksph::testing::kTaylorGreenBox << "[time]\nend = 0.12\ndt = 0.002\n[output]\nevery = 0\n";
  struct Case {
    const char* name;
    std::string args;
  };
  // Lattice displaced by up to 0.1 dx, so that the number density at t = 0 differs from particle to
  // particle (on a regular lattice with ghosts it is uniform, and a d0 left in the old order would
  // not show in cv).
  const std::string offset = " --set 'initial.offset=[\"0.005*sin(9*x+4*y)\", \"0.005*cos(7*x*y+1)\"]'";
  const std::string cavity = "--set fluid.spacing=0.05 --set time.dt=0.001 --set time.end=0.06 --set output.every=0" + offset;
  const std::vector<Case> cases = {
      {"cavity (walls, moving lid)", cavity},
      {"cavity, linear wall velocity, Shepard", cavity + " --set boundary.wall_velocity=linear --set method.kernel_correction=shepard"},
      {"Taylor-Green (doubly periodic)", tg + offset},
      {"cavity isph (KLU)", cavity + " --set method.scheme=isph --set time.dt=0.002 --set time.end=0.04"},
      {"cavity imex", cavity + " --set time.imex=true --set time.dt=0.002"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.name);
    const std::string off = dir / "off", on = dir / "on";
    const std::string base = "run " + c.args;
    REQUIRE(run_arksph(base + " --quiet --set fluid.shuffle_initial_order=true --set method.reorder_every=0 --out " + off,
                       log) == 0);
    REQUIRE(run_arksph(base + " --quiet --set fluid.shuffle_initial_order=true --set method.reorder_every=4 --out " + on,
                       log) == 0);
    const Checkpoint a = read_checkpoint(off + "/checkpoint.h5"), b = read_checkpoint(on + "/checkpoint.h5");
    CHECK(a.steps == b.steps);
    CHECK(!is_identity(a.id));  // shuffled, never re-sorted
    CHECK(a.id != b.id);        // re-sorted
    CHECK(same_particles(a, b));
    const double mismatch = state_mismatch(a, b);
    const double series = timeseries_mismatch(off + "/timeseries.csv", on + "/timeseries.csv");
    MESSAGE(std::string(c.name), ": largest relative difference ", mismatch, " (state), ", series, " (timeseries.csv)");
    CHECK(mismatch < 1e-10);
    CHECK(series < 1e-8);  // the CSV holds 10 significant digits: a last-digit flip is up to 1e-9
    CHECK(slurp(on + "/summary.json").find("\"reorders\"") != std::string::npos);
  }
}

// After the last step (a re-sort step: 60 steps, every 4) the stored order is the cell order.
TEST_CASE("reorder: after a re-sort the particles are in cell order (monotone cell index)") {
  ScratchDir dir("reorder_order");
  const std::string out = dir / "run", log = dir / "log.txt";
  REQUIRE(run_arksph("run --quiet --set fluid.spacing=0.05 --set time.dt=0.001 --set time.end=0.06 --set output.every=0 "
                     "--set fluid.shuffle_initial_order=true --set method.reorder_every=4 --out " + out,
                     log) == 0);
  const Checkpoint c = read_checkpoint(out + "/checkpoint.h5");
  REQUIRE(c.steps % 4 == 0);
  const Scene scene = read_scene_text(c.scene_toml, "checkpoint", {});
  Model model = build_model(scene);
  const double side = model.rhs->kernel().radius();
  const StateLayout L = c.layout();
  const std::vector<std::uint64_t> key =
      cell_keys(c.state.data() + L.pos(0), c.state.data() + L.pos(1), c.n, scene.min[0], scene.min[1], side);
  std::size_t descents = 0;
  for (std::size_t i = 1; i < c.n; ++i) descents += key[i] < key[i - 1];
  CHECK(descents == 0);
  CHECK(!is_identity(c.id));
}

// Run to T; run to T/2 and restart to T, with re-sorts every 7 steps (the checkpoint at step 50
// falls between two) and every 10 (a re-sort at the checkpoint step itself): the final states and
// the time series (whose density diagnostics use the t = 0 number density, which must follow the
// order) are bit-identical, as without re-sorting (test_checkpoint_runs.cpp).
TEST_CASE("reorder: a checkpoint restart across re-sorts ends bit-identical to the uninterrupted run") {
  ScratchDir dir("reorder_restart");
  const std::string scene = dir / "tg.toml", log = dir / "log.txt";
  std::ofstream(scene) << arksph::testing::test_scene("taylor_green_checkpoints.toml");
  for (const char* every : {"7", "10"}) {
    CAPTURE(every);
    const std::string full = dir / (std::string("full") + every), half = dir / (std::string("half") + every);
    const std::string sets = std::string(" --quiet --set fluid.shuffle_initial_order=true --set method.reorder_every=") + every;
    REQUIRE(run_arksph("run " + scene + sets + " --out " + full, log) == 0);
    REQUIRE(run_arksph("run " + scene + sets + " --out " + half + " --set time.end=0.1", log) == 0);
    const Checkpoint mid = read_checkpoint(half + "/checkpoint.h5");
    CHECK(!is_identity(mid.id));  // the restart starts from a re-sorted order
    REQUIRE(run_arksph("run --restart " + half + "/checkpoint.h5 --quiet --set time.end=0.2", log) == 0);
    const Checkpoint a = read_checkpoint(full + "/checkpoint.h5"), b = read_checkpoint(half + "/checkpoint.h5");
    CHECK(a.steps == b.steps);
    CHECK(a.id == b.id);
    CHECK(a.state == b.state);  // bit for bit (no NaN in a finished run)
    CHECK(slurp(full + "/timeseries.csv") == slurp(half + "/timeseries.csv"));
  }
}
