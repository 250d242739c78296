// Particles on the wall (boundary.wall_particles, Basa et al. 2008 §6.1.2): one particle at the
// nearest wall point of every fluid particle closer than dx to a no-slip wall, carrying the wall
// velocity whatever the fluid does, with the periodic images along the wall.
#include <doctest/doctest.h>

#include <cmath>
#include <sstream>

#include "run/setup.hpp"
#include "io/scene_reader.hpp"

using namespace arksph;

namespace {
// Channel periodic in x, walls at y = 0 (moving at 0.7) and y = 1, 20 x 20 particles.
const std::string kWallParticlesChannel = R"toml(
[scene]
name = "wall_particles"
[domain]
min = [0.0, 0.0]
max = [1.0, 1.0]
[boundary]
left = { kind = "periodic" }
right = { kind = "periodic" }
bottom = { kind = "wall", velocity = [0.7, 0.0] }
top = { kind = "wall" }
[fluid]
spacing = 0.05
viscosity = 1
[initial]
velocity = ["sin(5*x) + y", "cos(3*y)"]
[method]
kernel = "quintic_spline"
h_over_dx = 1.0
sound_speed = 10
[time]
end = 1
)toml";

struct OnWall {
  int bottom = 0, top = 0;
  double worst_velocity = 0;  // max |u - w| over the points on the walls
};

OnWall points_on_walls(const std::vector<std::string>& sets) {
  std::ostringstream w;
  const Scene scene = read_scene_text(kWallParticlesChannel, "test", sets, w);
  Model model = build_model(scene);
  std::vector<double> y(model.rhs->layout().size()), ydot(y.size());
  model.rhs->initial_state(y.data());
  model.rhs->eval(0.0, y.data(), ydot.data());
  const FluidFields& f = model.rhs->fields();
  OnWall o;
  for (std::size_t i = f.n_real; i < f.n_all; ++i) {
    const bool bottom = f.y[i] == 0.0, top = f.y[i] == 1.0;  // exactly on the wall line
    if (!bottom && !top) continue;
    (bottom ? o.bottom : o.top)++;
    const double wu = bottom ? 0.7 : 0.0;
    o.worst_velocity = std::max(o.worst_velocity, std::max(std::abs(f.u[i] - wu), std::abs(f.v[i])));
  }
  return o;
}
}  // namespace

TEST_CASE("wall particles: one per near-wall fluid particle, on the wall, with the wall velocity") {
  const OnWall off = points_on_walls({});
  CHECK(off.bottom + off.top == 0);  // mirror ghosts lie dx/2, 3dx/2, ... behind the walls, never on them
  for (const char* rule : {"mirror", "linear", "quadratic"}) {
    const OnWall on = points_on_walls({"boundary.wall_particles=true", std::string("boundary.wall_velocity=") + rule});
    INFO(rule);
    // 20 near-wall particles per wall, plus the periodic images of those within the support
    // radius 3 dx of the left or right side (3 per side and wall).
    CHECK(on.bottom == 26);
    CHECK(on.top == 26);
    CHECK(on.worst_velocity == 0.0);  // exactly w (map s = 0, b = w), untouched by the extrapolations
  }
}
