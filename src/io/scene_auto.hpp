// The `auto` values of scene keys whose right value depends on the scheme or on other keys,
// resolved once after the scene is read: the scene then holds the value the run uses, which the
// run header, summary.json and the resolved scene show.
#pragma once
#include "core/scene.hpp"

namespace arksph {

// method.projection, method.regularisation, method.density_diffusion.
void resolve_auto_values(Scene& s);

}  // namespace arksph
