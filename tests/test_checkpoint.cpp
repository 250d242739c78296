// Checkpoints and restart (io/checkpoint, run/checkpointing): the HDF5 round trip is bit-exact, a
// run restarted from a checkpoint ends bit-identical to the run that never stopped, a killed write
// leaves the previous checkpoint valid, and SIGTERM stops a run with a checkpoint and exit code 143.
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
#include <limits>
#include <sstream>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include "core/errors.hpp"
#include "test_support.hpp"
#include "io/checkpoint.hpp"
#include "io/scene_reader.hpp"

namespace fs = std::filesystem;
using namespace arksph;
using arksph::testing::ScratchDir;
using arksph::testing::slurp;

namespace {



// The doubly periodic Taylor-Green box of test_wcsph.cpp, with a fixed step and checkpoints.
const std::string kTaylorGreen = arksph::testing::kTaylorGreenBox + R"toml(
[time]
end = 0.2
dt = 0.002
[output]
every = 0.05
checkpoint_every = 0.1
)toml";

// Runs the binary; returns its exit code (-1 if it did not exit normally). stdout and stderr go to
// `log` (appended). One OpenMP thread: these runs are tiny, and spinning threads on a loaded
// machine made them 50 times slower (results do not depend on the thread count).
int run_arksph(const std::string& args, const std::string& log) {
  const std::string cmd = "OMP_NUM_THREADS=1 " + std::string(ARKSPH_BINARY) + " " + args + " >>" + log + " 2>&1";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// A checkpoint with awkward values: signed zero, subnormals, infinities, extreme ids.
Checkpoint sample_checkpoint(std::size_t n, int dim, bool has_density) {
  Checkpoint c;
  c.dimension = dim;
  c.has_density = has_density;
  c.n = n;
  c.time = 0.1 + 0.2;  // 0.30000000000000004: not a short decimal
  c.steps = 123456789012L;
  c.rhs_evals = 987654321098L;
  c.step_attempts = 7;
  c.error_test_fails = 3;
  c.last_step = std::nextafter(1e-3, 1.0);
  c.next_step = 1.0 / 3.0;
  c.output_frame = 42;
  c.checkpoint_index = 5;
  c.wall_reflections = 11;
  c.scene_toml = "[scene]\nname = \"caf\xC3\xA9 \\\"quoted\\\"\"\n# long line " + std::string(70000, 'x') + "\n";
  c.state.resize(c.layout().size());
  for (std::size_t i = 0; i < c.state.size(); ++i) c.state[i] = std::sin(1.0 + static_cast<double>(i)) * 1e3 / 7.0;
  c.state[0] = -0.0;
  c.state[1] = std::numeric_limits<double>::denorm_min();
  c.state[2] = -std::numeric_limits<double>::infinity();
  c.state[3] = std::numeric_limits<double>::max();
  for (std::size_t a = 0; a < n; ++a) {
    c.mass.push_back(1.0 / (3.0 + static_cast<double>(a)));
    c.rho0.push_back(a % 2 ? 1.8 : 1.0);
    c.id.push_back(static_cast<std::int64_t>(a) * 4000000000LL - 7);
    c.phase.push_back(static_cast<std::int32_t>(a % 3) - 1);
  }
  return c;
}

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

void check_equal(const Checkpoint& a, const Checkpoint& b) {
  CHECK(a.format_version == b.format_version);
  CHECK(a.dimension == b.dimension);
  CHECK(a.has_density == b.has_density);
  CHECK(a.n == b.n);
  CHECK(std::memcmp(&a.time, &b.time, sizeof a.time) == 0);
  CHECK(a.steps == b.steps);
  CHECK(a.rhs_evals == b.rhs_evals);
  CHECK(a.step_attempts == b.step_attempts);
  CHECK(a.error_test_fails == b.error_test_fails);
  CHECK(std::memcmp(&a.last_step, &b.last_step, sizeof a.last_step) == 0);
  CHECK(std::memcmp(&a.next_step, &b.next_step, sizeof a.next_step) == 0);
  CHECK(a.output_frame == b.output_frame);
  CHECK(a.checkpoint_index == b.checkpoint_index);
  CHECK(a.wall_reflections == b.wall_reflections);
  CHECK(a.scene_toml == b.scene_toml);
  CHECK(same_bits(a.state, b.state));
  CHECK(same_bits(a.mass, b.mass));
  CHECK(same_bits(a.rho0, b.rho0));
  CHECK(same_bits(a.id, b.id));
  CHECK(same_bits(a.phase, b.phase));
}

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

}  // namespace

