// Faults and hostile input through the command line: writes that fail (a file size limit stands in
// for a full disk), scene paths that are not files, huge values, batch sweeps with long values or
// conflicting overrides, and the small command-line conveniences (--version, --opt=value, what to
// look at after a run). Each test runs the real binary (ARKSPH_TEST_BINARY selects another).
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "run_arksph.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;
using arksph::testing::run_arksph_captured;
using arksph::testing::RunOutcome;
using arksph::testing::ScratchDir;
using arksph::testing::slurp;
using arksph::testing::count_lines;

namespace {

const char* kRunsScene =
    "[domain]\nmin = [0.0, 0.0]\nmax = [1.0, 1.0]\n[fluid]\nspacing = 0.1\n[time]\nend = 0.01\n";

std::string write_scene(const ScratchDir& scratch, const std::string& extra = "") {
  const std::string path = scratch / "S.toml";
  std::ofstream(path) << kRunsScene << extra;
  return path;
}


// The longest line of a text (messages must stay readable).
std::size_t longest_line(const std::string& s) {
  std::size_t best = 0, cur = 0;
  for (char c : s) {
    cur = c == '\n' ? 0 : cur + 1;
    best = std::max(best, cur);
  }
  return best;
}

}  // namespace

// The checkpoint (about 31 kB for 100 particles) does not fit under an 8 kB file size limit, the
// frames (about 5 kB) do. HDF5 must not be left with a half-closed file (which it closes again at exit: SIGSEGV).
TEST_CASE("hostile: a checkpoint that cannot be written exits 5 with the message, no crash, summary.json kept") {
  ScratchDir scratch("ck_full");
  const std::string scene = write_scene(scratch), out = scratch / "out";
  const RunOutcome o = run_arksph_captured("run " + scene + " --quiet --out " + out, scratch.dir.string(), 8000);
  CHECK(o.code == 5);
  CHECK(o.err.find("cannot write " + out + "/checkpoint.h5: File too large") != std::string::npos);
  CHECK(count_lines(o.err) == 1);
  CHECK(slurp(out + "/summary.json").find("\"status\": \"failed\"") != std::string::npos);
  for (const auto& e : fs::directory_iterator(out))  // no temporary left behind
    CHECK(e.path().filename().string().find(".tmp") == std::string::npos);
}

// 10,000 particles: a frame is about 87 kB, the checkpoint about 36 kB, summary.json 3 kB. Under a
// 60 kB limit the first frame fails; the checkpoint and summary.json are still written.
TEST_CASE("hostile: a frame that cannot be written exits 5, and the checkpoint and summary.json are written") {
  ScratchDir scratch("frame_full");
  const std::string scene = write_scene(scratch), out = scratch / "out";
  const RunOutcome o = run_arksph_captured("run " + scene + " --quiet --out " + out +
                                               " --set fluid.spacing=0.01 --set time.end=0.002",
                                           scratch.dir.string(), 60000);
  CHECK(o.code == 5);
  CHECK(o.err.find("cannot write " + out + "/particles_000000.vtp: File too large") != std::string::npos);
  CHECK(fs::exists(out + "/checkpoint.h5"));
  const std::string summary = slurp(out + "/summary.json");
  CHECK(summary.find("\"status\": \"failed\"") != std::string::npos);
  CHECK(summary.find("particles_000000.vtp") != std::string::npos);  // the failure names the file
}

TEST_CASE("hostile: an output folder that cannot be created exits 5 naming output.directory") {
  ScratchDir scratch("no_dir");
  const std::string scene = write_scene(scratch), file = scratch / "a_file";
  std::ofstream(file) << "x";
  const RunOutcome o = run_arksph_captured("run " + scene + " --quiet --out " + file + "/sub", scratch.dir.string());
  CHECK(o.code == 5);
  CHECK(count_lines(o.err) == 1);
  CHECK(o.err.find("output.directory") != std::string::npos);
}

// A directory, an endless device and an oversized file are refused at once. A reader that reads
// /dev/zero to its end never returns: the timeout turns such a hang into a failure of this test
// instead of a stuck ctest.
TEST_CASE("hostile: a scene, sweep or study path that is not a small regular file exits 2") {
  ScratchDir scratch("paths");
  const std::string big = scratch / "big.toml";
  {
    std::ofstream f(big);
    const std::string line = "# " + std::string(1022, 'x') + "\n";
    for (int i = 0; i < 17 * 1024; ++i) f << line;  // 17 MiB of comments
  }
  const std::string dir = scratch.dir.string();
  for (const std::string& path : {dir, std::string("/dev/zero"), std::string("/dev/urandom"), big}) {
    for (const std::string& cmd : {"run ", "batch ", "study order "}) {
      CAPTURE(cmd + path);
      const RunOutcome o = arksph::testing::run_command_captured(
          "timeout 20 " + arksph::testing::arksph_binary() + " " + cmd + path + " --quiet --out " + (scratch / "out"), dir);
      CHECK(o.code == 2);
      CHECK(count_lines(o.err) == 1);
      CHECK(o.err.find(path) != std::string::npos);
    }
  }
}

