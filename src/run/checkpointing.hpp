// Checkpoints during a run: scheduled ones (output.checkpoint_every), the last one at the end time,
// one on SIGINT/SIGTERM; and the state a restart starts from.
//
// Exact restart. A run restarted from a scheduled or final checkpoint continues bit for bit like
// the run that never stopped, provided both have the same stop times. Measured for WCSPH with a
// fixed step and, with the same stop times, in adaptive mode too. This holds because at every
// checkpoint the uninterrupted run drops the hidden state that a restart cannot have:
//   - the integrator is re-initialised at (t, y) as a new one (ERKStepReInit, first step
//     next_step), so no FSAL value, step-controller history or time round-off survives;
//   - the RHS evaluator's Verlet list and ghost set are rebuilt at the next evaluation
//     (RhsEvaluator::invalidate_neighbors), so pairs are summed in the same order;
//   - checkpoint times are stop times of the integrator, like output times, and both are
//     computed by scheduled_time.
// Not covered: the ISPH projection's warm starts (CG pressure guess, KLU refactorisation).
// A checkpoint written on a signal falls at an arbitrary step, so a restart from it is a valid
// continuation but not bit-identical to the uninterrupted run.
#pragma once
#include <string>
#include <utility>

#include "diagnostics/steady_state.hpp"
#include "diagnostics/viscous_dissipation.hpp"
#include "run/setup.hpp"
#include "io/checkpoint.hpp"

namespace arksph {

// k * every rounded to 15 significant digits, so that a scheduled time (output, checkpoint) equals
// the same time typed in a scene: 3 * 0.1 gives 0.3, not 0.30000000000000004. Then a run to
// time.end = 0.3 and a longer run with a checkpoint at 0.3 stop the integrator at the same time.
double scheduled_time(long k, double every);

class Checkpointer {
 public:
  // `restart` (may be null) is the checkpoint this run starts from, read from `restart_path`;
  // throws InputError if it does not fit the scene's particle set, the keys that shape the lattice
  // and the walls (run/restart_keys.hpp) or time.end.
  Checkpointer(const Scene& scene, const Model& model, const Checkpoint* restart, std::string restart_path);

  bool restarting() const { return restart_ != nullptr; }
  // The run id stored in the checkpoints this run writes (run/output_folder.hpp).
  void set_run_id(std::string id) { run_id_ = std::move(id); }
  // The steady-state monitor whose samples each checkpoint stores (null: none).
  void set_steady_monitor(const SteadyStateMonitor* m) { steady_ = m; }
  // The viscous dissipation of the energy budget, stored in each checkpoint (null: none).
  void set_viscous_dissipation(const ViscousDissipation* w) { dissipation_ = w; }
  const Checkpoint& restart() const { return *restart_; }
  double start_time() const { return restart_ ? restart_->time : 0.0; }
  // Index of the next output frame (frame * output.every) at the start of the run.
  int first_frame() const;
  std::string path() const { return path_; }
  // The integrator counters of the checkpointed run (TimeIntegrator::set_counter_offset).
  StepStats counters() const;

  // The stop time for the next step: t_stop, or the next scheduled checkpoint if that comes first.
  double limit(double t_stop);
  // True once if the scheduled checkpoint is due at t (the schedule moves on), for the caller to
  // write it with write_state and re-initialise as a restart from it does (see above;
  // RunProcess::continue_from_checkpoint, run/run_process.hpp).
  bool take_due(double t);
  // Writes the checkpoint of the whole state y (the model's layout and particle order) with the
  // integrator's counters `st` and its next step size. Returns the path.
  // `segment_cpu` is the CPU time of this run since it started (all ranks'); the checkpoint
  // stores it added to the earlier segments' (earlier_cpu_seconds).
  std::string write_state(double t, const double* y, const StepStats& st, double next_step, long frames,
                          long reflections, double segment_cpu);
  // CPU time of the runs this one continues (0 for a run from t = 0).
  double earlier_cpu_seconds() const { return restart_ ? restart_->cpu_seconds : 0.0; }
  // The viscous dissipation of the energy budget up to the restart's time (0 for a run from t = 0).
  double earlier_viscous_dissipation() const;

 private:
  bool due(double t) const;
  double next_time() const { return scheduled_time(next_, every_); }
  const Scene& scene_;
  const Model& model_;
  const Checkpoint* restart_;
  std::string path_;
  std::string run_id_;
  const SteadyStateMonitor* steady_ = nullptr;
  const ViscousDissipation* dissipation_ = nullptr;
  double every_ = 0;
  long next_ = 1;              // index k of the next scheduled checkpoint time k * every
  double stop_ = -1;           // the last stop time handed to the integrator (limit)
};

}  // namespace arksph
