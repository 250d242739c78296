// Faults that arise while a run goes: a NaN or infinity in the right-hand side or in a restarted
// state (exit 3 naming the time, the particle id and the quantity), an adaptive step that underflows
// (exit 3), a speed past time.blowup_speed (exit 3), and signals: SIGHUP and SIGQUIT stop a run like
// SIGTERM (checkpoint, summary.json, 128 + signal); a signal during set-up stops it there
// (128 + signal, no checkpoint).
// ARKSPH_TEST_BINARY runs these against another build (cli_outcome.hpp).
#include <doctest/doctest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <thread>

#include "cli_outcome.hpp"
#include "io/checkpoint.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;
using arksph::testing::arksph_binary;
using arksph::testing::CliOutcome;
using arksph::testing::run_cli;
using arksph::testing::ScratchDir;
using arksph::testing::slurp;

namespace {

const char* const kFaultsScene = arksph::testing::kMinimalScene;  // tests/process/cli_outcome.hpp

// Exit 3, one line, "t = ..., particle id <id>: <quantity>" (any id if `id` is empty).
void check_diagnosed(const CliOutcome& o, const std::string& id, const std::string& quantity) {
  CAPTURE(o.err);
  CHECK(o.code == 3);
  CHECK(o.lines() == 1);
  CHECK(o.says("t = "));
  CHECK(o.says("particle id " + id));
  CHECK(o.says(quantity));
  if (!id.empty()) CHECK(o.says("particle id " + id + ": " + quantity));
}

// Starts `arksph args...` with stdout and stderr to `log`; `blocked_pending`: the signal is blocked
// and already pending when the binary starts (the earliest a signal can arrive, deterministically).
pid_t spawn(const std::vector<std::string>& args, const std::string& log, int blocked_pending = 0) {
  const pid_t child = fork();
  if (child != 0) return child;
  const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  dup2(fd, 1);
  dup2(fd, 2);
  setenv("OMP_NUM_THREADS", "1", 1);
  // An ignored disposition survives exec and arksph keeps it (e.g. SIGHUP under nohup): the test
  // starts from the defaults, unblocked.
  sigset_t all;
  sigemptyset(&all);
  for (int s : {SIGHUP, SIGINT, SIGQUIT, SIGTERM}) {
    signal(s, SIG_DFL);
    sigaddset(&all, s);
  }
  sigprocmask(SIG_UNBLOCK, &all, nullptr);
  if (blocked_pending) {
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, blocked_pending);
    sigprocmask(SIG_BLOCK, &set, nullptr);  // the mask and the pending signal survive exec
    raise(blocked_pending);
  }
  std::vector<char*> argv;
  const std::string bin = arksph_binary();
  argv.push_back(const_cast<char*>(bin.c_str()));
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  execv(bin.c_str(), argv.data());
  _exit(127);
}

