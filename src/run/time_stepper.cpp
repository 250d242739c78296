#include "run/time_stepper.hpp"

namespace arksph {

TimeStepper make_time_stepper(const Scene& scene, RhsEvaluator& rhs, const ErkOptions& eo, const std::vector<double>& y0,
                              double t0) {
  TimeStepper ts;
  if (!scene.imex) {
    ts.integrator = std::make_unique<ErkIntegrator>([&rhs](double t, const double* y, double* yd) { rhs.eval(t, y, yd); },
                                                    y0, t0, eo);
    return ts;
  }
  ts.split = std::make_unique<ViscousSplit>(scene, rhs);
  ImexOptions io;
  static_cast<StepOptions&>(io) = eo;  // the step control of the run
  io.pair = scene.imex_pair;
  io.linear = scene.imex_linear;
  ts.integrator = std::make_unique<ImexIntegrator>(ts.split->functions(), y0, t0, io);
  return ts;
}

}  // namespace arksph
