// ParticleOde (run/particle_ode.hpp), the particle system behind the Python module: outside, the
// state in the order of increasing id; inside, the particles in cell order. Checked against the
// evaluator on the particles in their initial order, mapped particle by particle through the ids.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "io/scene_reader.hpp"
#include "run/particle_ode.hpp"

using namespace arksph;

namespace {

// The embedded cavity, WCSPH, 20 x 20, in a shuffled initial order (ids, memory order and cell
// order all differ), with a compressive initial velocity so that every block of f is non-zero.
Scene shuffled_cavity() {
  return read_scene_text(default_scene_toml(), "<embedded default>",
                         {"fluid.spacing=0.05", "method.scheme=\"wcsph\"", "fluid.shuffle_initial_order=true",
                          "initial.velocity=[\"x*y\", \"x - y\"]"});
}

// The outside index of each particle of `ids`: its rank among them.
std::vector<std::size_t> ranks(const std::vector<std::int64_t>& ids) {
  std::vector<std::int64_t> sorted = ids;
  std::sort(sorted.begin(), sorted.end());
  std::vector<std::size_t> r(ids.size());
  for (std::size_t a = 0; a < ids.size(); ++a)
    r[a] = static_cast<std::size_t>(std::lower_bound(sorted.begin(), sorted.end(), ids[a]) - sorted.begin());
  return r;
}

}  // namespace

TEST_CASE("particle ode: y0 and f in id order are the evaluator's on the particles in their initial order") {
  const Scene scene = shuffled_cavity();
  ParticleOde ode(scene);
  Model reference = build_model(scene);
  const StateLayout& L = reference.rhs->layout();
  REQUIRE(ode.layout().size() == L.size());
  const std::vector<std::size_t> outside = ranks(reference.particles.id);
  bool shuffled = false;  // the test means something only if the orders differ
  for (std::size_t a = 0; a < L.n; ++a) shuffled |= outside[a] != a;
  REQUIRE(shuffled);
  CHECK(std::is_sorted(ode.ids().begin(), ode.ids().end()));

  std::vector<double> y(L.size()), f(L.size());
  reference.rhs->initial_state(y.data());
  reference.rhs->eval(0.0, y.data(), f.data());
  std::vector<double> g(L.size());
  ode.rhs(0.0, ode.initial_state().data(), g.data());

  // y0: copies of the initial values, exact. f: the same sums in another order (cell order inside),
  // so equal to round-off: 1e-12 of the largest entry of the block.
  const std::size_t blocks = L.size() / L.n;
  for (std::size_t b = 0; b < blocks; ++b) {
    double scale = 0, worst = 0;
    for (std::size_t a = 0; a < L.n; ++a) scale = std::max(scale, std::abs(f[b * L.n + a]));
    for (std::size_t a = 0; a < L.n; ++a) {
      CHECK(ode.initial_state()[b * L.n + outside[a]] == y[b * L.n + a]);
      worst = std::max(worst, std::abs(g[b * L.n + outside[a]] - f[b * L.n + a]));
    }
    CAPTURE(b);
    CHECK(scale > 0);
    CHECK(worst <= 1e-12 * scale);
  }
}

TEST_CASE("particle ode: a NaN in y is refused with its index, block and particle id") {
  ParticleOde ode(shuffled_cavity());
  std::vector<double> y = ode.initial_state(), f(y.size());
  const std::size_t at = ode.layout().vel(1) + 3;
  y[at] = std::nan("");
  try {
    ode.rhs(0.0, y.data(), f.data());
    FAIL("no error for a NaN");
  } catch (const InputError& e) {
    const std::string what = e.what();
    CHECK(what.find("y[" + std::to_string(at) + "] is NaN") != std::string::npos);
    CHECK(what.find("block v") != std::string::npos);
    CHECK(what.find("particle id " + std::to_string(ode.ids()[3])) != std::string::npos);
  }
}

TEST_CASE("particle ode: the projection after a step is refused where the scene has none") {
  ParticleOde ode(shuffled_cavity());
  std::vector<double> y = ode.initial_state();
  CHECK_FALSE(ode.has_projection());
  CHECK_THROWS_AS(ode.project(0.0, y.data(), 1e-3, y.data()), InputError);
}
