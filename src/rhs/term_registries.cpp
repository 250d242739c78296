// The registered right-hand-side parts: one line each, in the order `arksph list` shows them.
#include "rhs/term_registry.hpp"

namespace arksph {

Part<TermFactory> viscosity_morris();
Part<TermFactory> viscosity_monaghan();
Part<TermFactory> viscosity_direct();
Part<TermFactory> viscosity_two_pass();
Part<TermFactory> viscosity_violeau();
Part<TermFactory> viscosity_cleary();
Part<TermFactory> pressure_gradient_colagrossi();
Part<TermFactory> pressure_gradient_monaghan();
Part<TermFactory> kernel_correction_none();
Part<TermFactory> kernel_correction_shepard();
Part<TermFactory> kernel_correction_bonet_lok();
Part<TermFactory> equation_of_state_tait();
Part<TermFactory> equation_of_state_ideal_gas();
Part<TermFactory> density_continuity();
Part<TermFactory> density_summation();

const Registry<TermFactory>& viscosity_models() {
  static const Registry<TermFactory> r("viscosity_model", "method.viscosity_model", {
      viscosity_morris(),
      viscosity_monaghan(),
      viscosity_direct(),
      viscosity_two_pass(),
      viscosity_violeau(),
      viscosity_cleary(),
  });
  return r;
}

const Registry<TermFactory>& pressure_gradients() {
  static const Registry<TermFactory> r("pressure_gradient", "method.pressure_gradient", {
      pressure_gradient_colagrossi(),
      pressure_gradient_monaghan(),
  });
  return r;
}

const Registry<TermFactory>& kernel_corrections() {
  static const Registry<TermFactory> r("kernel_correction", "method.kernel_correction", {
      kernel_correction_none(),
      kernel_correction_shepard(),
      kernel_correction_bonet_lok(),
  });
  return r;
}

const Registry<TermFactory>& equations_of_state() {
  static const Registry<TermFactory> r("equation_of_state", "method.equation_of_state", {
      equation_of_state_tait(),
      equation_of_state_ideal_gas(),
  });
  return r;
}

const Registry<TermFactory>& density_modes() {
  static const Registry<TermFactory> r("density_mode", "method.density_mode", {
      density_continuity(),
      density_summation(),
  });
  return r;
}

}  // namespace arksph
