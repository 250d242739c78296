// The scenes that the automatic rules of the regularisation (rhs/regularisation/) and of the wall
// velocity (wall_velocity_rules.cpp) single out, and the automatic rule of
// boundary.free_slip_divergence, declared with its key.
#pragma once
#include "core/parameter.hpp"
#include "core/registry.hpp"
#include "core/scene.hpp"

namespace arksph {

// True for isph (C&R's projection after each step) with a density correction that holds the
// particles at the reference density (the P-W correction), in a walled box with a flow (a wall or
// initial speed): the scenes whose automatic regularisation is the transport velocity.
bool corrected_walled_flow(const Scene& s, const SelectedParts& parts);

// boundary.free_slip_divergence, with its rule for "auto".
Param free_slip_divergence_param();

}  // namespace arksph
