// A run on one process: the set-up and the run loop of run/model_run.hpp with the process strategy
// of one process: f(t, y) over every particle, identity collectives, wall reflections and re-sorts
// at the sync points, frames and checkpoints of the integrator's state.
#include "run/simulation.hpp"

#include <chrono>
#include <optional>
#include <vector>

#include "boundary/wall_reflection.hpp"
#include "core/errors.hpp"
#include "diagnostics/flow_metrics.hpp"
#include "run/failure_diagnosis.hpp"
#include "run/interrupt.hpp"
#include "run/model_run.hpp"
#include "run/particle_reorder.hpp"
#include "run/time_stepper.hpp"

namespace arksph {

namespace {

class OneProcess final : public RunProcess {
 public:
  explicit OneProcess(const Scene& scene) : scene_(scene) {}

  void initial_state(Model& model) override;
  void adopted_order(const Permutation& from) override { permute(d0_, from); }
  double initial_acceleration() const override { return model_->rhs->max_acceleration(); }
  long start_stepping(double t0, const Checkpoint* restart, const StepStats& counters) override;
  void poll_interrupt() const override { poll_setup_interrupt(); }
  void started() override {
    std::vector<double>().swap(y0_);  // the integrator holds the state from here: one state vector less
    model_->rhs->set_between_phases(nullptr);  // from here a signal stops the run after a step, with a checkpoint
    set_activity("stepping " + std::to_string(model_->particles.n) + " particles");
  }

  TimeIntegrator& integrator() override { return *stepper_.integrator; }
  double step(double t, double stop) override { return stepper_.step(t, stop); }
  long reflect() override {
    const long r = static_cast<long>(reflection_->apply(integrator().state()));
    return r;
  }
  void check(const StateChecker& checker, double t) override { checker.check(t, integrator().state()); }
  void sync_point(double t, long steps) override {  // particles by cell
    if (reorder_->due(steps)) reorder_->apply(t, integrator(), d0_, stepper_.split.get());
  }
  double viscous_power(double t) override {  // a field refresh at the integrator's state
    model_->rhs->eval(t, integrator().state(), nullptr);
    return model_->rhs->viscous_power(model_->rhs->layout().n);
  }
  FrameSource frame_source(double t) override;

  void with_whole_state(bool, const std::function<void(const double*)>& use) override { use(integrator().state()); }
  // What a restart from the checkpoint does (run/checkpointing.hpp).
  void continue_from_checkpoint(double t, double h, const StepStats&, const double*) override {
    integrator().restart_at(t, h);
    model_->rhs->invalidate_neighbors();
    if (model_->projection) model_->projection->forget_warm_start();  // a restart starts the solvers cold
  }

  // ARKODE gave up: where the flow was most violent at the last accepted state.
  Verdict numerical_failure(double t, const std::string& what) override { return {3, what + failure_location(t)}; }
  std::string failure_location(double t) override {
    if (!stepper_.integrator) return "";  // before the first step
    return failure_diagnosis(*model_->rhs, model_->particles, t, stepper_.integrator->state());
  }
  Verdict out_of_memory(double t) override {
    return {6, "out of memory at t = " + arksph::message_number(t) + ": an allocation failed while " + activity()};
  }
  void report(RunTotals& totals) override {
    totals.neighbor_rebuilds = model_->rhs->neighbor_rebuilds();
    if (scene_.reorder_every > 0) {
      totals.reorders = reorder_->count();
      totals.reorder_seconds = reorder_->seconds();
    }
  }

 private:
  const Scene& scene_;
  Model* model_ = nullptr;
  std::vector<double> y0_;  // the initial state, until the frame at t = 0 is written
  std::vector<double> d0_;  // number density at t = 0, in the current particle order
  std::optional<ParticleReorder> reorder_;
  TimeStepper stepper_;
  std::optional<WallReflection> reflection_;
};

FrameSource OneProcess::frame_source(double t) {
  RhsEvaluator& rhs = *model_->rhs;
  rhs.eval(t, integrator().state(), nullptr);  // fresh density, pressure, neighbours
  const FluidFields& f = rhs.fields();
  FrameSource s;
  s.particles = {&f, f.n_real, d0_.data(), model_->particles.phase.data()};
  s.owns = [](double, double) { return true; };  // one process: its own sums are the totals
  s.x = f.x.data();  // wrapped into the box by the evaluator
  s.y = f.dim == 2 ? f.y.data() : nullptr;
  const Projection* projection = model_->projection.get();
  s.pressure = projection && !projection->pressure().empty() ? projection->pressure().data() : f.p.data();
  s.id = model_->particles.id.data();
  s.support = rhs.kernel().radius();
  return s;
}

// The initial state (sorted by cell: t = 0 is a sync point, before the first f) and its fields.
void OneProcess::initial_state(Model& model) {
  model_ = &model;
  reorder_.emplace(scene_, model);
  RhsEvaluator& rhs = *model.rhs;
  const std::string particles = std::to_string(rhs.layout().n) + " particles";
  rhs.set_between_phases(poll_setup_interrupt);  // until the first step (see started)
  set_activity("setting up the initial state of " + particles);
  y0_.resize(rhs.layout().size());
  rhs.initial_state(y0_.data());
  if (scene_.reorder_every > 0) reorder_->sort(y0_.data(), d0_);
  poll_setup_interrupt();
  set_activity("building the neighbour lists and initial fields of " + particles);
  rhs.eval(0.0, y0_.data(), nullptr);
  poll_setup_interrupt();
  d0_ = number_density(rhs.fields());  // at t = 0 in the t = 0 order, also on restart (bit-identical diagnostics)
}

// The step control and the integrator at t = 0 or at the checkpoint's state (the projection is
// wired in by make_time_stepper).
long OneProcess::start_stepping(double t0, const Checkpoint* restart, const StepStats& counters) {
  RhsEvaluator& rhs = *model_->rhs;
  const StateLayout& layout = rhs.layout();
  ErkOptions eo = integrator_options(scene_);
  eo.describe_entry = [this](std::size_t i, double v) {
    return describe_rhs_entry(model_->rhs->layout(), model_->particles.id, i, v);
  };
  eo.stability = [this](double, const double* y) {
    return stable_step(scene_, *model_, max_speed(model_->rhs->layout(), y), model_->rhs->max_acceleration());
  };
  eo.initial_dt = stable_step(scene_, *model_, max_speed(layout, y0_.data()), rhs.max_acceleration());
  if (restart) {  // continue from the stored state; d0 stays that of t = 0
    y0_ = restart->state;
    eo.initial_dt = restart->next_step;
    rhs.invalidate_neighbors();
  }
  poll_setup_interrupt();
  set_activity("creating the time integrator for " + std::to_string(layout.n) + " particles");
  const long before = rhs.evaluations();
  // A constrained projection starts from a divergence-free velocity (a restart already is).
  if (model_->projection && !restart) model_->projection->project_initial(0.0, y0_.data());
  stepper_ = make_time_stepper(scene_, rhs, eo, y0_, t0, model_->projection.get());
  integrator().set_counter_offset(counters);
  reflection_.emplace(scene_, layout);
  set_activity("writing the output at t = 0 of " + std::to_string(layout.n) + " particles");
  return rhs.evaluations() - before + 1;  // and the evaluation at t = 0
}

}  // namespace

RunResult run_simulation(const Scene& scene, const RunOptions& options) {
  const auto wall_start = std::chrono::steady_clock::now();
  poll_setup_interrupt();  // set-up polls for a signal between its phases and in its long loops
  OneProcess process(scene);
  return run_model(scene, options, process, wall_start);
}

}  // namespace arksph
