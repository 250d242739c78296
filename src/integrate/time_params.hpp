// The time-integration families a scene selects by name (ARKODE explicit tables, IMEX pairs) and the
// keys of the [time] table that the integrators read.
#pragma once
#include <vector>

#include "core/parameter.hpp"
#include "core/registry.hpp"

namespace arksph {

const Registry<Selected>& erk_tables();  // time.integrator
const Registry<Selected>& imex_pairs();  // time.imex_pair
// time.* keys in the order of the scene file (end excepted, which the run loop owns).
const std::vector<Param>& time_params();
const std::vector<Param>& imex_params();

}  // namespace arksph
