// The rules for the tangential velocity of no-slip wall ghosts (boundary.wall_velocity), registered
// by name. "mirror" is the ghost construction itself (boundary/ghosts.hpp); the others overwrite
// the mirrored value afterwards (WallVelocity_*_Basa2008.hpp).
#pragma once
#include "core/registry.hpp"

namespace arksph {

const Registry<Selected>& wall_velocity_rules();

}  // namespace arksph
