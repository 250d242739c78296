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
  io.pair = scene.imex_pair;
  io.fixed_dt = eo.fixed_dt;
  io.rtol = eo.rtol;
  io.atol = eo.atol;
  io.max_steps = eo.max_steps;
  io.stability = eo.stability;
  io.initial_dt = eo.initial_dt;
  io.linear = scene.imex_linear;
  ts.integrator = std::make_unique<ImexIntegrator>(ts.split->functions(), y0, t0, io);
  return ts;
}

}  // namespace arksph
