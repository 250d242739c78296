// The time-integration families a scene selects by name (ARKODE explicit tables, IMEX pairs) and the
// keys of the [time] table that the integrators read.
#pragma once
#include <vector>

#include "core/parameter.hpp"
#include "core/registry.hpp"
#include "core/scene.hpp"

namespace arksph {

const Registry<Selected>& erk_tables();  // time.integrator
const Registry<Selected>& imex_pairs();  // time.imex_pair
// time.* keys in the order of the scene file (end excepted, which the run loop owns).
const std::vector<Param>& time_params();
const std::vector<Param>& imex_params();

// With a fixed step (time.dt > 0) there is no error control, and the tolerances only set how far the
// implicit stages' Newton solve converges (IMEX). Loose adaptive tolerances (time.rtol = 1e-2) would
// stop it above the step's truncation error and spoil a measured order (ARK436L2SA measured 1.9 on a
// Taylor-Green vortex); so a fixed step solves to at most these, or to time.rtol / time.atol if tighter.
inline constexpr double kFixedStepRtol = 1e-10, kFixedStepAtol = 1e-12;
struct Tolerances {
  double rtol, atol;
};
// The tolerances handed to ARKODE for `scene` run with step `dt` (0: adaptive).
Tolerances integrator_tolerances(const Scene& scene, double dt);

}  // namespace arksph
