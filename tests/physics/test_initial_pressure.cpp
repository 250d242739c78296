// initial.pressure: WCSPH started from the Tait density of the Taylor-Green vortex's exact pressure
// p = -(1/4)(cos 4 pi x + cos 4 pi y) (rho0 = U = 1). A start at rho = rho0 leaves that pressure to
// build up through sound waves of velocity amplitude about p / (rho0 c) = 0.025 at c = 10, which
// dominate the early velocity error; the matched start has none. Periodic 25 x 25, Re = 100,
// regularisation off (its own error would blur the comparison), t = 0.1, about one acoustic
// crossing time. The bound: at most half the error of the start at rho0 (a start that ignored the
// key, or used the wrong sign, shows no gain or a larger error).
#include <doctest/doctest.h>

#include <sstream>

#include "core/errors.hpp"
#include "vortex_error.hpp"

using namespace arksph;

namespace {
// wcsph at c = 10 without regularisation, to t = 0.1.
const std::vector<std::string> kPlainWcsph = {"method.scheme=\"wcsph\"", "method.regularisation=\"none\"",
                                              "method.density_diffusion=\"none\"", "time.end=0.1"};

double l1_error(const testing::ScratchDir& dir, const std::string& name, const std::vector<std::string>& extra) {
  std::vector<std::string> sets = kPlainWcsph;
  sets.insert(sets.end(), extra.begin(), extra.end());
  return testing::vortex_l1_error(dir, name, sets);
}
}  // namespace

TEST_CASE("initial.pressure: WCSPH started from the exact pressure's density has no start-up sound waves") {
  const testing::ScratchDir dir("pressure_start");
  const std::string p = "initial.pressure=\"-0.25*(cos(4*pi*x) + cos(4*pi*y))\"";
  for (const std::string mode : {"continuity", "summation"}) {
    const std::string m = "method.density_mode=\"" + mode + "\"";
    const double at_rho0 = l1_error(dir, mode + "_rho0", {m});
    const double matched = l1_error(dir, mode + "_matched", {m, p});
    MESSAGE(mode, ": relative L1 at t = 0.1 ", matched, " from the exact pressure, ", at_rho0, " from rho0");
    CHECK(matched <= 0.5 * at_rho0);
  }
}

TEST_CASE("initial.pressure: a pressure below the Tait floor or a bad expression exits with a line naming the key") {
  std::ostringstream warnings;
  for (const std::string bad : {"initial.pressure=\"-100\"", "initial.pressure=\"cos(z)\""}) {
    CAPTURE(bad);
    std::vector<std::string> sets = kPlainWcsph;
    sets.insert(sets.end(), {bad, "time.end=0.001"});
    const Scene scene = read_scene_text(testing::kTaylorGreenVortex25, "<test>", sets, warnings);
    RunOptions opt;
    opt.quiet = true;
    opt.write_frames = false;
    try {
      run_simulation(scene, opt);
      FAIL("accepted");
    } catch (const InputError& e) {
      CHECK(std::string(e.what()).find("initial.pressure") != std::string::npos);
    }
  }
}
