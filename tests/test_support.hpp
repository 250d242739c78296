// Helpers shared by the test files.
#pragma once
#include <vector>

#include "app/setup.hpp"
#include "integrate/erk_integrator.hpp"

namespace arksph::testing {

// One fixed step of the scene's ERKStep table followed by the projection (the run loop's step for
// scheme isph), from the initial state y0 (filled here). Returns the state after the step.
inline std::vector<double> one_projected_step(const Scene& scene, Model& model, std::vector<double>& y0) {
  y0.assign(model.rhs->layout().size(), 0.0);
  model.rhs->initial_state(y0.data());
  ErkOptions o;
  o.table = scene.integrator;
  o.fixed_dt = scene.dt;
  Projection* proj = model.projection.get();
  o.postprocess = [proj](double t, double* y) { proj->project(t, y); };
  ErkIntegrator integ([&](double t, const double* y, double* yd) { model.rhs->eval(t, y, yd); }, y0, 0.0, o);
  proj->begin_step(0.0, y0.data());
  integ.step(scene.dt);
  return {integ.state(), integ.state() + integ.size()};
}

}  // namespace arksph::testing
