// Checkpoints of real runs (run/checkpointing): a run restarted from a checkpoint ends
// bit-identical to the run that never stopped, bad restarts are refused, a SIGKILL during repeated
// writes never leaves a torn file, and SIGTERM stops a run with a checkpoint and exit code 143.
#include <doctest/doctest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include "checkpoint_sample.hpp"
#include "io/checkpoint.hpp"
#include "run_arksph.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;
using namespace arksph;
using arksph::testing::run_arksph;
using arksph::testing::sample_checkpoint;
using arksph::testing::ScratchDir;
using arksph::testing::slurp;

namespace {

const std::string kTaylorGreen = arksph::testing::test_scene("taylor_green_checkpoints.toml");

// The x, y, u, v, rho blocks of two checkpoints hold the same bits.
void check_same_state(const std::string& path_a, const std::string& path_b) {
  const Checkpoint a = read_checkpoint(path_a), b = read_checkpoint(path_b);
  REQUIRE(a.n == b.n);
  REQUIRE(a.has_density);
  CHECK(a.time == b.time);
  CHECK(a.steps == b.steps);
  const StateLayout L = a.layout();
  const char* names[] = {"x", "y", "u", "v", "rho"};
  const std::size_t offsets[] = {L.pos(0), L.pos(1), L.vel(0), L.vel(1), L.rho()};
  for (int k = 0; k < 5; ++k) {
    CAPTURE(names[k]);
    CHECK(std::memcmp(a.state.data() + offsets[k], b.state.data() + offsets[k], a.n * sizeof(double)) == 0);
  }
}

// The number after "key": in a summary.json text (NaN if the key is missing).
double summary_number(const std::string& text, const std::string& key) {
  const std::size_t at = text.find("\"" + key + "\": ");
  return at == std::string::npos ? std::nan("") : std::stod(text.substr(at + key.size() + 4));
}

}  // namespace

// The same with a real SIGKILL: a child rewrites the checkpoint in a loop and is killed at some
// point of a write; what is left at `checkpoint.h5` is always one complete checkpoint.
TEST_CASE("checkpoint: SIGKILL during repeated writes never leaves a torn checkpoint.h5") {
  ScratchDir dir("sigkill");
  const std::string path = dir / "checkpoint.h5";
  Checkpoint c = sample_checkpoint(200000, 2, true);
  c.steps = 0;
  write_checkpoint(path, c);
  for (int delay_ms : {30, 75, 160}) {
    CAPTURE(delay_ms);
    const pid_t child = fork();
    REQUIRE(child >= 0);
    if (child == 0) {
      for (int k = 1;; ++k) {
        c.steps = k;
        std::fill(c.state.begin(), c.state.end(), static_cast<double>(k));
        write_checkpoint(path, c);
      }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
    kill(child, SIGKILL);
    int status = 0;
    waitpid(child, &status, 0);
    CHECK(WIFSIGNALED(status));
    const Checkpoint back = read_checkpoint(path);
    CHECK(back.n == c.n);
    if (back.steps > 0)  // a state written by the child: every value equals its step number
      CHECK(std::all_of(back.state.begin(), back.state.end(), [&](double v) { return v == back.steps; }));
  }
}

// Run to T; run to T/2 then restart to T: the final states are bit-identical (fixed step; the
// checkpoint time T/2 is a stop time of both). The output directory continues: the restarted run's
// timeseries.csv and particles.pvd equal those of the uninterrupted run.
TEST_CASE("checkpoint: a restarted run ends bit-identical to the uninterrupted run") {
  ScratchDir dir("restart");
  const std::string scene = dir / "tg.toml", log = dir / "log.txt";
  std::ofstream(scene) << kTaylorGreen;
  const std::string full = dir / "full", half = dir / "half";
  REQUIRE(run_arksph("run " + scene + " --quiet --out " + full, log) == 0);
  REQUIRE(run_arksph("run " + scene + " --quiet --out " + half + " --set time.end=0.1", log) == 0);
  Checkpoint first = read_checkpoint(half + "/checkpoint.h5");
  CHECK(first.time == 0.1);
  CHECK(first.cpu_seconds > 0);
  // CPU time adds up over restarts: with the first segment's CPU time set to 10^4 s in its
  // checkpoint (no test run takes that long), the second segment's checkpoint and summary report
  // more than 10^4 s; a count that started again at 0 would not.
  first.cpu_seconds = 1e4;
  write_checkpoint(half + "/checkpoint.h5", first);
  REQUIRE(run_arksph("run --restart " + half + "/checkpoint.h5 --quiet --set time.end=0.2", log) == 0);
  const double cpu_end = read_checkpoint(half + "/checkpoint.h5").cpu_seconds;
  CHECK(cpu_end > 1e4);
  CHECK(summary_number(slurp(half + "/summary.json"), "cpu_seconds") >= cpu_end);
  check_same_state(full + "/checkpoint.h5", half + "/checkpoint.h5");
  CHECK(slurp(full + "/timeseries.csv") == slurp(half + "/timeseries.csv"));
  // The same entries; the run id comment differs (two runs).
  const auto entries = [](const std::string& pvd) {
    std::string kept, line;
    std::istringstream in(pvd);
    while (std::getline(in, line))
      if (line.find("<!-- arksph run_id=") == std::string::npos) kept += line + "\n";
    return kept;
  };
  CHECK(entries(slurp(full + "/particles.pvd")) == entries(slurp(half + "/particles.pvd")));
  CHECK(fs::exists(half + "/particles_000004.vtp"));
  const std::string summary = slurp(half + "/summary.json");
  CHECK(summary.find("\"steps\": 100") != std::string::npos);
}

TEST_CASE("checkpoint: a restart that changes the particle set or does not go further is bad input") {
  ScratchDir dir("restart_bad");
  const std::string scene = dir / "tg.toml", log = dir / "log.txt", out = dir / "out";
  std::ofstream(scene) << kTaylorGreen;
  REQUIRE(run_arksph("run " + scene + " --quiet --out " + out + " --set time.end=0.01", log) == 0);
  const std::string ckpt = out + "/checkpoint.h5";
  CHECK(run_arksph("run --restart " + ckpt + " --quiet --set time.end=0.01", log) == 2);
  CHECK(run_arksph("run --restart " + ckpt + " --quiet --set time.end=0.02 --set fluid.spacing=0.125", log) == 2);
  CHECK(run_arksph("run --restart " + ckpt + " --quiet --set time.end=0.02 --set method.density_mode=summation", log) == 2);
  CHECK(run_arksph("run --restart " + dir / "nothing.h5" + " --quiet", log) == 2);
  CHECK(run_arksph("run " + scene + " --restart " + ckpt + " --quiet", log) == 2);
  // Each refusal is one line naming the checkpoint file.
  std::istringstream lines(slurp(log));
  int refusals = 0;
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("arksph: ", 0) == 0 && (line.find(".h5") != std::string::npos || line.find("tg.toml") != std::string::npos) &&
        line.find("restart from") == std::string::npos && line.find("finished") == std::string::npos &&
        line.find("scene '") == std::string::npos)
      ++refusals;
  CHECK(refusals == 5);
}

