// arksph command line: run, list, help. Exit codes: README.md, "Exit codes".
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <new>
#include <sstream>
#include <string>
#include <vector>

#include "run/omp_thread_limit.hpp"
#include "run/omp_wait_policy.hpp"
#include "run/interrupt.hpp"
#include "run/simulation.hpp"
#include "app/cli_args.hpp"
#include "app/run_report.hpp"
#include "app/study_commands.hpp"
#include "core/errors.hpp"
#include "io/checkpoint.hpp"
#include "io/input_file.hpp"
#include "io/scene_catalog.hpp"
#include "io/scene_reader.hpp"
#ifdef ARKSPH_WITH_MPI
#include <memory>

#include "distributed/distributed_run.hpp"
#include "parallel/communicator.hpp"
#include "run/launcher_ranks.hpp"
#endif

namespace {

#ifdef ARKSPH_WITH_MPI
// `arksph run` under an MPI launcher of several processes: MPI is initialised and the run is
// decomposed over the ranks (distributed/distributed_run.hpp). Without a launcher, or with one
// process, MPI is never initialised and the run is the one-process run.
std::unique_ptr<arksph::parallel::MpiSession> g_mpi;
std::unique_ptr<arksph::parallel::Communicator> g_comm;
#endif
// Ranks other than 0 of a decomposed run: the ranks agree on every outcome, rank 0 reports it.
bool g_quiet_rank = false;

arksph::RunResult run_scene(const arksph::Scene& scene, const arksph::RunOptions& options) {
#ifdef ARKSPH_WITH_MPI
  if (g_comm) return arksph::distributed::run_distributed(scene, options, *g_comm);
#endif
  return arksph::run_simulation(scene, options);
}

// The overview: every command in one line; each command's own --help gives its options.
const char* kUsage =
    "arksph - SPH for incompressible viscous flow (WCSPH and ISPH on SUNDIALS ARKODE)\n"
    "\n"
    "usage: arksph COMMAND [ARGS]   (arksph COMMAND --help: that command's options and files)\n"
    "  run [SCENE.toml]        runs a scene file, or the embedded default scene (lid-driven cavity, Re = 100)\n"
    "  run --restart FILE      continues a run from its checkpoint\n"
    "  batch SWEEP.toml        parameter sweep in parallel child runs\n"
    "  study order STUDY.toml  observed temporal order of ARKODE tables\n"
    "  study work-precision STUDY.toml   error against wall time, schemes x resolutions\n"
    "  list                    registered kernels, schemes, viscosity models, ARKODE tables, ...\n"
    "  default-scene           prints the embedded default scene (a commented template of every key)\n"
    "  scene-reference         prints the reference of every scene key and registered part (Markdown)\n"
    "  --version               version and git commit\n"
    "  mpirun -n P arksph run SCENE.toml   WCSPH or ISPH decomposed over P MPI ranks (docs/parallel.md;\n"
    "                          as root add --allow-run-as-root; on P > cores add --oversubscribe)\n"
    "\n"
    "output (in the output directory): particles_NNNNNN.vtp + particles.pvd (ParaView), timeseries.csv,\n"
    "summary.json, checkpoint.h5 (every output.checkpoint_every and at the end).\n"
    "Exit codes (README.md): 0 finished, 1 internal error (a bug), 2 bad input, 3 numerical failure\n"
    "(output so far stays valid), 4 order study flagged, 5 output could not be written, 6 out of memory,\n"
    "128+N stopped by signal N (130 SIGINT, 143 SIGTERM, 129 SIGHUP, 131 SIGQUIT; checkpoint.h5 written, continue with --restart).\n";

const char* kRunUsage =
    "usage: arksph run [SCENE.toml] [--out DIR] [--set KEY=VALUE ...] [--overwrite] [--quiet] [--progress-every S]\n"
    "       arksph run --restart FILE [--out DIR] [--set KEY=VALUE ...] [--quiet] [--progress-every S]\n"
    "       mpirun -n P arksph run SCENE.toml [...]\n"
    "\n"
    "Runs a scene file, or without one the embedded default scene (lid-driven cavity, Re = 100; see\n"
    "arksph default-scene). Every scene key is listed in docs/scene-reference.md (arksph scene-reference).\n"
    "\n"
    "options:\n"
    "  --set KEY=VALUE   overrides a scene key by its dotted path, one word per --set:\n"
    "                    --set time.end=2 --set method.kernel=cubic_spline\n"
    "  --out DIR         output folder (same as --set output.directory=DIR); --out=DIR works too\n"
    "  --overwrite       write into a folder that also holds files other than arksph outputs\n"
    "  --restart FILE    continues the run saved in checkpoint FILE (the scene is the one stored in FILE\n"
    "                    with the --set overrides, e.g. --set time.end=10); output continues in its folder\n"
    "  --quiet, -q       no progress line on stderr\n"
    "  --progress-every S  when stderr is not a terminal (a log), a progress line at least every S wall\n"
    "                    seconds besides the one per output frame (default 30; 0: after every step)\n"
    "  --help, -h        this text\n"
    "\n"
    "A fresh run replaces an earlier run's outputs in its folder (docs/user-guide.md, \"The output folder\").\n"
    "Under an MPI launcher with P > 1 processes the run is decomposed over the ranks (WCSPH and ISPH;\n"
    "docs/parallel.md lists what is refused there). Open MPI needs --allow-run-as-root as root and\n"
    "--oversubscribe for more ranks than cores.\n"
    "\n"
    "files written in the output folder: particles_NNNNNN.vtp + particles.pvd (ParaView), timeseries.csv,\n"
    "summary.json, checkpoint.h5 (every output.checkpoint_every and at the end), .arksph.lock while running.\n"
    "Exit codes: 0 finished, 1 internal error (a bug), 2 bad input, 3 numerical failure (output so far\n"
    "stays valid), 5 output could not be written, 6 out of memory, 128+N stopped by signal N (checkpoint\n"
    "written; continue with --restart).\n";

const char* kListUsage =
    "usage: arksph list\n"
    "Prints every family of registered parts (kernels, schemes, viscosity models, ARKODE tables, ...) with\n"
    "the scene key that chooses it and a one-line summary of each part. docs/scene-reference.md has more.\n";

const char* kDefaultSceneUsage =
    "usage: arksph default-scene [> FILE.toml]\n"
    "Prints the embedded default scene, the lid-driven cavity at Re = 100 that arksph run runs without a\n"
    "scene file, as commented TOML: every key with its default, range and unit. A template for new scenes.\n";

const char* kSceneReferenceUsage =
    "usage: arksph scene-reference [> FILE.md]\n"
    "Prints the reference of every scene key (type, default, range, unit, description) and of every\n"
    "registered part, in Markdown (docs/scene-reference.md is this text).\n";

// Commands without options: --help prints `usage` (exit 0); any other argument is bad input.
bool wants_help(int argc, char** argv, const char* command, const char* usage) {
  for (int i = 0; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      std::fputs(usage, stdout);
      return true;
    }
    throw arksph::InputError(arksph::echo_value(a) + ": unknown argument (see arksph " + command + " --help)");
  }
  return false;
}

