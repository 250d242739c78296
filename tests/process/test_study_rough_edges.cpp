// `arksph study order` and `arksph study work-precision` through the binary: the output folder's
// lock, refusal under an MPI launcher, steps that cannot show an order, a plot that hangs, an output
// folder that cannot be made, an analytic reference that is not finite, runs that `arksph run`
// refuses, and the console line of the work-precision target. Every run is tiny (a 16^2 or smaller
// Taylor-Green vortex to t = 0.01) and has a time limit, so that a version that hangs fails the test.
#include <doctest/doctest.h>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "run_arksph.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;
using arksph::testing::RunOutcome;
using arksph::testing::ScratchDir;

namespace {

const std::string kStudyScene = std::string(ARKSPH_SOURCE_DIR) + "/cases/sweeps/taylor_green_small.toml";

// `arksph ARGS` with the environment `env` (VAR=VALUE ...), killed after `seconds` (exit 124).
RunOutcome study(const std::string& args, const ScratchDir& scratch, const std::string& env = "", int seconds = 120) {
  return arksph::testing::run_command_captured("env " + env + " timeout " + std::to_string(seconds) + " " +
                                                   arksph::testing::arksph_binary() + " " + args,
                                               scratch.dir.string());
}

int lines(const std::string& text) { return static_cast<int>(std::count(text.begin(), text.end(), '\n')); }
bool err_says(const RunOutcome& o, const std::string& text) { return o.err.find(text) != std::string::npos; }

// An order study of Heun-Euler on the vortex to t = 0.01 with `extra` in [study] (which gives dt
// unless `dt` is empty); a tolerance no table misses, so that a finished study exits 0.
std::string order_file(const ScratchDir& scratch, const std::string& extra, const std::string& dt = "[2e-3, 1e-3]",
                       const std::string& name = "order.toml") {
  const std::string path = scratch / name;
  std::ofstream(path) << "[study]\nscene = \"" << kStudyScene << "\"\nset = [\"time.end=0.01\"]\n"
                      << "tables = [\"ARKODE_HEUN_EULER_2_1_2\"]\n"
                      << (dt.empty() ? "" : "dt = " + dt + "\n") << "reference_dt_divisor = 2\ntolerance = 10\n"
                      << extra;
  return path;
}

// A work-precision study of WCSPH on the vortex at 8^2 and 10^2 particles to t = 0.01 against the
// exact solution (or `velocity`).
std::string wp_file(const ScratchDir& scratch,
                    const std::string& velocity = "[\"sin(2*pi*x)*cos(2*pi*y)*exp(-8*pi^2*0.01*t)\", "
                                                  "\"-cos(2*pi*x)*sin(2*pi*y)*exp(-8*pi^2*0.01*t)\"]") {
  const std::string path = scratch / "wp.toml";
  std::ofstream(path) << "[study]\nscene = \"" << kStudyScene << "\"\nset = [\"time.end=0.01\", \"output.every=0.01\"]\n"
                      << "reference = \"analytic\"\nanalytic_velocity = " << velocity << "\n"
                      << "[[scheme]]\nname = \"wcsph\"\nset = [\"method.scheme=wcsph\"]\n"
                      << "[[resolution]]\nname = \"8\"\nset = [\"fluid.spacing=0.125\"]\n"
                      << "[[resolution]]\nname = \"10\"\nset = [\"fluid.spacing=0.1\"]\n";
  return path;
}

// Holds DIR/.arksph.lock as a run does (flock, pid written), until destroyed.
struct HeldLock {
  int fd = -1;
  explicit HeldLock(const std::string& dir) {
    fs::create_directories(dir);
    fd = ::open((dir + "/.arksph.lock").c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    REQUIRE(fd >= 0);
    REQUIRE(::flock(fd, LOCK_EX | LOCK_NB) == 0);
    const std::string pid = std::to_string(::getpid()) + "\n";
    REQUIRE(::pwrite(fd, pid.data(), pid.size(), 0) == static_cast<ssize_t>(pid.size()));
  }
  ~HeldLock() { ::close(fd); }
};

}  // namespace

TEST_CASE("study rough edges: item 14 study order into a folder held by another process exits 2 naming it and the holder") {
  ScratchDir scratch("rough_lock_order");
  const std::string out = scratch / "out";
  const HeldLock lock(out);
  const RunOutcome o = study("study order " + order_file(scratch, "") + " --out " + out, scratch);
  CAPTURE(o.err);
  CHECK(o.code == 2);
  CHECK(lines(o.err) == 1);
  CHECK(err_says(o, out));
  CHECK(err_says(o, "pid " + std::to_string(::getpid())));
  CHECK_FALSE(fs::exists(out + "/order_errors.csv"));
}

TEST_CASE("study rough edges: item 14 study work-precision holds its folder's lock until its end (plot included)") {
  ScratchDir scratch("rough_lock_wp");
  const std::string out = scratch / "out", state = scratch / "lock_state.txt";
  // The plot script runs last: it tries the study folder's lock and writes what it found.
  std::ofstream(scratch / "probe.py") << "import fcntl, os, sys\n"
                                      << "fd = os.open(os.path.join(os.path.dirname(sys.argv[1]), '.arksph.lock'), os.O_RDWR)\n"
                                      << "try:\n    fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)\n    s = 'free'\n"
                                      << "except OSError:\n    s = 'held'\n"
                                      << "open('" << state << "', 'w').write(s)\n";
  const RunOutcome o = study("study work-precision " + wp_file(scratch) + " --quiet --out " + out, scratch,
                             "ARKSPH_PLOT_WORK_PRECISION=" + (scratch / "probe.py"));
  CAPTURE(o.err);
  CHECK(o.code == 0);
  CHECK(arksph::testing::slurp(state) == "held");
  // And a second study into the folder while one holds it is refused.
  const HeldLock lock(out);
  const RunOutcome second = study("study work-precision " + wp_file(scratch) + " --quiet --out " + out, scratch);
  CHECK(second.code == 2);
  CHECK(lines(second.err) == 1);
  CHECK(err_says(second, "pid " + std::to_string(::getpid())));
}

TEST_CASE("study rough edges: item 14 a study under an MPI launcher of 2 processes is refused (exit 2, one line)") {
  ScratchDir scratch("rough_mpi");
  const std::string file = order_file(scratch, "");
  for (const char* kind : {"order ", "work-precision "}) {
    CAPTURE(kind);
    const std::string path = std::string(kind) == "order " ? file : wp_file(scratch);
    const RunOutcome rank0 = study("study " + std::string(kind) + path + " --out " + (scratch / "out"), scratch,
                                   "OMPI_COMM_WORLD_SIZE=2 OMPI_COMM_WORLD_RANK=0");
    CAPTURE(rank0.err);
    CHECK(rank0.code == 2);
    CHECK(lines(rank0.err) == 1);
    CHECK(err_says(rank0, "MPI launcher"));
    const RunOutcome rank1 = study("study " + std::string(kind) + path + " --out " + (scratch / "out"), scratch,
                                   "OMPI_COMM_WORLD_SIZE=2 OMPI_COMM_WORLD_RANK=1");
    CHECK(rank1.code == 2);
    CHECK(rank1.err.empty());  // rank 0 says it for both
    CHECK_FALSE(fs::exists(scratch / "out"));
  }
}

TEST_CASE("study rough edges: item 16 a step that cannot advance time is refused before any run (exit 2 naming it)") {
  ScratchDir scratch("rough_no_progress");
  const RunOutcome o = study("study order " + order_file(scratch, "", "[1e-3, 1e-300]") + " --out " + (scratch / "out"),
                             scratch, "", 60);
  CAPTURE(o.err);
  CHECK(o.code == 2);
  CHECK(lines(o.err) == 1);
  CHECK(err_says(o, "study.dt"));
  CHECK(err_says(o, "1e-300"));
  CHECK_FALSE(fs::exists(scratch / "out"));
  // The same in a table's own list.
  const RunOutcome per_table = study(
      "study order " + order_file(scratch, "[dt_for]\nARKODE_HEUN_EULER_2_1_2 = [1e-3, 1e-300]\n") + " --out " +
          (scratch / "out"),
      scratch, "", 60);
  CHECK(per_table.code == 2);
  CHECK(err_says(per_table, "dt_for.ARKODE_HEUN_EULER_2_1_2"));
}

TEST_CASE("study rough edges: item 17 a plot that hangs is stopped at ARKSPH_PLOT_TIMEOUT, the study's exit code stands") {
  ScratchDir scratch("rough_plot_hang");
  std::ofstream(scratch / "hang.py") << "import time\ntime.sleep(120)\n";
  const std::string out = scratch / "out";
  const RunOutcome o = study("study order " + order_file(scratch, "") + " --quiet --out " + out, scratch,
                             "ARKSPH_PLOT_ORDER=" + (scratch / "hang.py") + " ARKSPH_PLOT_TIMEOUT=2", 60);
  CAPTURE(o.err);
  CHECK(o.code == 0);  // 124: the study waited for the plot
  CHECK(lines(o.err) == 1);
  CHECK(err_says(o, "did not finish within 2 s"));
  CHECK(fs::exists(out + "/order_fit.csv"));
}

TEST_CASE("study rough edges: item 19 --out naming a regular file exits 5 with one line, as batch does") {
  ScratchDir scratch("rough_out_file");
  const std::string file = scratch / "a_file";
  std::ofstream(file) << "not a folder\n";
  const RunOutcome order = study("study order " + order_file(scratch, "") + " --out " + file, scratch);
  CAPTURE(order.err);
  CHECK(order.code == 5);
  CHECK(lines(order.err) == 1);
  CHECK(err_says(order, "cannot write " + file));
  const RunOutcome wp = study("study work-precision " + wp_file(scratch) + " --out " + file, scratch);
  CAPTURE(wp.err);
  CHECK(wp.code == 5);
  CHECK(lines(wp.err) == 1);
}

TEST_CASE("study rough edges: item 21 an analytic reference that is not finite is named, not measured as error 0") {
  ScratchDir scratch("rough_nan_reference");
  const std::string nan_velocity = "[\"sqrt(x - 2)\", \"0\"]";  // NaN everywhere in the unit box
  const RunOutcome order = study(
      "study order " + order_file(scratch, "reference = \"analytic\"\nanalytic_velocity = " + nan_velocity + "\n") +
          " --out " + (scratch / "out_order"),
      scratch);
  CAPTURE(order.err);
  CHECK(order.code == 2);  // not 4 with an order of 0 from errors of 0
  CHECK(lines(order.err) == 1);
  CHECK(err_says(order, "study.analytic_velocity"));
  CHECK(err_says(order, "not finite"));
  CHECK_FALSE(fs::exists(scratch / "out_order/order_errors.csv"));
  const RunOutcome wp = study("study work-precision " + wp_file(scratch, nan_velocity) + " --quiet --out " +
                                  (scratch / "out_wp"),
                              scratch);
  CAPTURE(wp.err);
  CHECK(wp.code == 2);  // not 3 "no run finished"
  CHECK(lines(wp.err) == 1);
  CHECK(err_says(wp, "study.analytic_velocity"));
  CHECK(err_says(wp, "not finite"));
  CHECK_FALSE(err_says(wp, "no run finished"));
}

TEST_CASE("study rough edges: item 22 an IMEX pair under isph with C&R's projection is refused with run's message") {
  ScratchDir scratch("rough_imex_isph");
  const std::string sets = "--set time.end=0.01 --set method.scheme=isph --set method.projection=cummins_rudman";
  const RunOutcome run = study("run " + kStudyScene + " " + sets + " --set time.imex=true --out " + (scratch / "run"), scratch);
  REQUIRE(run.code == 2);
  const auto at = run.err.find("time.imex: ");
  REQUIRE(at != std::string::npos);
  const std::string reason = run.err.substr(at, run.err.find('\n', at) - at);
  std::ofstream(scratch / "imex.toml")
      << "[study]\nscene = \"" << kStudyScene << "\"\n"
      << "set = [\"time.end=0.01\", \"method.scheme=isph\", \"method.projection=cummins_rudman\"]\n"
      << "tables = []\nimex_pairs = [\"ARK324L2SA\"]\ndt = [2e-3, 1e-3]\nreference_dt_divisor = 2\n";
  const RunOutcome o = study("study order " + (scratch / "imex.toml") + " --out " + (scratch / "out"), scratch);
  CAPTURE(o.err);
  CHECK(o.code == 2);
  CHECK(lines(o.err) == 1);
  CHECK(err_says(o, reason));
  CHECK_FALSE(fs::exists(scratch / "out"));
}

TEST_CASE("study rough edges: item 34 equal steps and steps longer than time.end are refused naming the key") {
  ScratchDir scratch("rough_steps");
  const RunOutcome equal = study("study order " + order_file(scratch, "", "[1e-3, 1e-3]") + " --out " + (scratch / "out"),
                                 scratch);
  CAPTURE(equal.err);
  CHECK(equal.code == 2);  // not 4 with an order of -nan
  CHECK(lines(equal.err) == 1);
  CHECK(err_says(equal, "study.dt"));
  const RunOutcome longer = study("study order " + order_file(scratch, "", "[0.05, 0.02]") + " --out " + (scratch / "out"),
                                  scratch);
  CAPTURE(longer.err);
  CHECK(longer.code == 2);  // not an order of 0
  CHECK(lines(longer.err) == 1);
  CHECK(err_says(longer, "study.dt"));
  CHECK(err_says(longer, "time.end"));
  CHECK_FALSE(fs::exists(scratch / "out"));
}

TEST_CASE("study rough edges: item 4 work-precision says what its target is, and the study files' keys are documented") {
  ScratchDir scratch("rough_wp_target");
  const RunOutcome o = study("study work-precision " + wp_file(scratch) + " --quiet --out " + (scratch / "out"), scratch,
                             "ARKSPH_PLOT_WORK_PRECISION=/nonexistent");
  CAPTURE(o.err);
  CHECK(o.code == 0);
  CHECK(o.out.find("target: L2 error") != std::string::npos);
  CHECK(o.out.find("geometric mean") != std::string::npos);  // no target_error in the file
  // docs/user-guide.md lists every key of both study files in a table row.
  const std::string guide = arksph::testing::slurp(std::string(ARKSPH_SOURCE_DIR) + "/docs/user-guide.md");
  for (const char* key : {"scene", "set", "output", "jobs", "reference", "analytic_velocity", "reference_set",
                          "target_error", "title", "tables", "imex_pairs", "dt", "reference_table",
                          "reference_dt_divisor", "tolerance"}) {
    CAPTURE(key);
    CHECK(guide.find("| `study." + std::string(key) + "` |") != std::string::npos);
  }
  for (const char* key : {"[[scheme]]", "[[resolution]]", "[dt_for]"}) {
    CAPTURE(key);
    CHECK(guide.find("| `" + std::string(key)) != std::string::npos);
  }
}
