// Ideal-gas equation of state (Basa et al. 2008 eq. 12) with the energy equation (eq. 14) in the
// ODE state: initial pressure and total-energy conservation of the symmetric pair.
#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <sstream>

#include "run/setup.hpp"
#include "io/scene_reader.hpp"
#include "rhs/terms.hpp"
#include "test_support.hpp"

using namespace arksph;

TEST_CASE("ideal gas: energy block in the state, p(0) = rho c^2 / gamma") {
  std::ostringstream w;
  const Scene scene = read_scene_text(testing::kTaylorGreenBox + "[time]\nend = 0.05\n", "test",
                                      {"method.equation_of_state=ideal_gas"}, w);
  Model model = build_model(scene);
  const auto& L = model.rhs->layout();
  CHECK(L.has_energy);
  CHECK(L.size() == 6 * L.n);  // x, y, u, v, rho, e
  std::vector<double> y(L.size()), ydot(y.size());
  model.rhs->initial_state(y.data());
  model.rhs->eval(0.0, y.data(), ydot.data());
  // sound_speed = 10 in the box: p = (gamma - 1) rho e = rho c^2 / gamma (relative round-off 1e-14).
  CHECK(std::abs(model.rhs->fields().p[3] - 100.0 / 1.4) < 1e-14 * 100.0);
  const std::vector<std::string> expect_in = {"eos:ideal_gas", "energy:basa14"};
  for (const auto& t : expect_in) CHECK(std::find(model.terms.begin(), model.terms.end(), t) != model.terms.end());
  CHECK(std::find(model.terms.begin(), model.terms.end(), "eos:tait") == model.terms.end());
  // ISPH has no equation of state: bad input.
  CHECK_THROWS(read_scene_text(testing::kTaylorGreenBox + "[time]\nend = 0.05\n", "test",
                               {"method.equation_of_state=ideal_gas", "method.scheme=isph"}, w));
}

// Without viscosity, eq. 14 paired with the momentum form of Basa eq. 8 (pressure_gradient =
// monaghan) conserves total energy sum_a m_a (e_a + |u_a|^2 / 2) exactly: the pair terms cancel.
// Ratio of the rate to sum_a m_a (|de_a/dt| + |u_a . du_a/dt|): round-off, 1e-13 as in the momentum test.
TEST_CASE("ideal gas: the energy equation conserves total energy with the symmetric pressure term") {
  for (const std::string dm : {"continuity", "summation"}) {
    std::ostringstream w;
    const Scene scene = read_scene_text(testing::kTaylorGreenBox + "[time]\nend = 0.05\n", "test",
                                        {"method.equation_of_state=ideal_gas", "fluid.viscosity=0",
                                         "method.pressure_gradient=monaghan", "method.density_mode=" + dm}, w);
    Model model = build_model(scene);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> r(-1, 1);
    const ParticleSet ps = testing::jittered(scene, model.particles, rng);
    RhsEvaluator rhs(scene, ps, make_kernel(scene.kernel, model.h, 2), terms_from_scene(scene, model.sound_speed));
    const auto& L = rhs.layout();
    std::vector<double> y(L.size()), ydot(y.size());
    rhs.initial_state(y.data());
    for (std::size_t a = 0; a < ps.n; ++a) y[L.energy() + a] *= 1.0 + 0.05 * r(rng);
    rhs.eval(0.0, y.data(), ydot.data());
    double rate = 0, scale = 0;
    for (std::size_t a = 0; a < ps.n; ++a) {
      const double de = ydot[L.energy() + a];
      const double work = y[L.vel(0) + a] * ydot[L.vel(0) + a] + y[L.vel(1) + a] * ydot[L.vel(1) + a];
      rate += ps.mass[a] * (de + work);
      scale += ps.mass[a] * (std::abs(de) + std::abs(work));
    }
    MESSAGE(dm << ": |d/dt total energy| / scale = " << std::abs(rate) / scale);
    CHECK(scale > 1e-3);
    CHECK(std::abs(rate) / scale < 1e-13);
  }
}
