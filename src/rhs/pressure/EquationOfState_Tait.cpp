// Tait equation of state, Cummins & Rudman 1999 eq. 7 (Szewc et al. 2012 eq. 26):
//   p = c^2 rho0 / gamma * ((rho / rho0)^gamma - 1) + p_b,  rho0 the reference density of the phase,
// p_b an optional background pressure (Morris et al. 1997) that keeps p > 0 against tensile clumping.
#include <cmath>

#include "rhs/term_registry.hpp"
#include "rhs/terms.hpp"

namespace arksph {

class EquationOfStateTait final : public Term {
 public:
  EquationOfStateTait(double sound_speed, double gamma, double background)
      : c2_(sound_speed * sound_speed), gamma_(gamma), background_(background) {}
  std::string name() const override { return "eos:tait"; }
  Stage stage() const override { return Stage::pressure; }
  bool uses_neighbors() const override { return false; }
  void apply(FluidFields& f) const override {
    if (gamma_ == 7.0)
      pressures(f, [](double r) {  // r^7 in four products, within a few ulp of pow: no libm call, the loop vectorises
        const double r2 = r * r;
        return (r2 * r2) * (r2 * r);
      });
    else
      pressures(f, [g = gamma_](double r) { return std::pow(r, g); });
  }

 private:
  template <class Power>
  void pressures(FluidFields& f, Power power) const {
#pragma omp parallel for schedule(static) if (f.n_real > 5000)  // cheaper than a thread wake-up below
    for (std::size_t a = 0; a < f.n_real; ++a) {
      const double ratio = f.rho[a] / f.rho0[a];
      const double stiffness = c2_ * f.rho0[a] / gamma_;
      f.p[a] = stiffness * (power(ratio) - 1.0) + background_;
    }
  }

  double c2_, gamma_, background_;
};

std::unique_ptr<Term> make_eos_tait(double sound_speed, double gamma, double background) {
  return std::make_unique<EquationOfStateTait>(sound_speed, gamma, background);
}

// Tait's parameters; method.sound_speed is resolved at set-up (resolve_sound_speed), and the
// factory is given the result.
Part<CompressibleTermsFactory> equation_of_state_tait() {
  return {"tait", "Tait equation of state (Cummins & Rudman 1999 eq. 7, Basa et al. 2008 eq. 13)",
          [](const Scene& scene, double sound_speed) {
            std::vector<std::unique_ptr<Term>> terms;
            terms.push_back(make_eos_tait(sound_speed, scene.tait_gamma, scene.background_pressure));
            return terms;
          },
          {number("method.sound_speed", 0.0).in(at_least(0)).unit("m/s").schemes({"wcsph"})
               .doc("WCSPH sound speed c0; 0: 10 x the reference speed (walls, initial speeds, sqrt(|g| L))")
               .to(&Scene::sound_speed),
           number("method.tait_gamma", 7.0).in(at_least(1))
               .doc("exponent gamma of the Tait equation (Cummins & Rudman 1999 eq. 7)").to(&Scene::tait_gamma),
           number("method.background_pressure", 0.0).in(at_least(0)).unit("Pa")
               .doc("constant added to the Tait pressure (Morris et al. 1997); keeps p > 0 at the walls")
               .to(&Scene::background_pressure)},
          {.tait = true}};
}

}  // namespace arksph
