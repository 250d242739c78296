#include "run/time_stepper.hpp"

namespace arksph {

TimeStepper make_time_stepper(const Scene& scene, RhsFunction f, const ErkOptions& eo, const std::vector<double>& y0,
                              double t0, Projection* projection, std::function<void()> projected) {
  TimeStepper ts;
  Projection* constrained = projection && projection->constrained() ? projection : nullptr;
  if (projection && !constrained) ts.after_step = projection;
  if (!projected) projected = [] {};
  ErkOptions o = eo;
  if (ts.after_step) {
    o.postprocess = [projection, projected](double t, double* y) {
      projection->project(t, y);
      projected();
    };
    if (scene.projection_points == ProjectionPoints::stages)
      o.postprocess_stage = [projection, projected](double t, double* y) {
        projection->project_stage(t, y);
        projected();
      };
  }
  if (constrained)
    f = [f = std::move(f), constrained, projected](double t, const double* y, double* yd) {
      f(t, y, yd);
      constrained->constrain(y, yd, nullptr, nullptr);
      projected();
    };
  ts.integrator = std::make_unique<ErkIntegrator>(std::move(f), y0, t0, o);
  return ts;
}

TimeStepper make_time_stepper(const Scene& scene, RhsEvaluator& rhs, const ErkOptions& eo, const std::vector<double>& y0,
                              double t0, Projection* projection) {
  if (!scene.imex)
    return make_time_stepper(
        scene, [&rhs](double t, const double* y, double* yd) { rhs.eval(t, y, yd); }, eo, y0, t0, projection, {});
  TimeStepper ts;
  Projection* constrained = projection && projection->constrained() ? projection : nullptr;
  if (projection && !constrained) ts.after_step = projection;
  ts.split = std::make_unique<ViscousSplit>(scene, rhs);
  if (constrained)
    ts.split->set_constraint([constrained](const double* y, double* fe, const double* au, const double* av) {
      constrained->constrain(y, fe, au, av);
    });
  ts.integrator = std::make_unique<ImexIntegrator>(ts.split->functions(), y0, t0, imex_options(scene, eo));
  return ts;
}

ImexOptions imex_options(const Scene& scene, const StepOptions& eo) {
  ImexOptions io;
  static_cast<StepOptions&>(io) = eo;  // the step control of the run
  io.pair = scene.imex_pair;
  io.linear = scene.imex_linear;
  return io;
}

}  // namespace arksph