// SIGTERM after the first frame: exit code 143, a readable checkpoint, summary.json "interrupted";
// the run then continues from it.
TEST_CASE("checkpoint: SIGTERM writes a checkpoint and exits 143") {
  ScratchDir dir("sigterm");
  const std::string scene = dir / "tg.toml", out = dir / "out";
  std::ofstream(scene) << kTaylorGreen;
  const pid_t child = fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    const int null = open("/dev/null", O_WRONLY);
    dup2(null, 1);
    dup2(null, 2);
    setenv("OMP_NUM_THREADS", "1", 1);
    execl(ARKSPH_BINARY, ARKSPH_BINARY, "run", scene.c_str(), "--quiet", "--out", out.c_str(), "--set",
          "time.end=1000", "--set", "output.every=0.01", static_cast<char*>(nullptr));
    _exit(127);
  }
  const auto start = std::chrono::steady_clock::now();
  while (!fs::exists(out + "/particles_000001.vtp") && std::chrono::steady_clock::now() - start < std::chrono::seconds(60))
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  REQUIRE(fs::exists(out + "/particles_000001.vtp"));
  kill(child, SIGTERM);
  int status = 0;
  waitpid(child, &status, 0);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 143);
  // Where the signal lands depends on the machine's load, so the checkpoint is checked against the
  // run's own record: at least the frame at t = 0.01 was written before the signal; the time is on
  // the fixed-step grid (steps x dt, round-off of summing the steps: 1e-12 relative); output_frame
  // counts the frames on disk, and the checkpoint lies between the last frame and the next one
  // (inclusive).
  const Checkpoint c = read_checkpoint(out + "/checkpoint.h5");
  const double dt = 0.002, every = 0.01;  // the scene's time.dt and the output.every set above
  MESSAGE("SIGTERM checkpoint at t = ", c.time, ", step ", c.steps, ", frames ", c.output_frame);
  CHECK(c.steps >= 5);
  CHECK(c.time == doctest::Approx(static_cast<double>(c.steps) * dt).epsilon(1e-12));
  long frames_on_disk = 0;
  for (const auto& e : fs::directory_iterator(out)) frames_on_disk += e.path().extension() == ".vtp";
  CHECK(c.output_frame == frames_on_disk);
  CHECK(c.output_frame >= 2);
  CHECK(static_cast<double>(c.output_frame - 1) * every <= c.time * (1 + 1e-12));
  // <=: a signal on the step that reaches the next frame time stops the run before that frame
  CHECK(c.time <= static_cast<double>(c.output_frame) * every * (1 + 1e-12));
  CHECK(slurp(out + "/summary.json").find("\"status\": \"interrupted\"") != std::string::npos);

  const std::string t_end = std::to_string(c.time + 0.02);
  CHECK(run_arksph("run --restart " + out + "/checkpoint.h5 --quiet --set time.end=" + t_end, dir / "log.txt") == 0);
  CHECK(read_checkpoint(out + "/checkpoint.h5").time == std::stod(t_end));
  CHECK(slurp(out + "/summary.json").find("\"status\": \"ok\"") != std::string::npos);
}