TEST_CASE("checkpoint: write + read round trip is bit-exact") {
  ScratchDir dir("roundtrip");
  for (const auto& [n, dim, rho] : {std::tuple{257ul, 2, true}, std::tuple{100000ul, 2, false}, std::tuple{5ul, 1, true}}) {
    CAPTURE(n);
    const Checkpoint c = sample_checkpoint(n, dim, rho);
    write_checkpoint(dir / "checkpoint.h5", c);
    CHECK_FALSE(fs::exists(dir / "checkpoint.h5.tmp"));
    check_equal(read_checkpoint(dir / "checkpoint.h5"), c);
  }
}

TEST_CASE("checkpoint: unreadable files give one-line InputErrors naming the file") {
  ScratchDir dir("bad");
  CHECK_THROWS_AS(read_checkpoint(dir / "missing.h5"), InputError);
  std::ofstream(dir / "text.h5") << "not hdf5\n";
  try {
    read_checkpoint(dir / "text.h5");
    FAIL("no exception");
  } catch (const InputError& e) {
    const std::string what = e.what();
    CHECK(what.find("text.h5") != std::string::npos);
    CHECK(what.find('\n') == std::string::npos);
  }
  CHECK_THROWS_AS(write_checkpoint(dir / "no/such/dir/checkpoint.h5", sample_checkpoint(3, 2, true)), std::runtime_error);
}

// A kill -9 while the next checkpoint is written leaves `checkpoint.h5.tmp` cut short beside the
// previous, complete `checkpoint.h5`; the reader opens the latter and ignores the former.
TEST_CASE("checkpoint: an interrupted write leaves the previous checkpoint valid") {
  ScratchDir dir("killed");
  const std::string path = dir / "checkpoint.h5";
  const Checkpoint before = sample_checkpoint(2000, 2, true);
  write_checkpoint(path, before);
  Checkpoint next = before;
  next.time = 0.5;
  write_checkpoint(dir / "other.h5", next);
  const std::string full = slurp(dir / "other.h5");
  std::ofstream(path + ".tmp", std::ios::binary).write(full.data(), static_cast<std::streamsize>(full.size() / 2));
  check_equal(read_checkpoint(path), before);
  CHECK_THROWS_AS(read_checkpoint(path + ".tmp"), InputError);  // the torn file itself is rejected cleanly

  // The next successful write replaces the stale temporary.
  write_checkpoint(path, next);
  CHECK_FALSE(fs::exists(path + ".tmp"));
  CHECK(read_checkpoint(path).time == 0.5);
}

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

TEST_CASE("checkpoint: output.checkpoint_every is read, validated and written back") {
  std::ostringstream warnings;
  const Scene s = read_scene_text(kTaylorGreen, "tg", {}, warnings);
  CHECK(s.checkpoint_every == 0.1);
  CHECK(read_scene_text(s.resolved_toml, "resolved", {}, warnings).checkpoint_every == 0.1);
  CHECK(s.resolved_toml.find("checkpoint_every = 0.1") != std::string::npos);
  CHECK(read_scene_text(default_scene_toml(), "default", {}, warnings).checkpoint_every == 0.0);
  CHECK_THROWS_AS(read_scene_text(kTaylorGreen, "tg", {"output.checkpoint_every=-1"}, warnings), InputError);
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
  CHECK(read_checkpoint(half + "/checkpoint.h5").time == 0.1);
  REQUIRE(run_arksph("run --restart " + half + "/checkpoint.h5 --quiet --set time.end=0.2", log) == 0);
  check_same_state(full + "/checkpoint.h5", half + "/checkpoint.h5");
  CHECK(slurp(full + "/timeseries.csv") == slurp(half + "/timeseries.csv"));
  CHECK(slurp(full + "/particles.pvd") == slurp(half + "/particles.pvd"));
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
  const Checkpoint c = read_checkpoint(out + "/checkpoint.h5");
  CHECK(c.time >= 0.01);
  CHECK(c.time < 1000);
  CHECK(c.output_frame >= 2);
  CHECK(slurp(out + "/summary.json").find("\"status\": \"interrupted\"") != std::string::npos);

  const std::string t_end = std::to_string(c.time + 0.02);
  CHECK(run_arksph("run --restart " + out + "/checkpoint.h5 --quiet --set time.end=" + t_end, dir / "log.txt") == 0);
  CHECK(read_checkpoint(out + "/checkpoint.h5").time == std::stod(t_end));
  CHECK(slurp(out + "/summary.json").find("\"status\": \"ok\"") != std::string::npos);
}