// Text printed to stdout in full, or OutputError (exit 5) when it could not be (a full disk, a closed pipe).
int print_text(const char* text, const char* what) {
  if (std::fputs(text, stdout) < 0 || std::fflush(stdout) != 0 || std::ferror(stdout))
    throw arksph::OutputError(std::string(what) + ": standard output could not be written (" + std::strerror(errno) + ")");
  return 0;
}

int cmd_list(int argc, char** argv) {
  if (wants_help(argc, argv, "list", kListUsage)) return 0;
  for (const arksph::FamilyInfo& f : arksph::scene_families()) {
    std::printf("%s (%s):\n", f.family.c_str(), f.key.c_str());
    for (const auto& e : f.entries) std::printf("  %-32s %s\n", e.name.c_str(), e.summary.c_str());
  }
  return 0;
}

int cmd_run(int argc, char** argv) {
  std::string scene_path, restart_path;
  std::vector<std::string> sets;
  arksph::RunOptions options;
  const std::vector<std::string> args = arksph::split_option_values(argc, argv, {"--set", "--out", "--restart", "--progress-every"});
  const int count = static_cast<int>(args.size());
  for (int i = 0; i < count; ++i) {
    const std::string& a = args[i];
    if (a == "--help" || a == "-h") {
      std::fputs(kRunUsage, stdout);
      return 0;
    } else if (a == "--set" || a == "--out") {
      if (i + 1 >= count) throw arksph::InputError(a + ": missing value");
      const std::string& v = args[++i];
      sets.push_back(a == "--set" ? arksph::set_value(v) : "output.directory=" + arksph::toml_string(v));
    } else if (a == "--restart") {
      if (i + 1 >= count) throw arksph::InputError(a + ": missing checkpoint file");
      if (!restart_path.empty()) throw arksph::InputError("--restart given twice (" + restart_path + ", " + args[i + 1] + ")");
      restart_path = args[++i];
    } else if (a == "--progress-every") {
      if (i + 1 >= count) throw arksph::InputError(a + ": missing number of seconds");
      options.progress_every = arksph::seconds_value(a, args[++i]);
    } else if (a == "--quiet" || a == "-q") {
      options.quiet = true;
    } else if (a == "--overwrite") {
      options.overwrite = true;
    } else if (!a.empty() && a[0] == '-') {
      throw arksph::InputError(arksph::echo_value(a) + ": unknown option (see arksph run --help)");
    } else if (scene_path.empty()) {
      scene_path = a;
    } else {
      throw arksph::InputError(arksph::echo_value(a) + ": more than one scene file given");
    }
  }
  if (!restart_path.empty() && !scene_path.empty())
    throw arksph::InputError(scene_path + ": give either a scene file or --restart FILE, not both");
  arksph::install_interrupt_handlers();  // before the set-up, which polls for a signal (run/interrupt.hpp)
  arksph::Checkpoint checkpoint;  // --restart: the scene is the one stored in the checkpoint
  if (!restart_path.empty()) {
    checkpoint = arksph::read_checkpoint(restart_path);
    arksph::check_restart_values(checkpoint, restart_path);
    options.restart = &checkpoint;
    options.restart_path = restart_path;
    std::printf("arksph: restart from %s at t = %.17g (step %ld)\n", restart_path.c_str(), checkpoint.time,
                checkpoint.steps);
  }
  // The scene's warnings: once, from rank 0 of a decomposed run (every rank reads the same scene).
  std::ostringstream other_ranks_warnings;
  std::ostream& warnings = g_quiet_rank ? static_cast<std::ostream&>(other_ranks_warnings) : std::cerr;
  const arksph::Scene scene =
      !restart_path.empty()
          ? arksph::read_scene_text(checkpoint.scene_toml, restart_path + " [scene_toml]", sets, warnings)
      : scene_path.empty()
          ? arksph::read_scene_text(arksph::default_scene_toml(), "<embedded default>", sets, warnings)
          : arksph::read_scene_text(arksph::read_input_file(scene_path, "scene"), scene_path, sets, warnings);
  const arksph::RunResult r = run_scene(scene, options);
  if (g_quiet_rank) return r.exit_code;
  if (r.interrupted) {
    std::fprintf(stderr, "arksph: %s; checkpoint written to %s (continue: arksph run --restart %s)\n",
                 r.message.c_str(), r.checkpoint.c_str(), r.checkpoint.c_str());
  } else if (r.exit_code == 5) {  // what could not be written; the checkpoint if it was
    std::fprintf(stderr, "arksph: %s (output so far kept in %s%s)\n", r.message.c_str(), scene.directory.c_str(),
                 r.checkpoint.empty() ? "" : ("; checkpoint " + r.checkpoint + " written").c_str());
  } else if (r.exit_code != 0) {
    std::fprintf(stderr, "arksph: simulation failed: %s (output so far kept in %s)\n", r.message.c_str(),
                 scene.directory.c_str());
  } else {
    if (r.steady_time >= 0)
      std::printf("arksph: steady state at t = %.6g (change rate %.3g < time.steady_tolerance = %g), before time.end = %g\n",
                  r.steady_time, r.steady_rate, scene.steady_tolerance, scene.end);
    std::printf("arksph: finished, output in %s\n", scene.directory.c_str());
    arksph::print_next_steps(scene.directory);
  }
  return r.exit_code;
}

}  // namespace

