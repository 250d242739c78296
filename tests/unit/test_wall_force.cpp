// The Lennard-Jones wall force (boundary.wall_force = "lennard_jones", Monaghan 1994 §3):
//   - on a lattice pushed towards the walls, its acceleration (f with the force minus f without)
//     equals a brute-force sum over every boundary particle of every wall;
//   - the undisturbed cell-centred lattice, whose first row lies r0 from the walls, feels none;
//   - with the ghosts off, the walls have no images; the scheme check.
#include <doctest/doctest.h>

#include <cmath>
#include <sstream>
#include <vector>

#include "core/errors.hpp"
#include "io/scene_reader.hpp"
#include "rhs/terms.hpp"
#include "run/setup.hpp"
#include "test_support.hpp"

using namespace arksph;
using arksph::testing::fields_at_start;

namespace {
const char* kWallForceBox = R"toml(
[scene]
name = "wall_force"
[domain]
min = [0.0, 0.0]
max = [1.0, 1.0]
[fluid]
spacing = 0.05
viscosity = 0.0
[method]
scheme = "wcsph"
sound_speed = 10
regularisation = "none"
density_diffusion = "none"
[time]
end = 0.01
)toml";

Scene wall_box(std::vector<std::string> sets) {
  std::ostringstream warnings;
  return read_scene_text(kWallForceBox, "<test>", sets, warnings);
}

// du/dt, dv/dt of the real particles at t = 0, and their positions.
struct Accelerations {
  std::vector<double> x, y, ax, ay;
  std::size_t ghosts = 0;
};
Accelerations evaluate(const Scene& scene) {
  Model model = build_model(scene);
  const FluidFields& f = fields_at_start(model);
  Accelerations out;
  out.ghosts = f.n_all - f.n_real;
  for (std::size_t a = 0; a < f.n_real; ++a) {
    out.x.push_back(f.x[a]);
    out.y.push_back(f.y[a]);
    out.ax.push_back(f.dudt[a]);
    out.ay.push_back(f.dvdt[a]);
  }
  return out;
}

// The boundary particles of the unit box's four walls, spaced r0, each corner once.
std::vector<std::array<double, 2>> boundary_particles(double r0) {
  std::vector<std::array<double, 2>> pts;
  const int n = static_cast<int>(std::lround(1.0 / r0));
  for (int j = 0; j <= n; ++j) {
    pts.push_back({0.0, j * r0});
    pts.push_back({1.0, j * r0});
  }
  for (int j = 1; j < n; ++j) {
    pts.push_back({j * r0, 0.0});
    pts.push_back({j * r0, 1.0});
  }
  return pts;
}

const std::vector<std::string> kPushed = {
    // Every particle moved 0.2 dx towards its nearest walls, and sideways by up to 0.06 dx.
    "initial.offset=[\"-0.01*(1 - 2*x) + 0.003*sin(37*y)\", \"-0.01*(1 - 2*y) + 0.003*cos(23*x)\"]"};
}  // namespace

TEST_CASE("wall force: the Lennard-Jones acceleration equals a brute-force sum over the boundary particles") {
  const double D = 0.7, r0 = 0.5 * 0.05;
  std::vector<std::string> with = kPushed, without = kPushed;
  for (auto* sets : {&with, &without}) sets->push_back("boundary.wall_ghosts=false");
  with.push_back("boundary.wall_force=lennard_jones");
  with.push_back("boundary.wall_force_strength=0.7");
  const Accelerations on = evaluate(wall_box(with)), off = evaluate(wall_box(without));
  REQUIRE(on.x.size() == 400);
  CHECK(on.ghosts == 0);  // no wall images
  const auto pts = boundary_particles(r0);
  double worst = 0, largest = 0;
  int pushed = 0;
  for (std::size_t a = 0; a < on.x.size(); ++a) {
    double ex = 0, ey = 0;
    for (const auto& p : pts) {
      const double dx = on.x[a] - p[0], dy = on.y[a] - p[1], r2 = dx * dx + dy * dy;
      if (r2 >= r0 * r0) continue;
      const double s = std::pow(r0 * r0 / r2, 2);  // (r0/r)^4
      ex += D * (s * s * s - s) / r2 * dx;
      ey += D * (s * s * s - s) / r2 * dy;
    }
    if (ex != 0 || ey != 0) ++pushed;
    largest = std::max(largest, std::hypot(ex, ey));
    worst = std::max(worst, std::hypot(on.ax[a] - off.ax[a] - ex, on.ay[a] - off.ay[a] - ey));
  }
  CHECK(pushed >= 70);  // the 76 particles of the outer ring (some sideways shifts leave a few out)
  CHECK(largest > 1.0);
  // Round-off: the same sums in another order and a subtraction of two whole evaluations.
  CHECK(worst <= 1e-12 * largest);
}

TEST_CASE("wall force: the undisturbed lattice feels no wall force, and the ghosts are there by default") {
  const Accelerations on = evaluate(wall_box({"boundary.wall_force=lennard_jones", "boundary.wall_force_strength=5"}));
  const Accelerations off = evaluate(wall_box({}));
  CHECK(on.ghosts > 0);
  CHECK(on.ghosts == off.ghosts);
  double worst = 0;
  for (std::size_t a = 0; a < on.x.size(); ++a)
    worst = std::max(worst, std::hypot(on.ax[a] - off.ax[a], on.ay[a] - off.ay[a]));
  // The first row sits r0 from the wall up to the round-off of its coordinate: (r0/r)^12 - (r0/r)^4
  // is then a few 1e-16, times D / r0 = 200.
  CHECK(worst <= 1e-11);
}

TEST_CASE("wall force: walls without ghosts need wcsph") {
  for (const char* scheme : {"isph", "isph-gpps"}) {
    try {
      wall_box({"boundary.wall_ghosts=false", std::string("method.scheme=") + scheme});
      FAIL("accepted boundary.wall_ghosts=false with " << scheme);
    } catch (const InputError& e) {
      const std::string what = e.what();
      CHECK(what.find("boundary.wall_ghosts") != std::string::npos);
      CHECK(what.find("\n") == std::string::npos);
    }
  }
}
