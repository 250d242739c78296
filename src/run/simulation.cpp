// A run on one process: the set-up of the model, the output folder, the integrator and the frame at
// t = 0 (or the state of a checkpoint), then the run loop (run/run_loop.hpp) with the strategy of one
// process: f(t, y) over every particle, wall reflections and re-sorts at the sync points, frames and
// checkpoints of the integrator's state.
#include "run/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>

#include "run/checkpointing.hpp"  // checkpoints and restart
#include "run/cpu_time.hpp"
#include "run/failure_diagnosis.hpp"
#include "run/interrupt.hpp"
#include "run/output_folder.hpp"
#include "run/output_start.hpp"
#include "run/output_resume.hpp"
#include "run/particle_reorder.hpp"
#include "run/run_loop.hpp"
#include "run/run_output.hpp"
#include "run/setup.hpp"
#include "run/state_check.hpp"
#include "run/time_stepper.hpp"
#include "boundary/wall_reflection.hpp"
#include "core/errors.hpp"
#include "diagnostics/flow_metrics.hpp"
#include "integrate/time_params.hpp"

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
    std::printf("  %s projection, divergence relaxation rate %.6g", scene.projection.c_str(), c.relaxation());
    if (c.density_relaxation())  // the P-W correction as a velocity in dr/dt
      std::printf(", density relaxation rate %.6g", c.density_relaxation()->rate());
    std::printf("\n");
  }
  const std::string method = scene.imex ? "ARKStep IMEX " + scene.imex_pair + " (viscosity implicit)" : scene.integrator;
  std::string stepping = "adaptive dt (stability limited)";
  if (scene.dt > 0) {
    const Tolerances tol = integrator_tolerances(scene, scene.dt);
    char text[160];
    std::snprintf(text, sizeof text, scene.imex ? "fixed dt %g (implicit stages solved to rtol %g, atol %g)" : "fixed dt %g",
                  scene.dt, tol.rtol, tol.atol);
    stepping = text;
  }
  std::printf("  integrator %s, %s, end time %g\n", method.c_str(), stepping.c_str(), scene.end);
  if (scene.steady_tolerance > 0) {  // diagnostics/steady_state.hpp
    char window[96] = "the latest output interval";
    if (scene.steady_window > 0 && steady_measures().at(scene.steady_measure) == SteadyMeasure::window_means)
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

class LocalRun final : public RunStrategy {
 public:
  LocalRun(const Scene& scene, const RunOptions& options);

  double start_time() const override { return checkpoints_->start_time(); }
  int first_frame() const override { return checkpoints_->first_frame(); }
  TimeIntegrator& integrator() override { return *stepper_.integrator; }
  void start() override;
  double step(double t, double stop) override { return stepper_.step(t, stop); }
  double limit(double t_stop) override { return checkpoints_->limit(t_stop); }
  Verdict reflect_and_check(double t, Verdict mine) override;
  Verdict agree_after_step(double, const Verdict& mine) override { return mine; }
  void sync_point(double t, long steps) override {  // particles by cell
    if (reorder_.due(steps)) reorder_.apply(t, integrator(), d0_, stepper_.split.get());
  }
  void write_frame(double t, const StepStats& stats) override {
    const long before = model_.rhs->evaluations();
    out_->write(t, integrator().state(), d0_, stats);
    diag_evals_ += model_.rhs->evaluations() - before;
  }
  ViscousDissipation* viscous_dissipation() override { return dissipation_ ? &*dissipation_ : nullptr; }
  double viscous_power(double t) override {  // a field refresh at the integrator's state
    model_.rhs->eval(t, integrator().state(), nullptr);
    ++diag_evals_;
    return model_.rhs->viscous_power(model_.rhs->layout().n);
  }
  bool steady() override { return out_->steady(); }
  double steady_rate() const override { return out_->steady_rate(); }
  void checkpoint_if_due(double t, int frame) override {
    checkpoints_->at(t, integrator(), *model_.rhs, frame, reflections_);
  }
  std::string checkpoint_at_end(double t, int frame) override {
    checkpoints_->at_end(t, integrator(), frame, reflections_);
    return checkpoints_->path();
  }
  std::string checkpoint_now(double t, int frame) override {
    return checkpoints_->write(t, integrator(), frame, reflections_);
  }
  std::string checkpoint_path() const override { return checkpoints_->path(); }
  // ARKODE gave up: where the flow was most violent at the last accepted state.
  Verdict numerical_failure(double t, const std::string& what) override { return {3, what + failure_location(t)}; }
  std::string failure_location(double t) override {
    if (!stepper_.integrator) return "";  // before the first step
    return failure_diagnosis(*model_.rhs, model_.particles, t, stepper_.integrator->state());
  }
  Verdict out_of_memory(double t) override {
    return {6, "out of memory at t = " + arksph::message_number(t) + ": an allocation failed while " + activity()};
  }
  void finish(RunResult& result, double wall, double stepping) override;

 private:
  void start_integrator();
  const Scene& scene_;
  Model model_;
  OutputFolder folder_;
  std::string run_id_;
  std::vector<double> y0_;  // the initial state, until the frame at t = 0 is written
  std::vector<double> d0_;  // number density at t = 0, in the current particle order
  ParticleReorder reorder_;
  std::optional<Checkpointer> checkpoints_;
  std::optional<RunOutput> out_;
  ErkOptions eo_;
  TimeStepper stepper_;
  std::optional<StateChecker> checker_;
  std::optional<WallReflection> reflection_;
  long reflections_ = 0;
  long diag_evals_ = 0;  // evaluations for the frames' diagnostics and the energy budget (summary.json)
  std::optional<ViscousDissipation> dissipation_;  // metrics.energy_budget
};

LocalRun::LocalRun(const Scene& scene, const RunOptions& options)
    : scene_(scene), model_(build_model(scene)), folder_(scene.directory, scene.source), reorder_(scene, model_) {
  // The output folder: locked for this run; a fresh run clears an earlier run's outputs, a restart
  // continues only its own run's (run/output_folder.hpp).
  if (!options.overwrite) folder_.refuse_foreign_files();
  run_id_ = start_output_folder(folder_, scene, options);
  RhsEvaluator& rhs = *model_.rhs;
  const StateLayout& layout = rhs.layout();
  print_run_header(scene, model_);
  const std::string particles = std::to_string(layout.n) + " particles";
  rhs.set_between_phases(poll_setup_interrupt);  // until the first step (see below)

  set_activity("setting up the initial state of " + particles);
  y0_.resize(layout.size());
  rhs.initial_state(y0_.data());
  if (scene.reorder_every > 0) reorder_.sort(y0_.data(), d0_);  // t = 0 is a sync point (before the first f)
  poll_setup_interrupt();
  set_activity("building the neighbour lists and initial fields of " + particles);
  rhs.eval(0.0, y0_.data(), nullptr);
  poll_setup_interrupt();
  d0_ = number_density(rhs.fields());  // at t = 0 in the t = 0 order, also on restart (bit-identical diagnostics)
  // Restart: the particles in the checkpoint's order (re-sorts, method.reorder_every); check the
  // checkpoint against the scene, and read the earlier output before RunOutput truncates it.
  if (options.restart) permute(d0_, adopt_particle_order(model_, options.restart->id));
  checkpoints_.emplace(scene, model_, options.restart, options.restart_path);
  checkpoints_->set_run_id(run_id_);
  const bool restarting = checkpoints_->restarting();
  const OutputHistory earlier = restarting ? read_output_history(scene.directory, checkpoints_->start_time(),
                                                                 checkpoints_->restart().output_frame, scene.every)
                                           : OutputHistory{};
  out_.emplace(scene, model_, options, run_id_);  // truncates timeseries.csv
  if (restarting) {
    out_->resume(earlier);
    out_->restore_steady(checkpoints_->restart().steady_samples, checkpoints_->restart().steady_columns);
  }
  checkpoints_->set_steady_monitor(&out_->steady_monitor());
  if (scene.energy_budget) {  // continued from the checkpoint on restart
    dissipation_.emplace(checkpoints_->earlier_viscous_dissipation());
    out_->set_viscous_dissipation(&*dissipation_);
    checkpoints_->set_viscous_dissipation(&*dissipation_);
  }
  start_integrator();
}

void LocalRun::start() {
  const std::string particles = std::to_string(model_.rhs->layout().n) + " particles";
  poll_setup_interrupt();
  set_activity("writing the output at t = 0 of " + particles);
  if (!checkpoints_->restarting()) out_->write(0.0, y0_.data(), d0_, integrator().stats());
  std::vector<double>().swap(y0_);  // the integrator holds the state from here: one state vector less
  poll_setup_interrupt();
  model_.rhs->set_between_phases(nullptr);  // from here a signal stops the run after a step, with a checkpoint
  set_activity("stepping " + particles);
}

// The step control and the integrator at t = 0 or at the checkpoint's state (the projection is
// wired in by make_time_stepper).
void LocalRun::start_integrator() {
  std::vector<double>& y0 = y0_;
  const Scene& scene = scene_;
  RhsEvaluator& rhs = *model_.rhs;
  const StateLayout& layout = rhs.layout();
  eo_ = integrator_options(scene);
  eo_.describe_entry = [this](std::size_t i, double v) {
    return describe_rhs_entry(model_.rhs->layout(), model_.particles.id, i, v);
  };
  eo_.stability = [this](double, const double* y) {
    return stable_step(scene_, model_, max_speed(model_.rhs->layout(), y), model_.rhs->max_acceleration());
  };
  eo_.initial_dt = stable_step(scene, model_, max_speed(layout, y0.data()), rhs.max_acceleration());
  const bool restarting = checkpoints_->restarting();
  if (restarting) {  // continue from the stored state; d0 stays that of t = 0
    y0 = checkpoints_->restart().state;
    eo_.initial_dt = checkpoints_->restart().next_step;
    rhs.invalidate_neighbors();
    StateChecker(scene, model_).check(checkpoints_->start_time(), y0.data());  // NaN, blow-up, escape in the file
  }
  poll_setup_interrupt();
  set_activity("creating the time integrator for " + std::to_string(layout.n) + " particles");
  const long diag_evals_before = rhs.evaluations();
  // A constrained projection starts from a divergence-free velocity (a restart already is).
  if (model_.projection && !restarting) model_.projection->project_initial(0.0, y0.data());
  stepper_ = make_time_stepper(scene, rhs, eo_, y0, checkpoints_->start_time(), model_.projection.get());
  integrator().set_counter_offset(checkpoints_->counters());
  if (integrator().workaround_installed()) out_->add_term("erkstep:fsal_bug_workaround");
  checker_.emplace(scene, model_);
  reflection_.emplace(scene, layout);
  reflections_ = restarting ? checkpoints_->restart().wall_reflections : 0;
  diag_evals_ = rhs.evaluations() - diag_evals_before + 1;
}

Verdict LocalRun::reflect_and_check(double t, Verdict mine) {
  if (mine.code) return mine;
  if (const long r = reflection_->apply(integrator().state())) {  // sync point: re-initialise
    reflections_ += r;
    integrator().reset(t);
  }
  try {
    checker_->check(t, integrator().state());
  } catch (const NumericalFailure& e) {
    return {3, e.what()};
  }
  return mine;
}

void LocalRun::finish(RunResult& result, double wall, double stepping) {
  const StepStats st = integrator().stats();
  if (scene_.reorder_every > 0) out_->set_reorders(reorder_.count(), reorder_.seconds());
  out_->set_stepping_seconds(stepping);
  out_->set_cpu_seconds(checkpoints_->earlier_cpu_seconds() + process_cpu_seconds());
  try {
    out_->finish(result, st, wall, diag_evals_, reflections_, model_.rhs->neighbor_rebuilds());
  } catch (const OutputError& e) {
    if (result.exit_code == 0 || result.exit_code == 5) {
      result.message = result.exit_code == 0 ? e.what() : result.message + "; " + e.what();
      result.exit_code = 5;
      result.checkpoint.clear();
    } else {
      result.message += std::string("; ") + e.what();
    }
  }
}

}  // namespace

RunResult run_simulation(const Scene& scene, const RunOptions& options) {
  const auto wall_start = std::chrono::steady_clock::now();
  poll_setup_interrupt();  // set-up polls for a signal between its phases and in its long loops
  LocalRun run(scene, options);
  return run_loop(scene, run, options.quiet, options.progress_every, wall_start);
}

}  // namespace arksph