int main(int argc, char** argv) {
  arksph::prefer_passive_omp_waiting(argv);  // see run/omp_wait_policy.hpp
  // A write beyond the file-size limit (ulimit -f) fails with EFBIG like a write to a full disk, and
  // is reported as one (exit 5, output so far kept) instead of killing the run without a word.
  std::signal(SIGXFSZ, SIG_IGN);
  arksph::bound_omp_threads();  // before the first parallel region (run/omp_thread_limit.hpp)
  try {
    if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h") || !std::strcmp(argv[1], "help")) {
      std::fputs(kUsage, stdout);
      return argc < 2 ? 2 : 0;
    }
    const std::string cmd = argv[1];
    if (cmd == "--version" || cmd == "version") {
      std::fputs(arksph::version_text().c_str(), stdout);
      return 0;
    }
#ifdef ARKSPH_WITH_MPI
    if (cmd == "run" && arksph::launcher_ranks_from_environment().size > 1) {
      g_mpi = std::make_unique<arksph::parallel::MpiSession>(&argc, &argv);
      g_comm = std::make_unique<arksph::parallel::Communicator>();
      g_quiet_rank = g_comm->rank() != 0;
      if (g_quiet_rank && !std::freopen("/dev/null", "w", stdout)) return 1;  // header, progress, final lines: rank 0
    }
#endif
    if (cmd == "run") return cmd_run(argc - 2, argv + 2);
    if (cmd == "list") return cmd_list(argc - 2, argv + 2);
    if (cmd == "batch") return arksph::cmd_batch(argc - 2, argv + 2);
    if (cmd == "study") return arksph::cmd_study(argc - 2, argv + 2);
    if (cmd == "default-scene") {
      if (wants_help(argc - 2, argv + 2, "default-scene", kDefaultSceneUsage)) return 0;
      return print_text(arksph::default_scene_toml(), "default-scene");
    }
    if (cmd == "scene-reference") {
      if (wants_help(argc - 2, argv + 2, "scene-reference", kSceneReferenceUsage)) return 0;
      return print_text(arksph::scene_reference_markdown().c_str(), "scene-reference");
    }
    std::fprintf(stderr, "arksph: %s: unknown command (try arksph --help)\n", arksph::echo_value(cmd).c_str());
    return 2;
  } catch (const arksph::InputError& e) {  // on several ranks: raised alike on every rank, reported by rank 0
    if (!g_quiet_rank) std::fprintf(stderr, "arksph: %s\n", e.what());
    return 2;
  } catch (const arksph::NumericalFailure& e) {
    if (!g_quiet_rank) std::fprintf(stderr, "arksph: simulation failed: %s\n", e.what());
    return 3;
  } catch (const arksph::OutputError& e) {
    if (!g_quiet_rank) std::fprintf(stderr, "arksph: %s\n", e.what());
    return 5;
  } catch (const arksph::OutOfMemory& e) {
    std::fprintf(stderr, "arksph: out of memory: %s\n", e.what());
    return 6;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "arksph: out of memory: an allocation failed while %s\n", arksph::activity().c_str());
    return 6;
  } catch (const arksph::InterruptedDuringSetup& e) {
    std::fprintf(stderr, "arksph: %s\n", e.what());
    return 128 + e.signal;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "arksph: internal error (a bug, please report it): %s\n", e.what());
    return 1;
  }
}
