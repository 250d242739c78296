// Wall reflection between steps (boundary/wall_reflection): position and normal velocity mirrored
// about the wall, moving walls included, periodic sides left alone.
#include <doctest/doctest.h>

#include "boundary/wall_reflection.hpp"
#include "io/scene_defaults.hpp"

using namespace arksph;

TEST_CASE("wall reflection: a particle beyond a wall comes back mirrored, others are untouched") {
  Scene s = scene_defaults();
  s.min = {0, 0};
  s.max = {1, 1};
  s.sides[3].velocity = {1.0, 0.5};     // top wall moving (normal velocity 0.5, for the check)
  s.sides[0].kind = SideKind::periodic;  // left/right periodic: never reflected
  s.sides[1].kind = SideKind::periodic;
  StateLayout L;
  L.n = 3;
  L.dim = 2;
  // particle 0 inside; 1 below the bottom wall; 2 above the top wall; all outside in x (periodic)
  std::vector<double> y = {/*x*/ 0.5, -0.2, 1.3, /*y*/ 0.5, -0.01, 1.02, /*u*/ 0.1, 0.2, 0.3, /*v*/ 0.1, -0.4, 0.7};
  const WallReflection r(s, L);
  CHECK(r.apply(y.data()) == 2);
  // x untouched (periodic), y mirrored about 0 and 1; v mirrored about w_n (0 and 0.5); u untouched.
  CHECK(y[0] == 0.5);
  CHECK(y[1] == -0.2);
  CHECK(y[2] == 1.3);
  CHECK(y[3] == 0.5);
  CHECK(y[4] == doctest::Approx(0.01).epsilon(1e-15));
  CHECK(y[5] == doctest::Approx(0.98).epsilon(1e-15));
  CHECK(y[6] == 0.1);
  CHECK(y[9] == 0.1);
  CHECK(y[10] == doctest::Approx(0.4).epsilon(1e-15));
  CHECK(y[11] == doctest::Approx(2 * 0.5 - 0.7).epsilon(1e-15));
  CHECK(r.apply(y.data()) == 0);  // idempotent once inside
}
