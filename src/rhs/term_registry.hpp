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
// Builds an equation of state's terms (the pressure, and what it needs in the state, such as the
// energy equation) from the resolved scene and the sound speed resolved at set-up.
using EquationOfStateFactory = std::vector<std::unique_ptr<Term>> (*)(const Scene&, double sound_speed);

const Registry<TermFactory>& viscosity_models();    // method.viscosity_model
const Registry<TermFactory>& pressure_gradients();  // method.pressure_gradient
const Registry<TermFactory>& kernel_corrections();  // method.kernel_correction ("none": no factory)
const Registry<EquationOfStateFactory>& equations_of_state();  // method.equation_of_state
// Selected by name, built by terms_from_scene: no factories.
const Registry<TermFactory>& density_modes();       // method.density_mode
const Registry<TermFactory>& regularisations();     // method.regularisation ("none": no factory)
// Built by terms_from_scene with the resolved sound speed (make_density_diffusion).
const Registry<TermFactory>& density_diffusions();  // method.density_diffusion
const Registry<TermFactory>& wall_forces();         // boundary.wall_force ("none": no factory)

}  // namespace arksph
