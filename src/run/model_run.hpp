// `arksph run`, written once for one process and for the ranks of a decomposed run: the set-up (the
// model, the output folder, the initial state, the restart, the output, the integrator) and the
// RunStrategy the run loop (run/run_loop.hpp) steps through. What differs between one process and
// ranks is the RunProcess it is given (run/run_process.hpp).
//
//   set-up   every process builds the whole model (run/setup.hpp); the root opens the output
//            folder (locked for this run; a fresh run clears an earlier run's outputs, a restart
//            continues only its own run's: run/output_folder.hpp) and prints the header; the
//            process takes its particles and their fields at t = 0; a restart puts the model's
//            particles into the checkpoint's order, checks the checkpoint against the scene and
//            reads the earlier output before RunOutput truncates it; the root opens the output;
//            the energy budget continues from the checkpoint; the projection and the integrator
//            at the initial or the checkpoint's state.
//   collective  every failure of the set-up is agreed by the ranks (RunProcess::together).
#pragma once
#include <chrono>
#include <memory>
#include <optional>
#include <string>

#include "run/checkpointing.hpp"
#include "run/output_folder.hpp"
#include "run/run_loop.hpp"
#include "run/run_output.hpp"
#include "run/run_process.hpp"
#include "run/state_check.hpp"

namespace arksph {

class ModelRun final : public RunStrategy {
 public:
  // Throws InputError for bad input found at set-up (also: the folder is locked by another run,
  // holds foreign files, or another run's output on restart), OutputError if the folder cannot be
  // created; InterruptedDuringSetup for a signal before the first step (run/interrupt.hpp).
  ModelRun(const Scene& scene, const RunOptions& options, RunProcess& process);

  double start_time() const override { return checkpoints_->start_time(); }
  int first_frame() const override { return checkpoints_->first_frame(); }
  TimeIntegrator& integrator() override { return process_.integrator(); }
  void start() override;
  double step(double t, double stop) override { return process_.step(t, stop); }
  double limit(double t_stop) override { return checkpoints_->limit(t_stop); }
  Verdict reflect_and_check(double t, Verdict mine) override;
  Verdict agree_after_step(double t, const Verdict& mine) override;
  void sync_point(double t, long steps) override { process_.sync_point(t, steps); }
  ViscousDissipation* viscous_dissipation() override { return dissipation_ ? &*dissipation_ : nullptr; }
  double viscous_power(double t) override {
    ++diagnostic_evals_;
    return process_.sum(process_.viscous_power(t));
  }
  void write_frame(double t, const StepStats& stats) override;
  bool steady() override { return process_.max(static_cast<std::int64_t>(out_ && out_->steady())) > 0; }
  double steady_rate() const override { return out_ ? out_->steady_rate() : 0.0; }
  void checkpoint_if_due(double t, int frame) override;
  std::string checkpoint_at_end(double t, int frame) override {  // unless the scheduled one was written at t
    return last_checkpoint_ == t ? checkpoints_->path() : checkpoint_now(t, frame);
  }
  std::string checkpoint_now(double t, int frame) override;
  std::string checkpoint_path() const override { return checkpoints_->path(); }
  std::string failure_location(double t) override { return process_.failure_location(t); }
  Verdict numerical_failure(double t, const std::string& what) override { return process_.numerical_failure(t, what); }
  Verdict out_of_memory(double t) override { return process_.out_of_memory(t); }
  void finish(RunResult& result, double wall, double stepping) override;

 private:
  void open_output_folder(const RunOptions& options);
  void open_output(const RunOptions& options, const OutputHistory& earlier);
  std::string write_checkpoint(double t, const double* y, int frame);
  long reflections() const { return reflections_before_ + static_cast<long>(process_.sum(reflections_here_)); }

  const Scene& scene_;
  RunProcess& process_;
  const bool root_;
  const bool write_frames_;  // the run writes frames (and their free_surface array and wall points)
  std::optional<Model> model_;
  std::unique_ptr<OutputFolder> folder_;  // the root's
  std::string run_id_;
  std::optional<Checkpointer> checkpoints_;
  std::optional<RunOutput> out_;  // the root's
  std::optional<StateChecker> checker_;
  std::optional<ViscousDissipation> dissipation_;  // metrics.energy_budget: the same on every process
  long diagnostic_evals_ = 0;  // evaluations for the frames' diagnostics and the energy budget (summary.json)
  long reflections_before_ = 0;  // the run's before a restart
  double reflections_here_ = 0;  // this process's since (summed at checkpoints and at the end)
  bool reflected_ = false;       // this process reflected a particle at the last step
  double last_checkpoint_ = -1;  // time of the last checkpoint written
};

// The set-up and the run loop with `process`. Collective over the processes of `process`.
RunResult run_model(const Scene& scene, const RunOptions& options, RunProcess& process,
                    std::chrono::steady_clock::time_point wall_start);

}  // namespace arksph