// Exit code of the child, -1 if a signal ended it; gives up (kills it) after `seconds`.
int wait_exit(pid_t child, int seconds) {
  int status = 0;
  const auto start = std::chrono::steady_clock::now();
  while (waitpid(child, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() - start > std::chrono::seconds(seconds)) {
      kill(child, SIGKILL);
      waitpid(child, &status, 0);
      return -2;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

TEST_CASE("hostile runs: a NaN or infinity arising in the run exits 3 naming time, particle id and quantity") {
  ScratchDir dir("hostile_nan");
  const std::string scene = dir / "S.toml", out = dir / "out";
  std::ofstream(scene) << kFaultsScene;
  auto run = [&](const std::string& args) { return run_cli("run " + scene + " --quiet --out " + out + " " + args); };
  // The body force turns NaN after t = 0.003 at the particle at (0.95, 0.95) only: id 99, whatever
  // its index after the shuffle of the initial order and the re-sort by cell.
  const std::string corner_nan = "--set 'fluid.body_force=[\"t > 0.003 && x > 0.9 && y > 0.9 ? 0/0 : 0\", \"0\"]'";
  for (const std::string& variant : {"", "--set method.scheme=isph", "--set method.scheme=isph-gpps",
                                     "--set time.imex=true", "--set time.dt=0.001"}) {
    CAPTURE(variant);
    check_diagnosed(run(corner_nan + " --set fluid.shuffle_initial_order=true " + variant), "99", "acceleration ax = NaN");
  }
  // An infinity (log of 0 at the particles at x = 0.05) after t = 0.003.
  check_diagnosed(run("--set 'fluid.body_force=[\"0\", \"t > 0.003 ? log(x - 0.05) : 0\"]'"), "0",
                  "acceleration ay = -inf");
  // A lid so fast that the pressure overflows in the first right-hand side.
  check_diagnosed(run("--set 'boundary.top.velocity=[1e200, 0]'"), "", "acceleration");
}

TEST_CASE("hostile runs: a NaN in the state of a checkpoint exits 3 naming the particle id") {
  ScratchDir dir("hostile_restart_nan");
  const std::string scene = dir / "S.toml", out = dir / "out";
  std::ofstream(scene) << kFaultsScene;
  REQUIRE(run_cli("run " + scene + " --quiet --out " + out).code == 0);
  const std::string file = out + "/checkpoint.h5";
  arksph::Checkpoint c = arksph::read_checkpoint(file);
  std::size_t a = 0;  // the index of the particle with id 42 (the file keeps the run's order)
  while (a < c.n && c.id[a] != 42) ++a;
  REQUIRE(a < c.n);
  c.state[c.layout().vel(1) + a] = std::numeric_limits<double>::quiet_NaN();
  arksph::write_checkpoint(file, c);
  check_diagnosed(run_cli("run --restart " + file + " --quiet --set time.end=0.02"), "42", "velocity v");
}

TEST_CASE("hostile runs: an adaptive step that underflows exits 3 instead of running for ever") {
  ScratchDir dir("hostile_underflow");
  const std::string scene = dir / "S.toml";
  std::ofstream(scene) << kFaultsScene;
  // An acceleration of 1e300 limits the step to ~1e-151 (0.25 sqrt(h / a)): 10^149 steps to
  // time.end. A version without the check runs until the time limit (exit 124).
  const CliOutcome o = run_cli("run " + scene + " --quiet --out " + (dir / "out") + " --set 'fluid.body_force=[1e300, 0]'"
                               " --set method.regularisation=none --set method.density_diffusion=none",
                               "", 60);
  CAPTURE(o.err);
  CHECK(o.code == 3);
  CHECK(o.lines() == 1);
  CHECK(o.says("underflowed"));
}

TEST_CASE("hostile runs: SIGHUP and SIGQUIT stop a run like SIGTERM, with checkpoint and summary") {
  const std::string tg = arksph::testing::test_scene("taylor_green_checkpoints.toml");
  for (const auto& [sig, code] : {std::pair{SIGHUP, 129}, std::pair{SIGQUIT, 131}}) {
    CAPTURE(sig);
    ScratchDir dir("hostile_signal_" + std::to_string(sig));
    const std::string scene = dir / "tg.toml", out = dir / "out";
    std::ofstream(scene) << tg;
    const pid_t child = spawn({"run", scene, "--quiet", "--out", out, "--set", "time.end=1000", "--set",
                               "output.every=0.01"},
                              dir / "log.txt");
    REQUIRE(child > 0);
    const auto start = std::chrono::steady_clock::now();
    while (!fs::exists(out + "/particles_000001.vtp") && std::chrono::steady_clock::now() - start < std::chrono::seconds(60))
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    REQUIRE(fs::exists(out + "/particles_000001.vtp"));
    kill(child, sig);
    CHECK(wait_exit(child, 120) == code);
    const arksph::Checkpoint c = arksph::read_checkpoint(out + "/checkpoint.h5");
    CHECK(c.steps >= 5);  // at least the frame at t = 0.01 (5 steps of 0.002) was written before
    CHECK(slurp(out + "/summary.json").find("\"status\": \"interrupted\"") != std::string::npos);
  }
}

TEST_CASE("hostile runs: a signal during set-up stops the run there with 128 + signal and no checkpoint") {
  for (const auto& [sig, code] : {std::pair{SIGTERM, 143}, std::pair{SIGHUP, 129}, std::pair{SIGQUIT, 131},
                                  std::pair{SIGINT, 130}}) {
    CAPTURE(sig);
    ScratchDir dir("hostile_setup_signal_" + std::to_string(sig));
    const std::string scene = dir / "S.toml", out = dir / "out", log = dir / "log.txt";
    std::ofstream(scene) << kFaultsScene;
    // The signal is pending from the start: a version that does not poll during set-up (and keeps
    // the signal blocked) finishes the run (exit 0).
    const pid_t child = spawn({"run", scene, "--quiet", "--out", out}, log, sig);
    REQUIRE(child > 0);
    CHECK(wait_exit(child, 120) == code);
    const std::string said = slurp(log);
    CAPTURE(said);
    CHECK(said.find("during set-up") != std::string::npos);
    CHECK(said.find("no checkpoint") != std::string::npos);
    CHECK(!fs::exists(out + "/checkpoint.h5"));
  }
}

// time.blowup_speed sets the speed at which a run counts as blown up. A periodic box under a uniform
// body force g = 10 has no pressure gradient: every particle moves at u = g t, so a bound of 5 is
// crossed at t = 0.5 by the step that ends there or just after (the acceleration's step limit
// 0.25 sqrt(h / g) = 0.029), while the same run without the key (bound 100 x max(c, 10 sqrt(g L)))
// reaches its end.
TEST_CASE("hostile runs: time.blowup_speed stops a run whose particles pass it") {
  ScratchDir dir("blowup_speed");
  const std::string scene = dir / "S.toml", out = dir / "out";
  std::ofstream(scene) << kFaultsScene << R"(
[boundary]
left = { kind = "periodic" }
right = { kind = "periodic" }
bottom = { kind = "periodic" }
top = { kind = "periodic" }
)";
  auto run = [&](const std::string& args) {
    return run_cli("run " + scene + " --quiet --out " + out + " --set time.end=0.7 --set 'fluid.body_force=[\"10\", \"0\"]' " +
                   args);
  };
  CHECK(run("").code == 0);
  const CliOutcome o = run("--set time.blowup_speed=5");
  check_diagnosed(o, "", "exceeds the blow-up bound 5 (time.blowup_speed)");
  // "t = T, particle id N: speed S exceeds ...": the first step past u = 5 ends in [0.5, 0.53].
  const double t = std::stod(o.err.substr(o.err.find("t = ") + 4));
  const double speed = std::stod(o.err.substr(o.err.find("speed ") + 6));
  CHECK(t >= 0.5);
  CHECK(t <= 0.53);
  CHECK(speed == doctest::Approx(10 * t).epsilon(1e-6));  // u = g t: no pressure gradient in the periodic box
  CHECK(run("--set time.blowup_speed=-1").code == 2);
}

// A failed run of a projection scheme at a free surface names that known limit and the scheme that
// runs such flows; the same failure under WCSPH does not. A column 5 particles wide and 10 high collapses
// under g = 1 and passes the bound 0.3 within t = 0.3 under either scheme.
TEST_CASE("hostile runs: a failed ISPH run at a free surface names the known limit") {
  ScratchDir dir("known_limit");
  const std::string scene = dir / "S.toml", out = dir / "out";
  std::ofstream(scene) << kFaultsScene;
  auto run = [&](const std::string& scheme) {
    return run_cli("run " + scene + " --quiet --out " + out + " --overwrite --set method.scheme=" + scheme +
                   " --set time.end=1 --set time.blowup_speed=0.3 --set 'fluid.region=\"x < 0.5\"'" +
                   " --set 'fluid.body_force=[\"0\", \"-1\"]'");
  };
  for (const char* scheme : {"isph", "wcsph"}) {
    CAPTURE(scheme);
    const CliOutcome o = run(scheme);
    check_diagnosed(o, "", "exceeds the blow-up bound 0.3 (time.blowup_speed)");
    const bool named = o.err.find("at a free surface is known to fail in violent flows") != std::string::npos;
    CHECK(named == (std::string(scheme) == "isph"));
  }
}
