// The run's time integrator from the scene: ERKStep with time.integrator, or, with time.imex,
// ARKStep with the pair time.imex_pair, the viscous term implicit (integrate/viscous_split.hpp).
#pragma once
#include <functional>
#include <memory>
#include <vector>

#include "core/scene.hpp"
#include "integrate/erk_integrator.hpp"
#include "integrate/imex_integrator.hpp"
#include "integrate/time_integrator.hpp"
#include "integrate/viscous_split.hpp"
#include "projection/projection.hpp"
#include "rhs/evaluator.hpp"

namespace arksph {

struct TimeStepper {
  std::unique_ptr<ViscousSplit> split;  // time.imex only
  std::unique_ptr<TimeIntegrator> integrator;
  Projection* after_step = nullptr;  // C&R's projection after each step (null: none, or constrained)
  // One step from t towards `stop`: the projection after each step keeps the positions r^n for
  // its centring, then the integrator steps (and projects). Returns the time reached.
  double step(double t, double stop) {
    if (after_step) after_step->begin_step(t, integrator->state());
    return integrator->step(stop);
  }
};

// `eo`: the ERK options of the run (integrator_options plus stability limit and first step); the
// IMEX integrator takes its step control from it.
// `projection`: the run's projection, or null. C&R's projection runs after each step (and after
// each stage with method.projection_points = "stages"); a constrained one
// (Projection::constrained) becomes part of f (ERK) or of f_E (IMEX), where it sees the whole
// acceleration (under IMEX a projection must be constrained: no post-processing).
TimeStepper make_time_stepper(const Scene& scene, RhsEvaluator& rhs, const ErkOptions& eo, const std::vector<double>& y0,
                              double t0, Projection* projection = nullptr);
// The IMEX options of the run: the step control of `eo` (the run's ERK options), time.imex_pair and
// time.imex_linear.
ImexOptions imex_options(const Scene& scene, const StepOptions& eo);
// The same with ERKStep (no time.imex) and f given as a function (one rank's, over its particles
// and their halo); `projected` is called after each projection (after a step or stage, or the
// constrained one inside f), when the projection's pressure is that of the current particles.
TimeStepper make_time_stepper(const Scene& scene, RhsFunction f, const ErkOptions& eo, const std::vector<double>& y0,
                              double t0, Projection* projection, std::function<void()> projected);

}  // namespace arksph
