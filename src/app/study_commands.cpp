// `arksph batch` and `arksph study`: argument parsing around study/batch.hpp, study/order_study.hpp and
// study/work_precision.hpp.
#include "app/study_commands.hpp"

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "app/cli_args.hpp"
#include "core/errors.hpp"
#include "run/interrupt.hpp"
#include "run/launcher_ranks.hpp"
#include "study/batch.hpp"
#include "study/order_study.hpp"
#include "study/work_precision.hpp"

namespace arksph {

namespace {
const char* kBatchUsage =
    "usage: arksph batch SWEEP.toml [--jobs N] [--out DIR] [--set KEY=VALUE ...] [--quiet] [--progress-every S]\n"
    "  Runs the Cartesian product of the sweep's [[vary]] lists over its base scene, N runs at a time, each\n"
    "  a child process `arksph run` writing <out>/<run name>/. Runs already finished ok are skipped;\n"
    "  a run stopped before its end (signal, lost session) continues from its checkpoint.h5, if it wrote one.\n"
    "  --set adds an override to every run (after the sweep's own set list); a varied key is refused (exit 2).\n"
    "  Results: <out>/batch.csv and <out>/batch.json. Exit 0 if every run finished ok, 3 otherwise,\n"
    "  2 for a bad sweep file or a folder in use by another batch (nothing is run), 5 if batch.csv cannot be written.\n"
    "  Under an MPI launcher (mpirun -n K arksph batch ...) the K processes share the runs (rank r runs\n"
    "  those with index r mod K, N at a time each); rank 0 writes the results and gives the exit code.\n"
    "  Before any run, every run's scene is read (a bad one is a bad sweep); a check that takes long says\n"
    "  how far it got every S wall seconds (--progress-every, default 5).\n";

const char* kStudyUsage =
    "usage: arksph study order STUDY.toml [--out DIR] [--set KEY=VALUE ...] [--quiet]\n"
    "  Temporal order of ARKODE tables on one scene at fixed steps (docs/user-guide.md, \"Order study\").\n"
    "  Writes <out>/order_errors.csv and <out>/order_fit.csv; exit 0 if every table is within the\n"
    "  tolerance of its nominal order, 4 if one is flagged, 2 for bad input or a folder in use, 5 if the\n"
    "  output cannot be written.\n"
    "usage: arksph study work-precision STUDY.toml [--out DIR] [--jobs N] [--set KEY=VALUE ...] [--quiet]\n"
    "  Error against wall time for schemes x resolutions (docs/user-guide.md, \"Work-precision study\").\n"
    "  Writes <out>/work_precision.csv (and .png), prints which scheme reaches the target error soonest;\n"
    "  exit 0, 3 if the reference run failed or no run has a finite error, 2 for bad input or a folder in use,\n"
    "  5 if the output cannot be written.\n"
    "  A study runs in one process (not under mpirun). Its plot is given ARKSPH_PLOT_TIMEOUT seconds (default 60).\n"
    "  Study file keys: docs/user-guide.md, \"Studies\".\n";

int parse_int(const std::string& opt, const std::string& v) {
  char* end = nullptr;
  const long n = std::strtol(v.c_str(), &end, 10);
  if (end == v.c_str() || *end || n < 1 || n > 256) throw InputError(opt + " " + v + ": expected an integer in [1, 256]");
  return static_cast<int>(n);
}
// STUDY.toml [--out DIR] [--jobs N] [--set KEY=VALUE ...] [--quiet]; --jobs only for work-precision.
StudyArgs parse_study_args(const std::string& kind, int argc, char** argv) {
  StudyArgs args;
  const bool takes_jobs = kind == "work-precision";
  const std::vector<std::string> list = split_option_values(argc, argv, {"--set", "--out", "--jobs"});
  const int count = static_cast<int>(list.size());
  for (int i = 0; i < count; ++i) {
    const std::string& a = list[i];
    if ((a == "--set" || a == "--out" || (takes_jobs && (a == "--jobs" || a == "-j"))) && i + 1 < count) {
      const std::string& v = list[++i];
      if (a == "--set") args.sets.push_back(set_value(v));
      else if (a == "--out") args.out = v;
      else args.jobs = parse_int(a, v);
    } else if (a == "--quiet" || a == "-q") {
      args.quiet = true;
    } else if (!a.empty() && a[0] == '-') {
      throw InputError(echo_value(a) + ": unknown option or missing value (see arksph study --help)");
    } else if (args.path.empty()) {
      args.path = a;
    } else {
      throw InputError(echo_value(a) + ": more than one study file given");
    }
  }
  if (args.path.empty()) throw InputError("study " + kind + ": missing the study file (see arksph study --help)");
  return args;
}
}  // namespace

int cmd_batch(int argc, char** argv) {
  std::string sweep_path;
  std::vector<std::string> extra_sets;
  BatchOptions opt;
  const std::vector<std::string> list = split_option_values(argc, argv, {"--set", "--out", "--jobs", "--progress-every"});
  const int count = static_cast<int>(list.size());
  for (int i = 0; i < count; ++i) {
    const std::string& a = list[i];
    if (a == "--help" || a == "-h") {
      std::fputs(kBatchUsage, stdout);
      return 0;
    } else if (a == "--progress-every") {
      if (i + 1 >= count) throw InputError(a + ": missing number of seconds");
      opt.progress_every = seconds_value(a, list[++i]);
    } else if (a == "--jobs" || a == "-j" || a == "--out") {
      if (i + 1 >= count) throw InputError(a + ": missing value");
      const std::string& v = list[++i];
      if (a == "--out") opt.output = v;
      else opt.jobs = parse_int(a, v);
    } else if (a == "--set") {
      if (i + 1 >= count) throw InputError(a + ": missing value");
      extra_sets.push_back(set_value(list[++i]));
    } else if (a == "--quiet" || a == "-q") {
      opt.quiet = true;
    } else if (!a.empty() && a[0] == '-') {
      throw InputError(echo_value(a) + ": unknown option (see arksph batch --help)");
    } else if (sweep_path.empty()) {
      sweep_path = a;
    } else {
      throw InputError(echo_value(a) + ": more than one sweep file given");
    }
  }
  if (sweep_path.empty()) throw InputError("batch: missing the sweep file (see arksph batch --help)");
  Sweep sweep = read_sweep_file(sweep_path);
  for (const std::string& set : extra_sets) {  // an override of a varied key would silently replace it
    const std::string key = varied_key_overridden(sweep, set);
    if (key.rfind("output.directory", 0) == 0)
      throw InputError("--set " + echo_value(set) + ": the batch gives every run its own folder inside its output "
                       "folder; choose that folder with --out DIR");
    if (!key.empty())
      throw InputError("--set " + echo_value(set) + ": " + echo_value(key) + " is varied by " + echo_value(sweep_path) +
                       "; remove it from the sweep's [[vary]] or from --set");
  }
  for (auto& run : sweep.runs) run.sets.insert(run.sets.end(), extra_sets.begin(), extra_sets.end());
  sweep.common_sets.insert(sweep.common_sets.end(), extra_sets.begin(), extra_sets.end());
  opt.launcher_ranks = true;  // under mpirun -n K: K processes share the runs (study/batch_ranks.hpp)
  const BatchResult res = run_batch(sweep, opt);
  if (res.signal) {  // the runs it stopped keep their checkpoints; the same command resumes them
    if (!res.partial)
      std::fprintf(stderr, "arksph: batch interrupted by %s; the stopped runs wrote their checkpoints (continue: "
                           "run the same batch command again)\n", interrupt_name(res.signal));
    return 128 + res.signal;
  }
  return res.failed > 0 && !res.partial ? 3 : 0;  // rank 0 reports for all (a nonzero rank > 0 would end the launch)
}

int cmd_study(int argc, char** argv) {
  if (argc < 1 || !std::strcmp(argv[0], "--help") || !std::strcmp(argv[0], "-h")) {
    std::fputs(kStudyUsage, stdout);
    return argc < 1 ? 2 : 0;
  }
  const std::string kind = argv[0];
  if (kind != "order" && kind != "work-precision")
    throw InputError("study " + kind + ": unknown study (expected: order, work-precision)");
  for (int i = 1; i < argc; ++i)
    if (!std::strcmp(argv[i], "--help") || !std::strcmp(argv[i], "-h")) {  // arksph study order --help
      std::fputs(kStudyUsage, stdout);
      return 0;
    }
  const StudyArgs args = parse_study_args(kind, argc - 1, argv + 1);
  // A study runs in one process and its runs are one-process runs: under a launcher of K > 1
  // processes each would run the whole study into the same folder. Refused, rank 0 saying why.
  if (const LauncherRanks ranks = launcher_ranks_from_environment(); ranks.size > 1) {
    if (ranks.rank == 0)
      std::fprintf(stderr,
                   "arksph: study %s: started as %d processes by an MPI launcher; a study runs in one process "
                   "(its runs are one-process runs): start it without mpirun\n",
                   kind.c_str(), ranks.size);
    return 2;
  }
  return kind == "order" ? cmd_order_study(args) : cmd_work_precision_study(args);
}

}  // namespace arksph
