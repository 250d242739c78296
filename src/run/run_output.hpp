// Everything a run writes: VTP frames + PVD, timeseries.csv (flow and case metrics), summary.json.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "run/setup.hpp"
#include "run/run_result.hpp"
#include "diagnostics/flow_metrics.hpp"
#include "diagnostics/frame_reduction.hpp"
#include "diagnostics/steady_state.hpp"
#include "diagnostics/viscous_dissipation.hpp"
#include "io/csv_writer.hpp"
#include "io/pvd_writer.hpp"
#include "io/frame.hpp"
#include "io/summary_json.hpp"

namespace arksph {

struct OutputHistory;  // checkpoint restart (run/output_resume.hpp)

// What a run reports in summary.json besides its integrator's counters and the output's own.
struct RunTotals {
  double wall_seconds = 0;
  // timing.stepping: the wall time of the steps alone (each step with its checks, reflections and
  // re-sorts or migrations), without set-up, frames and checkpoints (negative: not reported).
  double stepping_seconds = -1;
  // cpu_seconds: CPU time of the run (user + system, all threads and ranks), summed over its
  // restarts (run/cpu_time.hpp; negative: not reported).
  double cpu_seconds = -1;
  long diagnostic_evals = 0;
  long wall_reflections = 0;
  long neighbor_rebuilds = 0;
  // method.reorder_every: the sync points that re-sorted (or migrated) the particles, and their
  // time (reorders negative: re-sorting off).
  long reorders = -1;
  double reorder_seconds = 0;
  // "mpi": the ranks of the run (1 for one process) and, over several ranks, what the
  // decomposition did (distributed/distributed_run.hpp).
  Json mpi = Json::object().set("ranks", 1);
};

class RunOutput {
 public:
  // Opens timeseries.csv in the existing output folder (OutputError if it cannot). `run_id` goes
  // into particles.pvd and summary.json (run/output_folder.hpp). `pieces` > 0 (output.pieces on
  // that many ranks): each frame is particles_NNNNNN.pvtp naming the ranks' pieces
  // (io/pvtp_writer.hpp), which the ranks write themselves; no whole frame is written.
  RunOutput(const Scene& scene, Model& model, const RunOptions& options, std::string run_id, int pieces = 0);
  void add_term(const std::string& t) { model_.terms.push_back(t); }
  // A frame, its diagnostics reduced over the run's processes (diagnostics/frame_reduction.hpp,
  // run/model_run.cpp): the CSV row and files of `diag`, and the frame: the pieces' index (the
  // constructor's `pieces`), else `whole` (rows in any order, written in id order; null: no frame
  // file; 1D: also profile_1d.csv). output.walls: `walls`, the frame's wall points
  // (run/wall_frame.hpp, rows in id order), as walls_NNNNNN.vtp, or with pieces the index
  // walls_NNNNNN.pvtp of the ranks' wall pieces. Throws OutputError when a file cannot be written.
  void record(const FrameDiagnostics& diag, const StepStats& stats, const Frame* whole, const Frame* walls = nullptr);
  // Writes summary.json (also after a failure: status "failed" with the diagnosis). Throws OutputError.
  void finish(const RunResult& result, const StepStats& stats, const RunTotals& totals);
  // time.steady_tolerance: the flow was steady at the latest output time (diagnostics/steady_state.hpp).
  bool steady() const { return steady_.steady(); }
  double steady_rate() const { return steady_.rate(); }
  const SteadyStateMonitor& steady_monitor() const { return steady_; }
  // metrics.energy_budget: the viscous dissipation whose total each CSV row carries (the run loop
  // advances it after every step; the same on every rank).
  void set_viscous_dissipation(const ViscousDissipation* w) { dissipation_ = w; }
  // Restart: the steady-state samples of the checkpoint (rows of `columns` values: t, KE,
  // centreline...), taken up again so that the windows continue across the restart.
  void restore_steady(const std::vector<double>& rows, int columns);
  // Restart: continue an earlier run's frames, PVD entries and CSV rows (defined in run/output_resume.cpp).
  void resume(const OutputHistory& earlier);
  int frames() const { return frames_; }  // frames written so far: the number of the next one

 private:
  std::vector<std::string> csv_columns() const;
  const Scene& scene_;
  Model& model_;
  RunOptions options_;
  std::string run_id_;
  std::unique_ptr<PvdCollection> pvd_;
  std::unique_ptr<PvdCollection> walls_pvd_;  // output.walls: walls.pvd
  TimeseriesCsv csv_;
  int frames_ = 0;
  double last_t_ = 0;
  double last_divergence_ = 0;  // r.m.s. of D u at the last output (projection/divergence_operator.hpp)
  FlowMetrics last_;
  Json case_metrics_ = Json::object();
  SteadyStateMonitor steady_;
  const ViscousDissipation* dissipation_ = nullptr;
  double steady_time_ = -1;  // the output time at which the flow was found steady (-1: not yet)
  double eps_max_window_ = 0;  // Poiseuille: max eps for t* in [0.5, 2]
  double output_seconds_ = 0, diagnostic_seconds_ = 0;
  int pieces_;  // 0: whole frames; else the ranks whose pieces a frame's index names
};

}  // namespace arksph
