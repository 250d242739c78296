// The rules for the tangential velocity of no-slip wall ghosts (boundary.wall_velocity), registered
// by name. "mirror" is the ghost construction itself (boundary/ghosts.hpp) and has no factory; the
// others overwrite the mirrored value afterwards (WallVelocity_*_Basa2008.hpp). They act in 2D.
#pragma once
#include <memory>

#include "boundary/wall_velocity_rule.hpp"
#include "core/registry.hpp"

namespace arksph {

using WallVelocityFactory = std::unique_ptr<WallVelocityRule> (*)(const Scene& scene, double dx);

const Registry<WallVelocityFactory>& wall_velocity_rules();

}  // namespace arksph
