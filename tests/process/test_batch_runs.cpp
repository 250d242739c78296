// `arksph batch`, the real binary: the CI sweep of cases/sweeps (12 runs, a resumed second
// invocation), a failing run and a crashing run. The sweep and JSON readers alone:
// unit/test_batch_sweep.cpp.
#include <doctest/doctest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/errors.hpp"
#include "io/checkpoint.hpp"
#include "io/json_reader.hpp"
#include "study/batch.hpp"
#include "study/sweep.hpp"
#include "test_support.hpp"

using namespace arksph;
namespace fs = std::filesystem;
using arksph::testing::count_lines;

namespace {
const std::string kSweepDir = std::string(ARKSPH_SOURCE_DIR) + "/cases/sweeps";

struct BinaryOutcome {
  int code = -1;
  std::string err;
};

BinaryOutcome run_binary(const std::string& args, const testing::ScratchDir& scratch) {
  static int calls = 0;
  const std::string err = scratch / ("stderr_" + std::to_string(calls++) + ".txt");
  const int status = std::system((std::string(ARKSPH_BINARY) + " " + args + " >/dev/null 2>" + err).c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, testing::slurp(err)};
}

int column(const std::vector<std::string>& header, const std::string& name) {
  for (std::size_t i = 0; i < header.size(); ++i)
    if (header[i] == name) return static_cast<int>(i);
  FAIL("no column " << name);
  return -1;
}

std::string sweep_text(const std::string& body) {
  return "[sweep]\nscene = \"taylor_green_small.toml\"\n" + body;
}

}  // namespace

// The CI sweep: 12 runs, each must finish ok (status "ok" in its summary.json, exit 0); the
// combined CSV has one row per run with the varied values; a second invocation runs nothing.
TEST_CASE("batch: the CI sweep runs 12 runs ok, and a second invocation skips them all") {
  testing::ScratchDir scratch("batch_ci");
  const std::string out = scratch / "ci";
  const BinaryOutcome first = run_binary("batch " + kSweepDir + "/ci_sweep.toml --jobs 2 --out " + out, scratch);
  CHECK(first.code == 0);
  const auto rows = testing::read_csv(out + "/batch.csv");
  REQUIRE(rows.size() == 13);  // header + 12 runs
  const int status = column(rows[0], "status"), skipped = column(rows[0], "skipped"),
            kernel = column(rows[0], "method.kernel"), ke = column(rows[0], "kinetic_energy");
  int wendland = 0;
  for (std::size_t r = 1; r < rows.size(); ++r) {
    CHECK(rows[r][status] == "ok");
    CHECK(rows[r][skipped] == "0");
    CHECK(std::stod(rows[r][ke]) > 0);  // the metrics of summary.json made it into the table
    wendland += rows[r][kernel] == "wendland_quintic";
    CHECK(fs::exists(out + "/" + rows[r][0] + "/summary.json"));
  }
  CHECK(wendland == 6);
  CHECK(count_lines(first.err) >= 12);  // a progress line per run
  const JsonValue j = read_json_file(out + "/batch.json");
  CHECK(j.find("runs")->items.size() == 12);
  CHECK(j.find("runs_not_ok")->number == 0);

  const BinaryOutcome second = run_binary("batch " + kSweepDir + "/ci_sweep.toml --jobs 2 --out " + out, scratch);
  CHECK(second.code == 0);
  const auto again = testing::read_csv(out + "/batch.csv");
  REQUIRE(again.size() == 13);
  for (std::size_t r = 1; r < again.size(); ++r) {
    CHECK(again[r][skipped] == "1");
    CHECK(again[r][status] == "ok");
  }
}

// A run that fails (time.max_steps = 1 stops it with exit 3) must not stop the others, and the
// batch exits non-zero. A value the scene reader refuses makes the sweep bad: exit 2, nothing runs.
TEST_CASE("batch: a failing run gives a non-zero exit, a bad value is a bad sweep (exit 2)") {
  testing::ScratchDir scratch("batch_fail");
  const std::string scene = kSweepDir + "/taylor_green_small.toml";
  std::ofstream(scratch / "fail.toml") << "[sweep]\nscene = \"" << scene
                                       << "\"\nset = [\"time.end=0.02\"]\n[[vary]]\nkey = \"time.max_steps\"\nvalues = [1, 100000]\n";
  const BinaryOutcome o = run_binary("batch " + (scratch / "fail.toml") + " --out " + (scratch / "out"), scratch);
  CHECK(o.code == 3);
  const auto rows = testing::read_csv(scratch / "out/batch.csv");
  REQUIRE(rows.size() == 3);
  const int status = column(rows[0], "status"), code = column(rows[0], "exit_code");
  CHECK(rows[1][status] == "failed");
  CHECK(rows[1][code] == "3");
  CHECK(rows[2][status] == "ok");

  std::ofstream(scratch / "bad.toml") << "[sweep]\nscene = \"" << scene
                                      << "\"\n[[vary]]\nkey = \"method.kernel\"\nvalues = [\"cubic_spline\", \"no_such_kernel\"]\n";
  const BinaryOutcome b = run_binary("batch " + (scratch / "bad.toml") + " --out " + (scratch / "bad"), scratch);
  CHECK(b.code == 2);
  CHECK(count_lines(b.err) == 1);
  CHECK(b.err.find("method.kernel") != std::string::npos);
  CHECK_FALSE(fs::exists(scratch / "bad/batch.csv"));
}

