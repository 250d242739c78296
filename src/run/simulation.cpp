// The run loop: step (ARKODE), check, diagnose, write. Reads like the algorithm:
//   set up -> write t = 0 -> repeat { advance one step; check the state } and at each output time
//   { refresh fields; diagnostics; write frame, CSV row }, at each checkpoint time { checkpoint.h5 }
//   -> checkpoint.h5, summary.json. A restart (options.restart) starts the same loop from a checkpoint.
#include "run/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <new>

#include "run/checkpointing.hpp"  // checkpoints and restart
#include "run/cpu_time.hpp"
#include "run/interrupt.hpp"
#include "run/output_folder.hpp"
#include "run/output_start.hpp"
#include "run/output_resume.hpp"
#include "run/particle_reorder.hpp"
#include "run/progress.hpp"
#include "run/run_output.hpp"
#include "run/setup.hpp"
#include "run/state_check.hpp"
#include "run/time_stepper.hpp"
#include "boundary/wall_reflection.hpp"
#include "core/errors.hpp"
#include "diagnostics/flow_metrics.hpp"

namespace arksph {

namespace {
void print_run_header(const Scene& scene, const Model& model) {
  std::printf("arksph: scene '%s' (%s)\n", scene.name.c_str(), scene.source.c_str());
  std::printf("  scheme %s, %zu particles, dimension %d, dx %.6g, h %.6g, kernel %s\n", scene.scheme.c_str(),
              model.particles.n, scene.dimension, scene.spacing, model.h, scene.kernel.c_str());
  std::string chosen;  // the keys given as "auto" that this run uses, and what their rules chose
  for (const auto& [key, value] : scene.automatic)
    if (std::find(scene.automatic_unused.begin(), scene.automatic_unused.end(), key) == scene.automatic_unused.end())
      chosen += (chosen.empty() ? " " : ", ") + key + " = " + value;
  if (!chosen.empty()) std::printf("  auto:%s\n", chosen.c_str());
  if (model.sound_speed > 0) std::printf("  sound speed %.6g\n", model.sound_speed);
  if (model.reference_speed > 0) std::printf("  flow speed U %.6g (scale of the regularisation velocity)\n", model.reference_speed);
  if (model.projection && model.projection->constrained()) {
    const ConstrainedPressure& c = *model.projection->constraint();
    std::printf("  constrained projection, divergence relaxation rate %.6g", c.relaxation());
    if (c.density_relaxation())  // the P-W correction as a velocity in dr/dt
      std::printf(", density relaxation rate %.6g", c.density_relaxation()->rate());
    std::printf("\n");
  }
  const std::string method = scene.imex ? "ARKStep IMEX " + scene.imex_pair + " (viscosity implicit)" : scene.integrator;
  std::printf("  integrator %s, %s, end time %g\n", method.c_str(),
              scene.dt > 0 ? ("fixed dt " + std::to_string(scene.dt)).c_str() : "adaptive dt (stability limited)",
              scene.end);
  if (scene.steady_tolerance > 0) {  // diagnostics/steady_state.hpp
    char window[96] = "the latest output interval";
    if (scene.steady_window > 0 && scene.steady_measure == "window_means")
      std::snprintf(window, sizeof window, "the means of two windows of %g of simulated time", scene.steady_window);
    else if (scene.steady_window > 0)
      std::snprintf(window, sizeof window, "every output interval of the last %g of simulated time", scene.steady_window);
    std::printf("  stops at steady state: change rate of the kinetic energy%s below %g per unit time over %s\n",
                scene.ghia_re ? " and the Ghia centreline velocities" : "", scene.steady_tolerance, window);
  }
  std::printf("  terms:");
  for (const auto& t : model.terms) std::printf(" %s", t.c_str());
  std::printf("\n  output: %s\n", scene.directory.c_str());
  std::fflush(stdout);
}

}  // namespace

RunResult run_simulation(const Scene& scene, const RunOptions& options) {
  using clock = std::chrono::steady_clock;
  const auto wall_start = clock::now();
  poll_setup_interrupt();  // set-up polls for a signal between its phases and in its long loops
  Model model = build_model(scene);
  // The output folder: locked for this run; a fresh run clears an earlier run's outputs, a restart
  // continues only its own run's (run/output_folder.hpp).
  OutputFolder folder(scene.directory, scene.source);
  if (!options.overwrite) folder.refuse_foreign_files();
  const std::string run_id = start_output_folder(folder, scene, options);
  RhsEvaluator& rhs = *model.rhs;
  const StateLayout& layout = rhs.layout();
  print_run_header(scene, model);
  const std::string particles = std::to_string(layout.n) + " particles";
  rhs.set_between_phases(poll_setup_interrupt);  // until the first step (see below)

  set_activity("setting up the initial state of " + particles);
  std::vector<double> y0(layout.size());
  rhs.initial_state(y0.data());
  std::vector<double> d0;
  ParticleReorder reorder(scene, model);
  if (scene.reorder_every > 0) reorder.sort(y0.data(), d0);  // t = 0 is a sync point (before the first f)
  poll_setup_interrupt();
  set_activity("building the neighbour lists and initial fields of " + particles);
  rhs.eval(0.0, y0.data(), nullptr);
  poll_setup_interrupt();
  d0 = number_density(rhs.fields());  // at t = 0 in the t = 0 order, also on restart (bit-identical diagnostics)
  // Restart: the particles in the checkpoint's order (re-sorts, method.reorder_every); check the
  // checkpoint against the scene, and read the earlier output before RunOutput truncates it.
  if (options.restart) permute(d0, adopt_particle_order(model, options.restart->id));
  Checkpointer checkpoints(scene, model, options.restart, options.restart_path);
  checkpoints.set_run_id(run_id);
  const OutputHistory earlier = checkpoints.restarting() ? read_output_history(scene.directory, checkpoints.start_time(),
                                                                               checkpoints.restart().output_frame, scene.every)
                                                         : OutputHistory{};
  RunOutput out(scene, model, options, run_id);  // truncates timeseries.csv
  if (checkpoints.restarting()) {
    out.resume(earlier);
    out.restore_steady(checkpoints.restart().steady_samples, checkpoints.restart().steady_columns);
  }
  checkpoints.set_steady_monitor(&out.steady_monitor());

  ErkOptions eo = integrator_options(scene);
  eo.describe_entry = [&](std::size_t i, double v) { return describe_rhs_entry(layout, model.particles.id, i, v); };
  eo.stability = [&](double, const double* y) {
    return stable_step(scene, model, max_speed(layout, y), rhs.max_acceleration());
  };
  eo.initial_dt = stable_step(scene, model, max_speed(layout, y0.data()), rhs.max_acceleration());
  if (model.projection && !model.projection->constrained()) {
    Projection* proj = model.projection.get();
    eo.postprocess = [proj](double t, double* y) { proj->project(t, y); };
    if (scene.projection_points == "stages") eo.postprocess_stage = [proj](double t, double* y) { proj->project_stage(t, y); };
  }
  if (checkpoints.restarting()) {  // continue from the stored state; d0 stays that of t = 0
    y0 = checkpoints.restart().state;
    eo.initial_dt = checkpoints.restart().next_step;
    rhs.invalidate_neighbors();
    StateChecker(scene, model).check(checkpoints.start_time(), y0.data());  // NaN, blow-up, escape in the file
  }
  poll_setup_interrupt();
  set_activity("creating the time integrator for " + particles);
  const long diag_evals_before = rhs.evaluations();
  // A constrained projection starts from a divergence-free velocity (a restart already is).
  if (model.projection && !checkpoints.restarting()) model.projection->project_initial(0.0, y0.data());
  TimeStepper stepper = make_time_stepper(scene, rhs, eo, y0, checkpoints.start_time(), model.projection.get());
  TimeIntegrator& integrator = *stepper.integrator;
  integrator.set_counter_offset(checkpoints.counters());
  if (integrator.workaround_installed()) out.add_term("erkstep:fsal_bug_workaround");

  StateChecker checker(scene, model);
  const WallReflection reflection(scene, layout);
  long reflections = checkpoints.restarting() ? checkpoints.restart().wall_reflections : 0;
  Progress progress(scene.end, options.quiet);
  long diag_evals = rhs.evaluations() - diag_evals_before + 1;

  poll_setup_interrupt();
  set_activity("writing the output at t = 0 of " + particles);
  double t = checkpoints.start_time();
  int frame = checkpoints.first_frame();
  int tiny_steps = 0;  // adaptive steps in a row below the underflow floor (check_step_size)
  RunResult result;
  double stepping = 0;  // the steps alone (summary.json timing.stepping)
  try {
    // Output at t = 0, every `every`, and the end time exactly.
    if (!checkpoints.restarting()) out.write(0.0, y0.data(), d0, integrator.stats());
    std::vector<double>().swap(y0);  // the integrator holds the state from here: one state vector less
    poll_setup_interrupt();
    rhs.set_between_phases(nullptr);  // from here a signal stops the run after a step, with a checkpoint
    set_activity("stepping " + particles);
    while (t < scene.end) {
      double t_next = scene.every > 0 ? scheduled_time(frame, scene.every) : scene.end;  // 3 * 0.1 -> 0.3
      if (t_next > scene.end * (1 - 1e-12)) t_next = scene.end;
      double dt_max = 0;  // largest step since the last output (the last one may be cut to hit t_next)
      while (t < t_next) {
        const auto step_start = clock::now();
        if (model.projection) model.projection->begin_step(t, integrator.state());
        const double stop = checkpoints.limit(t_next);
        t = integrator.step(stop);  // checkpoint times are stop times too
        const ErkStats st = integrator.stats();
        dt_max = std::max(dt_max, st.last_step);
        if (scene.dt == 0) check_step_size(t, st.last_step, scene.end, tiny_steps);
        if (const long r = reflection.apply(integrator.state())) {  // sync point: re-initialise
          reflections += r;
          integrator.reset(t);
        }
        if (reorder.due(st.steps)) reorder.apply(t, integrator, d0, stepper.split.get());  // sync point: particles by cell
        checker.check(t, integrator.state());
        if (st.steps >= scene.max_steps)
          throw NumericalFailure("time.max_steps = " + std::to_string(scene.max_steps) + " reached at t = " +
                                 std::to_string(t) + " before time.end");
        progress.step(t, st.steps, st.last_step);
        if (const int sig = pending_interrupt()) throw Interrupted{sig};
        stepping += std::chrono::duration<double>(clock::now() - step_start).count();
        if (t < t_next) checkpoints.at(t, integrator, rhs, frame, reflections);
      }
      const long before = rhs.evaluations();
      ErkStats st = integrator.stats();
      st.last_step = dt_max;
      out.write(t, integrator.state(), d0, st);
      diag_evals += rhs.evaluations() - before;
      progress.frame(t, st.steps, dt_max);
      ++frame;
      if (out.steady() && t < scene.end) {  // time.steady_tolerance: end here as at time.end
        result.steady_time = t;
        result.steady_rate = out.steady_rate();
        break;
      }
      checkpoints.at(t, integrator, rhs, frame, reflections);
    }
    checkpoints.at_end(t, integrator, frame, reflections);
    result.checkpoint = checkpoints.path();
  } catch (const NumericalFailure& e) {
    result.exit_code = 3;
    result.message = e.what();
  } catch (const OutputError& e) {  // disk full, size limit: keep what still fits, exit 5
    result.exit_code = 5;
    result.message = e.what();
    if (result.message.rfind("cannot write " + checkpoints.path() + ":", 0) != 0) {
      try {
        result.checkpoint = checkpoints.write(t, integrator, frame, reflections);
      } catch (const OutputError& again) {
        result.message += std::string("; ") + again.what();
      }
    }
  } catch (const std::bad_alloc&) {
    result.exit_code = 6;
    result.message = "out of memory at t = " + std::to_string(t) + ": an allocation failed while " + activity();
  } catch (const Interrupted& i) {  // checkpoint at the last completed step, then exit 128 + signal
    result.exit_code = 128 + i.signal;
    result.interrupted = true;
    result.checkpoint = checkpoints.write(t, integrator, frame, reflections);
    result.message = std::string("interrupted by ") + interrupt_name(i.signal) + " at t = " + std::to_string(t);
  }
  progress.finish();
  const ErkStats st = integrator.stats();
  const double wall = std::chrono::duration<double>(clock::now() - wall_start).count();
  if (scene.reorder_every > 0) out.set_reorders(reorder.count(), reorder.seconds());
  out.set_stepping_seconds(stepping);
  out.set_cpu_seconds(checkpoints.earlier_cpu_seconds() + process_cpu_seconds());
  try {
    out.finish(result, st, wall, diag_evals, reflections, rhs.neighbor_rebuilds());
  } catch (const OutputError& e) {
    if (result.exit_code == 0 || result.exit_code == 5) {
      result.message = result.exit_code == 0 ? e.what() : result.message + "; " + e.what();
      result.exit_code = 5;
      result.checkpoint.clear();
    } else {
      result.message += std::string("; ") + e.what();
    }
  }
  return result;
}

}  // namespace arksph
