// Registries of the right-hand-side families a scene selects by name (rhs/term_registries.cpp lists
// the parts, one line each; every part is defined in its own file with its parameters and traits).
#pragma once
#include <memory>
#include <vector>

#include "core/param_builder.hpp"
#include "core/registry.hpp"
#include "core/scene.hpp"
#include "rhs/term.hpp"

namespace arksph {

// Builds a part's term from the resolved scene (its parameters included).
using TermFactory = std::unique_ptr<Term> (*)(const Scene&);
// Builds the terms of a weakly compressible part from the resolved scene and the sound speed
// resolved at set-up: an equation of state (the pressure, and what it needs in the state, such as
// the energy equation), density diffusion.
using CompressibleTermsFactory = std::vector<std::unique_ptr<Term>> (*)(const Scene&, double sound_speed);

const Registry<TermFactory>& viscosity_models();    // method.viscosity_model
const Registry<TermFactory>& pressure_gradients();  // method.pressure_gradient
const Registry<TermFactory>& kernel_corrections();  // method.kernel_correction ("none": no factory)
const Registry<CompressibleTermsFactory>& equations_of_state();  // method.equation_of_state
// Trait .state = {"density"}: the density in the ODE state (a rate, built after the pressure
// gradient); else a density computed before the terms that read it.
const Registry<TermFactory>& density_modes();       // method.density_mode
const Registry<TermFactory>& regularisations();     // method.regularisation ("none": no factory)
const Registry<CompressibleTermsFactory>& density_diffusions();  // method.density_diffusion ("none": no factory)
const Registry<TermFactory>& wall_forces();         // boundary.wall_force ("none": no factory)

}  // namespace arksph
