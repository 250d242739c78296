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
Part<CompressibleTermsFactory> equation_of_state_tait();
Part<CompressibleTermsFactory> equation_of_state_ideal_gas();
Part<TermFactory> density_continuity();
Part<TermFactory> density_summation();
Part<TermFactory> regularisation_none();
Part<TermFactory> regularisation_shifting();
Part<TermFactory> regularisation_transport_velocity();
Part<CompressibleTermsFactory> density_diffusion_none();
Part<CompressibleTermsFactory> density_diffusion_delta_sph();
Part<TermFactory> wall_force_none();
Part<TermFactory> wall_force_lennard_jones();
AutomaticRule automatic_viscosity_model();
AutomaticRule automatic_density_mode();
AutomaticRule automatic_density_diffusion();
AutomaticRule automatic_regularisation();

const Registry<TermFactory>& viscosity_models() {
  static const Registry<TermFactory> r("viscosity_model", "method.viscosity_model", {
      viscosity_morris(),
      viscosity_monaghan(),
      viscosity_direct(),
      viscosity_two_pass(),
      viscosity_violeau(),
      viscosity_cleary(),
  }, {}, automatic_viscosity_model());
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

const Registry<CompressibleTermsFactory>& equations_of_state() {
  static const Registry<CompressibleTermsFactory> r("equation_of_state", "method.equation_of_state", {
      equation_of_state_tait(),
      equation_of_state_ideal_gas(),
  });
  return r;
}

const Registry<TermFactory>& density_modes() {
  static const Registry<TermFactory> r("density_mode", "method.density_mode", {
      density_continuity(),
      density_summation(),
  }, {}, automatic_density_mode());
  return r;
}

const Registry<TermFactory>& regularisations() {
  static const Registry<TermFactory> r("regularisation", "method.regularisation", {
      regularisation_none(),
      regularisation_shifting(),
      regularisation_transport_velocity(),
  }, {}, automatic_regularisation());
  return r;
}

const Registry<CompressibleTermsFactory>& density_diffusions() {
  static const Registry<CompressibleTermsFactory> r("density_diffusion", "method.density_diffusion", {
      density_diffusion_none(),
      density_diffusion_delta_sph(),
  }, {}, automatic_density_diffusion());
  return r;
}

Part<TermFactory> regularisation_none() { return {"none", "particles move with the fluid velocity, dr/dt = u"}; }

const Registry<TermFactory>& wall_forces() {
  static const Registry<TermFactory> r("wall_force", "boundary.wall_force", {
      wall_force_none(),
      wall_force_lennard_jones(),
  });
  return r;
}

}  // namespace arksph