TEST_CASE("hostile: a 1 MB value and a 200,000-term expression are echoed cut to about 200 characters") {
  ScratchDir scratch("long_values");
  std::string terms = "x";
  for (int i = 0; i < 200000; ++i) terms += "+x";
  const std::pair<std::string, std::string> cases[] = {
      {"[method]\nkernel = \"" + std::string(1 << 20, 'k') + "\"\n", "method.kernel"},
      {"[initial]\nvelocity = [\"" + terms + "+unknown_name\", \"0\"]\n", "initial.velocity"},
      {"[" + std::string(300000, 't') + "]\na = 1\n", "characters"},
  };
  for (const auto& [extra, key] : cases) {
    CAPTURE(key);
    const std::string scene = write_scene(scratch, extra);
    const RunOutcome o = run_arksph_captured("run " + scene + " --quiet --out " + (scratch / "out"), scratch.dir.string());
    CHECK(o.code == 2);
    CHECK(count_lines(o.err) == 1);
    CHECK(o.err.size() < 1000);
    CHECK(o.err.find(key) != std::string::npos);
  }
}

TEST_CASE("hostile: batch with a long varied value runs in a short folder, a bad sweep still exits 2") {
  ScratchDir scratch("batch_long");
  write_scene(scratch);
  const std::string long_name(400, 'n');
  std::ofstream(scratch / "sweep.toml") << "[sweep]\nscene = \"S.toml\"\njobs = 1\n[[vary]]\nkey = \"scene.name\"\n"
                                        << "values = [\"short\", \"" << long_name << "\"]\n";
  const RunOutcome o = run_arksph_captured("batch " + (scratch / "sweep.toml") + " --quiet --out " + (scratch / "b"),
                                           scratch.dir.string());
  CHECK(o.code == 0);
  CHECK(fs::exists(scratch / "b/0_name-short/summary.json"));  // short names as they are
  int folders = 0;
  for (const auto& e : fs::directory_iterator(scratch / "b"))
    if (e.is_directory()) {
      ++folders;
      CHECK(e.path().filename().string().size() <= 120);
    }
  CHECK(folders == 2);
  std::ofstream(scratch / "bad.toml") << "[sweep]\nscene = \"S.toml\"\n[[vary]]\nkey = \"scene.name\"\n"
                                      << "values = [\"" << long_name << "\"]\n[[vary]]\nkey = \"fluid.spacing\"\n"
                                      << "values = [-1.0]\n";
  CHECK(run_arksph_captured("batch " + (scratch / "bad.toml") + " --quiet --out " + (scratch / "c"), scratch.dir.string())
            .code == 2);
}

TEST_CASE("hostile: batch --set of a varied key, or of output.directory, exits 2 naming the key") {
  ScratchDir scratch("batch_set");
  write_scene(scratch);
  std::ofstream(scratch / "sweep.toml") << "[sweep]\nscene = \"S.toml\"\n[[vary]]\nkey = \"time.end\"\n"
                                        << "values = [0.01, 0.02]\n";
  for (const auto& [set, key] : {std::pair<std::string, std::string>{"time.end=0.5", "time.end"},
                                 {"'time={end=0.5}'", "time.end"},
                                 {"output.directory=" + (scratch / "x"), "output.directory"}}) {
    CAPTURE(set);
    const RunOutcome o = run_arksph_captured("batch " + (scratch / "sweep.toml") + " --quiet --out " +
                                                 (scratch / "b") + " --set " + set,
                                             scratch.dir.string());
    CHECK(o.code == 2);
    CHECK(o.err.find(key) != std::string::npos);
    CHECK_FALSE(fs::exists(scratch / "b/0_end-0.01"));  // nothing ran
  }
}

TEST_CASE("cli: --version, --out=DIR, and what to look at after a run") {
  ScratchDir scratch("conveniences");
  const std::string scene = write_scene(scratch), out = scratch / "out";
  const RunOutcome v = run_arksph_captured("--version", scratch.dir.string());
  CHECK(v.code == 0);
  CHECK(v.out.rfind("arksph ", 0) == 0);
  const RunOutcome o = run_arksph_captured("run " + scene + " --quiet --out=" + out + " --set=time.end=0.005",
                                           scratch.dir.string());
  CHECK(o.code == 0);
  CHECK(fs::exists(out + "/particles_000001.vtp"));
  CHECK(o.out.find("paraview " + out + "/particles.pvd") != std::string::npos);
  CHECK(o.out.find("CV ") != std::string::npos);
}
