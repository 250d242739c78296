// The run loop, written once for a run on one process and a run over MPI ranks:
//
//   the frame at the start
//   until time.end (or a steady state):
//     until the next output time:
//       one step to the next stop time (output or checkpoint);
//       the step's verdict: step size, wall reflections and state check, step budget, signals
//         (agreed by every rank);
//       the sync point: re-sort or migrate the particles when due;
//       the energy budget's viscous dissipation advanced to the step's end (metrics.energy_budget);
//       a scheduled checkpoint when one falls inside the output interval
//     the frame; stop at a steady state; a scheduled checkpoint
//   the final checkpoint (on a signal: the checkpoint of the last completed step)
//   errors -> exit codes: 3 numerical failure, 5 output not written, 6 out of memory, 128 + signal.
//
// What differs between one process and a decomposed run is a RunStrategy the loop is given: the
// integrator and what happens around its steps, the collectives that make every rank reach the same
// verdict, the frames, the checkpoints and the summary. The set-up builds the strategy.
#pragma once
#include <chrono>
#include <string>

#include "core/scene.hpp"
#include "diagnostics/viscous_dissipation.hpp"
#include "integrate/time_integrator.hpp"
#include "run/run_result.hpp"
#include "core/verdict.hpp"

namespace arksph {

class RunStrategy {
 public:
  virtual ~RunStrategy() = default;

  // Where the run starts: the time, and the index of the next output frame.
  virtual double start_time() const = 0;
  virtual int first_frame() const = 0;
  // The integrator of the run (a strategy may replace it, e.g. at a checkpoint).
  virtual TimeIntegrator& integrator() = 0;
  // The output at the start (a fresh run's frame at t = 0; a restart has it already); then the
  // run is ready to step.
  virtual void start() = 0;

  // One step from t towards `stop` (C&R's projection keeps the positions r^n first). Returns the
  // time reached.
  virtual double step(double t, double stop) = 0;
  // The stop time of the next step: t_stop, or the next scheduled checkpoint if it comes first.
  virtual double limit(double t_stop) = 0;
  // After an accepted step to t: the wall reflections and the state check of this process's
  // particles; `mine` is the loop's own verdict so far (step size). Returns this process's verdict.
  virtual Verdict reflect_and_check(double t, Verdict mine) = 0;
  // Collective: the verdict every rank agrees on (the identity on one process); a step with a wall
  // reflection on any rank re-initialises the integrator on every rank.
  virtual Verdict agree_after_step(double t, const Verdict& mine) = 0;
  // The sync point after the step that made `steps` accepted steps: re-sort or migrate when due.
  virtual void sync_point(double t, long steps) = 0;

  // metrics.energy_budget: the viscous dissipation, which the loop advances after the start and
  // after every accepted step (null: no budget).
  virtual ViscousDissipation* viscous_dissipation() = 0;
  // Collective: sum_a m_a u_a . a_visc,a over every particle at the state of t, from a field
  // refresh there (RhsEvaluator::viscous_power); the same on every rank.
  virtual double viscous_power(double t) = 0;

  // The output at time t: fields, diagnostics, the frame and the CSV row.
  virtual void write_frame(double t, const StepStats& stats) = 0;
  // time.steady_tolerance: whether the flow was steady at the last frame (the same on every rank),
  // and its change rate there.
  virtual bool steady() = 0;
  virtual double steady_rate() const = 0;

  // The scheduled checkpoint, when due at t (`frame`: the index of the next output frame).
  virtual void checkpoint_if_due(double t, int frame) = 0;
  // The checkpoint at the end of the run (unless the scheduled one was written at t). Returns its path.
  virtual std::string checkpoint_at_end(double t, int frame) = 0;
  // A checkpoint at t now (a signal, or after an output error). Returns its path.
  virtual std::string checkpoint_now(double t, int frame) = 0;
  virtual std::string checkpoint_path() const = 0;

  // Where the flow is most violent at t (run/failure_diagnosis.hpp), appended to the message of a
  // step-size failure; "" where that is not known without a collective (ranks).
  virtual std::string failure_location(double) { return ""; }
  // The verdict after ARKODE gave up at or after t, the time of the last accepted step (the same on
  // every rank).
  virtual Verdict numerical_failure(double t, const std::string& what) = 0;
  // An allocation failed at t: the verdict, or rethrows (called from the handler).
  virtual Verdict out_of_memory(double t) = 0;

  // summary.json and the last agreement: `result` is the run's outcome, updated when the summary
  // cannot be written. `wall` is the run's wall time, `stepping` the steps' alone.
  virtual void finish(RunResult& result, double wall, double stepping) = 0;
};

// Runs the loop above from strategy.start_time() to scene.end. `wall_start`: when the run's set-up began (summary.json's wall time); `quiet`: no
// progress on stderr; `progress_every`: wall seconds between progress lines when stderr is not a
// terminal (run/progress.hpp).
RunResult run_loop(const Scene& scene, RunStrategy& strategy, bool quiet, double progress_every,
                   std::chrono::steady_clock::time_point wall_start);

// The end of the output interval that starts at frame `frame`: frame * output.every, or time.end.
double next_output_time(const Scene& scene, int frame);

}  // namespace arksph