// A run killed by a signal (here a stand-in executable that sends itself SIGSEGV) is recorded as
// "crashed" with exit code 128 + 11, and the other runs of the batch still finish.
TEST_CASE("batch: a crashing run is recorded and does not stop the batch") {
  testing::ScratchDir scratch("batch_crash");
  const std::string fake = scratch / "fake_arksph.sh";
  // Crashes for the first kernel, else delegates to the real binary.
  std::ofstream(fake) << "#!/bin/sh\ncase \"$*\" in *kernel=cubic_spline*) kill -SEGV $$ ;; esac\nexec " << ARKSPH_BINARY
                      << " \"$@\"\n";
  fs::permissions(fake, fs::perms::owner_all);
  const Sweep sw = read_sweep_text(sweep_text("set = [\"time.end=0.01\"]\n[[vary]]\nkey = \"method.kernel\"\n"
                                              "values = [\"cubic_spline\", \"wendland_quintic\"]\n"),
                                   kSweepDir + "/crash.toml");
  BatchOptions opt;
  opt.executable = fake;
  opt.output = scratch / "out";
  opt.jobs = 2;
  opt.quiet = true;
  const BatchResult res = run_batch(sw, opt);
  REQUIRE(res.runs.size() == 2);
  CHECK(res.runs[0].status == "crashed");
  CHECK(res.runs[0].exit_code == 128 + 11);
  CHECK(res.runs[1].status == "ok");
  CHECK(res.failed == 1);
  CHECK(testing::slurp(scratch / "out/batch.csv").find(",crashed,139,") != std::string::npos);
}

// A run that stopped before its end (here a stand-in executable: the run goes to t = 0.05 of 0.1,
// writes its checkpoint there, loses its summary.json and is killed, as in a lost session) is
// continued from its checkpoint by the next invocation, and ends bit-identical to a batch that was
// never stopped: t = 0.05 is a scheduled checkpoint of the sweep's runs, and a restart from a
// scheduled checkpoint repeats the uninterrupted run bit for bit (docs/user-guide.md, "Checkpoints
// and restart"). A run that starts
// anew would also end equal, so the checkpoint time and the `resumed` column tell the two apart.
TEST_CASE("batch: a run stopped before its end continues from its checkpoint") {
  testing::ScratchDir scratch("batch_resume");
  const std::string fake = scratch / "stopping_arksph.sh";
  std::ofstream(fake) << "#!/bin/sh\n"
                      << "case \"$*\" in *--restart*) exec " << ARKSPH_BINARY << " \"$@\" ;; esac\n"
                      << "prev=; for a in \"$@\"; do [ \"$prev\" = --out ] && out=$a; prev=$a; done\n"
                      << ARKSPH_BINARY << " \"$@\" --set time.end=0.05\n"
                      << "rm -f \"$out/summary.json\"\n"
                      << "kill -KILL $$\n";
  fs::permissions(fake, fs::perms::owner_all);
  const Sweep sw = read_sweep_text(sweep_text("set = [\"time.end=0.1\", \"output.every=0.025\", \"output.checkpoint_every=0.05\"]\n[[vary]]\n"
                                              "key = \"method.kernel\"\nvalues = [\"wendland_quintic\"]\n"),
                                   kSweepDir + "/resume.toml");
  BatchOptions opt;
  opt.output = scratch / "stopped";
  opt.quiet = true;
  opt.executable = fake;
  const BatchResult first = run_batch(sw, opt);
  REQUIRE(first.runs.size() == 1);
  CHECK(first.runs[0].status == "crashed");
  const std::string dir = first.runs[0].dir;
  CHECK(read_checkpoint(dir + "/checkpoint.h5").time == 0.05);

  opt.executable = ARKSPH_BINARY;
  const BatchResult second = run_batch(sw, opt);
  CHECK(second.runs[0].status == "ok");
  CHECK(second.runs[0].resumed);
  CHECK_FALSE(second.runs[0].skipped);
  const auto rows = testing::read_csv(opt.output + "/batch.csv");
  REQUIRE(rows.size() == 2);
  CHECK(rows[1][column(rows[0], "resumed")] == "1");

  opt.output = scratch / "uninterrupted";
  const BatchResult whole = run_batch(sw, opt);
  REQUIRE(whole.runs[0].status == "ok");
  CHECK_FALSE(whole.runs[0].resumed);
  const Checkpoint a = read_checkpoint(dir + "/checkpoint.h5"), b = read_checkpoint(whole.runs[0].dir + "/checkpoint.h5");
  CHECK(a.time == 0.1);
  CHECK(a.steps == b.steps);
  CHECK(a.state == b.state);  // bit for bit
  CHECK(testing::slurp(dir + "/timeseries.csv") == testing::slurp(whole.runs[0].dir + "/timeseries.csv"));

  // A third invocation finds the resumed run finished.
  opt.output = scratch / "stopped";
  CHECK(run_batch(sw, opt).runs[0].skipped);
}
