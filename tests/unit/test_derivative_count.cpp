// RhsOptions::derivative_count: a rank of a decomposed run wants the derivatives of its own
// particles only (the first n), not of its halo copies. The first n must keep the bits of an
// evaluation over all particles, and the force sweep must really skip the others.
#include <doctest/doctest.h>

#include <random>
#include <sstream>
#include <vector>

#include "io/scene_reader.hpp"
#include "rhs/terms.hpp"
#include "run/setup.hpp"
#include "test_support.hpp"

using namespace arksph;

namespace {

// ydot of the scene's right-hand side on its jittered lattice (test_support.hpp) with densities
// perturbed by 1 %, the force sweep restricted to the first `count` particles.
struct Derivatives {
  StateLayout layout;
  std::vector<double> ydot;
};
Derivatives derivatives(const Scene& scene, std::size_t count) {
  Model model = build_model(scene);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> vel(-1, 1);
  const ParticleSet ps = testing::jittered(scene, model.particles, rng);
  RhsOptions options;
  options.derivative_count = count;
  RhsEvaluator rhs(scene, ps, make_kernel(scene.kernel, model.h, 2), terms_from_scene(scene, model.sound_speed), options);
  std::vector<double> y(rhs.layout().size()), ydot(y.size());
  rhs.initial_state(y.data());
  if (rhs.layout().has_density)
    for (std::size_t a = 0; a < ps.n; ++a) y[rhs.layout().rho() + a] *= 1.0 + 0.01 * vel(rng);
  rhs.eval(0.0, y.data(), ydot.data());
  return {rhs.layout(), ydot};
}

}  // namespace

TEST_CASE("derivative_count: the first n particles keep their bits, the others are not swept") {
  // The WCSPH default f (shifting and delta-SPH fused with the pressure gradient, continuity and
  // viscosity in one sweep), on the doubly periodic box and on a walled cavity (wall ghosts).
  const std::string cavity = testing::slurp(std::string(ARKSPH_SOURCE_DIR) + "/cases/cavity_re100/scene.toml");
  for (const auto& [name, text, sets] :
       {std::tuple{"periodic box", testing::kTaylorGreenBox,
                   std::vector<std::string>{"method.regularisation=\"auto\"", "method.density_diffusion=\"auto\"",
                                            "time.end=1"}},
        std::tuple{"cavity", cavity, std::vector<std::string>{"fluid.spacing=0.05"}}}) {
    const std::string what = name;
    CAPTURE(what);
    std::ostringstream warnings;
    const Scene scene = read_scene_text(text, "test", sets, warnings);
    const Derivatives full = derivatives(scene, static_cast<std::size_t>(-1));
    const StateLayout& L = full.layout;
    REQUIRE(L.n > 20);
    REQUIRE(L.has_density);  // the continuity equation: its rate is a force-stage sum too
    const std::size_t half = L.n / 2;
    const Derivatives part = derivatives(scene, half);
    const std::vector<double>&all = full.ydot, &some = part.ydot;
    long same = 0, untouched = 0;
    const std::size_t blocks = L.size() / L.n;  // x, y, u, v, rho
    for (std::size_t block = 0; block < blocks; ++block)
      for (std::size_t a = 0; a < half; ++a) same += all[block * L.n + a] == some[block * L.n + a] ? 1 : 0;
    CHECK(same == static_cast<long>(blocks * half));  // every entry of the first half, bit for bit
    // The velocity derivatives of the second half: the sweep did not reach them.
    for (std::size_t a = half; a < L.n; ++a)
      untouched += (some[L.vel(0) + a] != all[L.vel(0) + a] || some[L.vel(1) + a] != all[L.vel(1) + a]) ? 1 : 0;
    CHECK(untouched == static_cast<long>(L.n - half));
  }
}
