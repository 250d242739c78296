// Tangential velocity of no-slip ghosts (Basa et al. 2008 §6.1.2): every registered rule continues a
// Couette profile exactly into the walls; quadratic extrapolation also continues a parabola, which
// linear extrapolation and mirroring miss.
#include <doctest/doctest.h>

#include <cmath>
#include <sstream>

#include "run/setup.hpp"
#include "io/names.hpp"
#include "io/scene_reader.hpp"

using namespace arksph;

namespace {
// Channel periodic in x, walls at y = 0 and 1, 20 x 20 particles, u = 4 y (1 - y): the analytic
// continuation behind the walls is the same parabola.
const std::string kWallVelocityChannel = R"toml(
[scene]
name = "wall_velocity"
[domain]
min = [0.0, 0.0]
max = [1.0, 1.0]
[boundary]
left = { kind = "periodic" }
right = { kind = "periodic" }
bottom = { kind = "wall" }
top = { kind = "wall" }
[fluid]
spacing = 0.05
viscosity = 1
[initial]
velocity = ["4*y*(1-y)", "0"]
[method]
kernel = "quintic_spline"
h_over_dx = 1.0
sound_speed = 10
[time]
end = 1
)toml";

struct GhostError {
  double max_abs = 0;  // max |u_ghost - u_exact(y)| over the ghosts behind the walls
  double max_v = 0;    // max |v_ghost|: the normal component is mirrored (v = 0 here)
  int count = 0;
};

// The ghosts of the channel with `mode`, against the exact continuation u_exact(y) of the initial
// velocity (the parabola unless the overrides change it).
template <class Exact>
GhostError ghost_error(const std::string& mode, const std::vector<std::string>& extra, Exact u_exact) {
  std::ostringstream w;
  std::vector<std::string> sets = {"boundary.wall_velocity=" + mode};
  sets.insert(sets.end(), extra.begin(), extra.end());
  const Scene scene = read_scene_text(kWallVelocityChannel, "test", sets, w);
  Model model = build_model(scene);
  std::vector<double> y(model.rhs->layout().size()), ydot(y.size());
  model.rhs->initial_state(y.data());
  model.rhs->eval(0.0, y.data(), ydot.data());
  const FluidFields& f = model.rhs->fields();
  GhostError e;
  for (std::size_t i = f.n_real; i < f.n_all; ++i) {
    if (f.y[i] > 0 && f.y[i] < 1) continue;  // periodic images
    e.max_abs = std::max(e.max_abs, std::abs(f.u[i] - u_exact(f.y[i])));
    e.max_v = std::max(e.max_v, std::abs(f.v[i]));
    ++e.count;
  }
  return e;
}

double parabola(double y) { return 4 * y * (1 - y); }

GhostError ghost_error(const std::string& mode, const std::vector<std::string>& extra = {}) {
  return ghost_error(mode, extra, parabola);
}
}  // namespace

// Couette flow u = y between the wall y = 0 at rest and the wall y = 1 moving at (1, 0): mirroring
// (2 w - u), linear and quadratic extrapolation all continue a linear profile exactly, with one
// and two ghost layers. Round-off only: 1e-12 against velocities of order 1. A rule that ignored
// the wall velocity, or took the distance on the wrong side, is off by O(0.1).
TEST_CASE("wall velocity: every registered rule continues a Couette profile exactly into the walls") {
  const std::vector<std::string> couette = {"initial.velocity=[\"y\", \"0\"]",
                                            "boundary.top.velocity=[1, 0]"};
  const auto rules = registered_names("wall_velocity");
  REQUIRE(rules.size() >= 3);
  for (const std::string& rule : rules) {
    for (const char* model : {"morris", "two_pass"}) {
      CAPTURE(rule);
      CAPTURE(model);
      std::vector<std::string> sets = couette;
      sets.push_back(std::string("method.viscosity_model=") + model);
      const GhostError e = ghost_error(rule, sets, [](double y) { return y; });
      CHECK(e.count > 0);
      CHECK(e.max_abs < 1e-12);
      CHECK(e.max_v < 1e-15);
    }
  }
}

TEST_CASE("wall velocity: quadratic extrapolation continues a parabolic profile exactly into the wall") {
  // Lagrange interpolation through (0, 0), (d1, u1), (d2, u2) of a parabola is the parabola:
  // round-off only (1e-12 against velocities of order 1).
  const GhostError q = ghost_error("quadratic");
  CHECK(q.count > 0);
  CHECK(q.max_abs < 1e-12);
  CHECK(q.max_v < 1e-15);
  // Two-pass ghosts are twice as deep; the extrapolation still holds there.
  const GhostError q2 = ghost_error("quadratic", {"method.viscosity_model=two_pass"});
  CHECK(q2.count > q.count);
  CHECK(q2.max_abs < 1e-12);
  // Linear extrapolation (constant shear into the wall) and mirroring miss the curvature: the
  // deepest ghost (d = 2.975 dx behind the wall) is off by about 4 d^2 + ... (> 0.05 here).
  const GhostError lin = ghost_error("linear"), mir = ghost_error("mirror");
  MESSAGE("max ghost error: quadratic " << q.max_abs << ", linear " << lin.max_abs << ", mirror " << mir.max_abs);
  CHECK(lin.max_abs > 0.05);
  CHECK(mir.max_abs > lin.max_abs);
}

// Linear extrapolation from a particle pressed against the wall. The first row of the Couette channel
// is moved to 0.02 dx above the bottom wall, and the fluid slips at both walls by 0.01
// (u = y + 0.01). Behind the bottom wall, ghosts down to 3 dx deep would take
// -(d_g / d_near)(u_near - w), i.e. up to -(0.15 / 0.001) 0.011 = -1.65, faster than the lid. With
// d_near held at dx/2 they take at most (0.15 / 0.025) 0.011 = 0.066. The error against the slipping
// profile's continuation y + 0.01 is then about 0.08 at both walls. The bound of 0.5 sits between
// that and the 4.3 measured without the bound.
TEST_CASE("wall velocity: linear extrapolation from a particle pressed against the wall stays bounded") {
  const std::vector<std::string> pressed = {"initial.offset=[\"0\", \"-0.024*(y < 0.03)\"]",
                                            "initial.velocity=[\"y + 0.01\", \"0\"]",
                                            "boundary.top.velocity=[1, 0]"};
  const GhostError e = ghost_error("linear", pressed, [](double y) { return y + 0.01; });
  MESSAGE("largest ghost error behind the walls: " << e.max_abs);
  CHECK(e.count > 0);
  CHECK(e.max_abs < 0.5);
}
