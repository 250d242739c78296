// The IMEX dependency pattern found by the cell list (with periodic copies) against the all-pairs
// minimum-image search it replaces: the two must agree entry for entry (the same exact distance test
// decides both, so no tolerance: any difference is a missed or extra coupling).
#include <doctest/doctest.h>

#include <random>

#include "run/setup.hpp"
#include "integrate/dependency_pattern.hpp"
#include "integrate/viscous_jacobian.hpp"
#include "io/scene_reader.hpp"
#include "test_support.hpp"

using namespace arksph;

namespace {
// Pattern of the scene's particles jittered by +-0.3 dx (a few pushed 0.2 dx outside the box, as in a
// stage before the wall reflection), at the Jacobian's dependency radius plus its skin of dx / 2.
void check_against_brute(const std::string& toml, const std::vector<std::string>& sets) {
  std::ostringstream warnings;
  const Scene scene = read_scene_text(toml, "pattern_scene", sets, warnings);
  Model model = build_model(scene);
  const ViscousJacobian jac(scene, *model.rhs);
  const double radius = jac.dependency_radius() + 0.5 * scene.spacing;
  ParticleSet ps = model.particles;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> jitter(-0.3 * scene.spacing, 0.3 * scene.spacing);
  for (std::size_t a = 0; a < ps.n; ++a)
    for (int k = 0; k < 2; ++k) ps.init_pos[k][a] += jitter(rng);
  ps.init_pos[0][0] = scene.min[0] - 0.2 * scene.spacing;
  ps.init_pos[1][ps.n - 1] = scene.max[1] + 0.2 * scene.spacing;
  PeriodicAxes axes;
  for (int k = 0; k < 2; ++k) {
    axes.periodic[k] = scene.sides[2 * k].kind == SideKind::periodic;
    axes.len[k] = scene.max[k] - scene.min[k];
  }
  const double* x = ps.init_pos[0].data();
  const double* y = ps.init_pos[1].data();
  const auto fast = dependency_pattern(x, y, ps.n, radius, axes);
  const auto brute = dependency_pattern_brute(x, y, ps.n, radius, axes);
  REQUIRE(fast.size() == brute.size());
  std::size_t differing = 0, entries = 0;
  for (std::size_t a = 0; a < ps.n; ++a) {
    differing += fast[a] != brute[a];
    entries += brute[a].size();
  }
  MESSAGE(scene.name, ": ", ps.n, " particles, ", entries, " pattern entries");
  CHECK(entries > ps.n);  // not trivially the diagonal
  CHECK(differing == 0);
}
}  // namespace

TEST_CASE("imex pattern: the cell-list search equals the all-pairs search, walled and periodic scenes") {
  SUBCASE("walled cavity, mirror and linear wall velocity (larger dependency radius)") {
    check_against_brute(default_scene_toml(), {"fluid.spacing=0.05"});
    check_against_brute(default_scene_toml(), {"fluid.spacing=0.05", "boundary.wall_velocity=linear"});
  }
  SUBCASE("doubly periodic box, also with a radius above half the period (two-pass model)") {
    check_against_brute(testing::kTaylorGreenBox + "[time]\nend = 0.1\n", {});
    check_against_brute(testing::kTaylorGreenBox + "[time]\nend = 0.1\n",
                        {"fluid.spacing=0.125", "method.viscosity_model=two_pass"});
  }
}

TEST_CASE("imex pattern: 1D periodic points, cell list equals all pairs") {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> pos(-0.01, 1.01);
  std::vector<double> x(200);
  for (double& v : x) v = pos(rng);
  for (const bool periodic : {false, true}) {
    PeriodicAxes axes;
    axes.periodic[0] = periodic;
    CHECK(dependency_pattern(x.data(), nullptr, x.size(), 0.03, axes) ==
          dependency_pattern_brute(x.data(), nullptr, x.size(), 0.03, axes));
  }
}
