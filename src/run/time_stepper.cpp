#include "run/time_stepper.hpp"

namespace arksph {

TimeStepper make_time_stepper(const Scene& scene, RhsEvaluator& rhs, const ErkOptions& eo, const std::vector<double>& y0,
                              double t0, Projection* projection) {
  TimeStepper ts;
  Projection* constrained = projection && projection->constrained() ? projection : nullptr;
  if (projection && !constrained) ts.after_step = projection;
  if (!scene.imex) {
    ErkOptions o = eo;
    if (ts.after_step) {
      o.postprocess = [projection](double t, double* y) { projection->project(t, y); };
      if (projection_options().projection_points.at(scene.projection_points) == ProjectionPoints::stages)
        o.postprocess_stage = [projection](double t, double* y) { projection->project_stage(t, y); };
    }
    RhsFunction f = [&rhs](double t, const double* y, double* yd) { rhs.eval(t, y, yd); };
    if (constrained)
      f = [&rhs, constrained](double t, const double* y, double* yd) {
        rhs.eval(t, y, yd);
        constrained->constrain(y, yd, nullptr, nullptr);
      };
    ts.integrator = std::make_unique<ErkIntegrator>(std::move(f), y0, t0, o);
    return ts;
  }
  ts.split = std::make_unique<ViscousSplit>(scene, rhs);
  if (constrained)
    ts.split->set_constraint([constrained](const double* y, double* fe, const double* au, const double* av) {
      constrained->constrain(y, fe, au, av);
    });
  ImexOptions io;
  static_cast<StepOptions&>(io) = eo;  // the step control of the run
  io.pair = scene.imex_pair;
  io.linear = scene.imex_linear;
  ts.integrator = std::make_unique<ImexIntegrator>(ts.split->functions(), y0, t0, io);
  return ts;
}

}  // namespace arksph
