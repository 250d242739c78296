// `arksph batch SWEEP.toml`: runs the Cartesian product of a sweep (study/sweep.hpp) as child
// processes of the same binary (`/proc/self/exe run SCENE --out DIR --quiet --set ...`), at most
// `jobs` at a time, so that a crashing run cannot take the batch down. Each run writes its own
// folder <output>/<run name>/ (the run's files, run.log with its stdout and stderr, batch_run.txt
// with its command line). Runs whose folder already holds a summary.json with status "ok" for the
// same command line are skipped (resume); a run of the same command line that stopped before its end
// with a checkpoint.h5 in its folder continues from it (`arksph run --restart`). The results are combined into <output>/batch.csv and
// <output>/batch.json: each run's --set values, status, exit code, wall time, steps and its
// summary.json metrics. One progress line per finished run on stderr. The batch locks its folder
// like a run does (run/output_folder.hpp): a second batch into the same folder exits 2.
// With `launcher_ranks`, a batch started as K processes by an MPI launcher spreads its runs over
// them (study/batch_ranks.hpp): rank r runs the runs with index ≡ r (mod K), rank 0 writes the
// combined files.
#pragma once
#include <string>
#include <vector>

#include "study/sweep.hpp"

namespace arksph {

struct BatchOptions {
  int jobs = 0;             // 0: the sweep's jobs, else the number of cores
  std::string output;       // "" : the sweep's output folder
  std::string executable;   // the arksph binary ("" : /proc/self/exe)
  bool quiet = false;       // no progress lines
  double progress_every = 5;  // wall seconds between the lines of the scene check ("checked the scenes of ...")
  bool launcher_ranks = false;  // share the runs with the other processes of an MPI launch (if any)
  bool folder_locked = false;   // the caller holds the output folder's lock (a study): not taken again
};

struct BatchRunResult {
  std::string name, dir;
  std::vector<std::string> values;  // one per column (Sweep::columns)
  std::string status;               // ok | failed | bad_input | crashed | interrupted | missing_summary
  int exit_code = 0;                // the child's exit code (128 + signal if killed)
  bool skipped = false;             // finished earlier (resume)
  double wall_seconds = 0;
  long steps = 0, rhs_evals = 0;
  std::vector<std::pair<std::string, std::string>> metrics;  // name, number as written
  bool resumed = false;             // continued from the checkpoint.h5 of an earlier, stopped launch
};

struct BatchResult {
  std::vector<BatchRunResult> runs;
  int failed = 0, skipped = 0;
  double wall_seconds = 0;
  bool partial = false;  // a rank > 0 of a launch: its own runs only, no combined files written
  int signal = 0;        // SIGHUP/SIGINT/SIGQUIT/SIGTERM received: forwarded to the running children
};

// Validates every run's scene in-process first (a bad value throws InputError before anything
// runs), then runs the batch. The caller maps failed > 0 to a non-zero exit.
BatchResult run_batch(const Sweep& sweep, const BatchOptions& options);

// The combined files (also called by run_batch).
void write_batch_csv(const Sweep& sweep, const BatchResult& result, const std::string& path);
void write_batch_json(const Sweep& sweep, const BatchResult& result, const std::string& path);

}  // namespace arksph
