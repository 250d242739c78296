// Ideal-gas equation of state, Basa et al. 2008 eq. 12, p = rho R T, written with the specific
// internal energy e = c_v T of a gas with ratio of specific heats gamma:
//   p = (gamma - 1) rho e.
// e is part of the ODE state (the energy equation 14, Energy_Basa2008.cpp). setup.cpp chooses
// e(0) = c^2 / (gamma (gamma - 1)), so that the initial sound speed sqrt(gamma p / rho) is the
// scene's c (Basa: 125 kPa at rho = 1, i.e. c = 418 m/s for gamma = 1.4).
#include "rhs/term_registry.hpp"
#include "rhs/terms.hpp"

namespace arksph {

class EquationOfStateIdealGas final : public Term {
 public:
  explicit EquationOfStateIdealGas(double gamma) : gamma_(gamma) {}
  std::string name() const override { return "eos:ideal_gas"; }
  Stage stage() const override { return Stage::pressure; }
  bool uses_neighbors() const override { return false; }
  void apply(FluidFields& f) const override {
    for (std::size_t a = 0; a < f.n_real; ++a) f.p[a] = (gamma_ - 1.0) * f.rho[a] * f.e[a];
  }

 private:
  double gamma_;
};

std::unique_ptr<Term> make_eos_ideal_gas(double gamma) { return std::make_unique<EquationOfStateIdealGas>(gamma); }

Part<CompressibleTermsFactory> equation_of_state_ideal_gas() {
  return {"ideal_gas", "ideal gas p = (gamma - 1) rho e, with the energy equation in the state (Basa et al. 2008 eqs. 12, 14)",
          [](const Scene& scene, double) {
            std::vector<std::unique_ptr<Term>> terms;
            terms.push_back(make_eos_ideal_gas(scene.gas_gamma));
            terms.push_back(make_energy_equation());
            return terms;
          },
          {number("method.gas_gamma", 1.4).in(above(1))
               .doc("ideal_gas: ratio of specific heats; e(0) is chosen so that the sound speed is method.sound_speed")
               .to(&Scene::gas_gamma)},
          {.schemes = {"wcsph"}, .state = {"energy"}}};
}

}  // namespace arksph
