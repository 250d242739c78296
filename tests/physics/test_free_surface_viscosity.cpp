// The viscous dissipation at a free surface: the power of the viscous term on the potential flow of a
// standing wave against the exact dissipation of that flow.
//
// The first sloshing mode of a layer H deep in a tank L long with free-slip walls (cases/standing_wave)
// starts from a flat surface with the potential flow phi = B cosh(k y) cos(k x), k = pi / L, at its
// largest. Its dissipation is 2 mu int e:e dV = 2 mu B^2 k^4 L sinh(2kH) / (2k), and its kinetic
// energy rho B^2 k^2 L sinh(2kH) / (8k), so dE/dt = -8 nu k^2 E at that instant: the rate that,
// averaged over a period with the energy shared with the surface's potential energy, gives Lamb's
// amplitude decay exp(-2 nu k^2 t) (Hydrodynamics §348). A viscous term whose power is half of it
// makes the wave decay at half Lamb's rate.
#include <doctest/doctest.h>

#include <cstddef>
#include <sstream>
#include <string>
#include <vector>

#include "io/scene_reader.hpp"
#include "run/setup.hpp"

using namespace arksph;

namespace {

const std::string kStandingWave = R"toml(
[scene]
name = "standing_wave"
[domain]
min = [0.0, 0.0]
max = [2.0, 1.5]
[boundary]
left   = { kind = "wall", slip = "free_slip" }
right  = { kind = "wall", slip = "free_slip" }
bottom = { kind = "wall", slip = "free_slip" }
top    = { kind = "wall", slip = "free_slip" }
[fluid]
spacing = 0.05
region = "y < 1"
viscosity = 0.005
body_force = ["0", "-1"]
[initial]
hydrostatic = true
velocity = ["-0.0052156*cosh(pi/2*y)*sin(pi/2*x)", "0.0052156*sinh(pi/2*y)*cos(pi/2*x)"]
[method]
scheme = "wcsph"
[time]
end = 1
)toml";

struct Power {
  double viscous = 0;  // sum_a m_a u_a . (du/dt)_viscous
  double kinetic = 0;  // sum_a m_a |u_a|^2 / 2
};

// The state of the scene at t = 0, the particles' masses and du/dt, dv/dt (in the state's order).
struct Rates {
  std::vector<double> y, mass, accel;
  std::size_t n = 0;
};
Rates rates_at_start(const std::vector<std::string>& sets) {
  std::ostringstream w;
  const Model model = build_model(read_scene_text(kStandingWave, "test", sets, w));
  const StateLayout& L = model.rhs->layout();
  Rates r;
  r.n = L.n;
  r.y.resize(L.size());
  std::vector<double> ydot(L.size());
  model.rhs->initial_state(r.y.data());
  model.rhs->eval(0.0, r.y.data(), ydot.data());
  r.mass = model.particles.mass;
  r.accel.assign(ydot.begin() + static_cast<std::ptrdiff_t>(L.vel(0)), ydot.begin() + static_cast<std::ptrdiff_t>(L.vel(0) + 2 * L.n));
  return r;
}

// The viscous term's power: du/dt with the viscosity less du/dt without it, on the same state.
Power viscous_power(const std::vector<std::string>& sets) {
  std::vector<std::string> inviscid = sets;
  inviscid.push_back("fluid.viscosity=0");
  const Rates with = rates_at_start(sets), without = rates_at_start(inviscid);
  REQUIRE(with.y == without.y);
  Power p;
  const std::size_t n = with.n;
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t k = 0; k < 2; ++k) {
      const double u = with.y[(2 + k) * n + a];  // velocities follow the positions (StateLayout::vel)
      p.kinetic += 0.5 * with.mass[a] * u * u;
      p.viscous += with.mass[a] * u * (with.accel[k * n + a] - without.accel[k * n + a]);
    }
  return p;
}

}  // namespace

TEST_CASE("free surface: the default viscous term dissipates a standing wave's energy at the exact rate") {
  const double nu = 0.005, k = 3.14159265358979 / 2.0;
  // 20 %: the issue's tolerance on the decay rate; what is left is the cut support's error, which the
  // pair form keeps to a few per cent at both spacings.
  for (const std::string spacing : {"0.05", "0.025"}) {
    CAPTURE(spacing);
    const Power p = viscous_power({"fluid.spacing=" + spacing});
    const double exact = -8.0 * nu * k * k * p.kinetic;
    MESSAGE("dx " << spacing << ": viscous power / exact " << p.viscous / exact);
    CHECK(p.viscous / exact == doctest::Approx(1.0).epsilon(0.2));
  }
  // The check can fail: Morris' form, summed over the support the surface cuts, dissipates about
  // half (the wave then decays at about half Lamb's rate).
  const Power morris = viscous_power({"method.viscosity_model=morris"});
  const double ratio = morris.viscous / (-8.0 * nu * k * k * morris.kinetic);
  MESSAGE("morris: viscous power / exact " << ratio);
  CHECK(ratio < 0.8);
}
