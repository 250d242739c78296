// The pieces behind the hostile-input rules, in process: capped echoes, the input-file checks, the
// names a fresh run removes, frame rows in id order, batch folder names and conflicting overrides.
// The same rules through the binary: process/test_hostile_runs.cpp, process/test_output_folder_runs.cpp.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "io/checkpoint.hpp"
#include "io/csv_writer.hpp"
#include "io/frame_order.hpp"
#include "io/input_file.hpp"
#include "run/output_folder.hpp"
#include "study/sweep.hpp"
#include "checkpoint_sample.hpp"
#include "test_support.hpp"

using namespace arksph;
namespace fs = std::filesystem;
using arksph::testing::ScratchDir;

TEST_CASE("hostile input: echo_value keeps short values and cuts long ones to about 200 characters") {
  CHECK(echo_value("cubic_spline") == "cubic_spline");
  CHECK(echo_value("a\nb") == "a b");
  const std::string cut = echo_value(std::string(1000000, 'k'));
  CHECK(cut.size() < 240);
  CHECK(cut.find("(1000000 characters)") != std::string::npos);
  // A cut never splits a UTF-8 character: 'é' is two bytes, 150 of them are 300 bytes. Cut at 200
  // bytes, they keep 100 whole; behind one ASCII byte, 99 whole and the split one dropped.
  std::string accents;
  for (int i = 0; i < 150; ++i) accents += "\xc3\xa9";
  CHECK(echo_value(accents) == accents.substr(0, 200) + "\u2026 (150 characters)");
  CHECK(echo_value("x" + accents) == "x" + accents.substr(0, 198) + "\u2026 (151 characters)");
}

TEST_CASE("hostile input: read_input_file refuses directories, devices and files over 16 MiB") {
  ScratchDir dir("input_file");
  std::ofstream(dir / "ok.toml") << "a = 1\n";
  CHECK(read_input_file(dir / "ok.toml", "scene") == "a = 1\n");
  for (const std::string& path : {dir.dir.string(), std::string("/dev/zero"), dir / "missing.toml"}) {
    CAPTURE(path);
    CHECK_THROWS_AS(read_input_file(path, "scene"), InputError);
  }
  fs::resize_file(dir / "ok.toml", kMaxInputFileBytes + 1);
  CHECK_THROWS_WITH_AS(read_input_file(dir / "ok.toml", "scene"),
                       doctest::Contains("more than the limit of 16777216 bytes"), InputError);
}

TEST_CASE("hostile input: the run-output names a fresh run removes, and the ones it leaves") {
  for (const char* name : {"particles_000000.vtp", "particles_123456.vtp", "particles.pvd", "timeseries.csv",
                           "summary.json", "checkpoint.h5", "nn_histogram.csv", "ghia_u.csv",
                           "interface_000003.csv", "profile_1d.csv", "particles.pvd.tmp.4242", "checkpoint.h5.tmp",
                           ".arksph.lock", "run.log", "batch_run.txt", "particles_000002.pvtp",
                           "particles_000002_r0.vtp", "particles_000002_r17.vtp", "walls.pvd", "walls_000003.vtp",
                           "walls_000003.pvtp", "walls_000003_r1.vtp"}) {
    CAPTURE(name);
    CHECK(is_run_output(name));
  }
  for (const char* name : {"notes.txt", "scene.toml", "particles_abc.vtp", "particles.vtp", "summary.json.bak",
                           "my.tmp.1", "batch.csv", "timeseries.csv.tmp.x", "particles_000002_r.vtp",
                           "particles__r1.vtp", "particles_000002_x1.vtp", "particles_r1.vtp", "particles_1_r1.pvtp",
                           "checkpoint_old.h5", "checkpoint_backup_t5.h5", "walls.vtp", "walls_x.vtp",
                           "walls_000003_r.vtp"}) {  // a user's copies: not removed
    CAPTURE(name);
    CHECK_FALSE(is_run_output(name));
  }
  CHECK(new_run_id().size() == 16);
  CHECK(new_run_id() != new_run_id());
}

TEST_CASE("hostile input: frame rows are written in id order, every array permuted alike") {
  const std::vector<double> x = {3, 1, 2}, y = {30, 10, 20}, u = {0.3, 0.1, 0.2};
  const std::vector<std::int64_t> id = {2, 0, 1};
  const std::vector<std::int32_t> phase = {7, 5, 6};
  Frame f;
  f.n = 3;
  f.x = x.data();
  f.y = y.data();
  f.u = u.data();
  f.v = u.data();
  f.pressure = f.density = f.summation_density = f.mass = x.data();
  f.id = id.data();
  f.phase = phase.data();
  const FrameInIdOrder sorted(f);
  const Frame& g = sorted.frame();
  for (std::size_t k = 0; k < 3; ++k) {
    CHECK(g.id[k] == static_cast<std::int64_t>(k));
    CHECK(g.x[k] == k + 1);
    CHECK(g.y[k] == 10.0 * (k + 1));
    CHECK(g.mass[k] == k + 1);
    CHECK(g.phase[k] == static_cast<std::int32_t>(5 + k));
  }
  const std::vector<std::int64_t> in_order = {0, 1, 2};
  f.id = in_order.data();
  CHECK(FrameInIdOrder(f).frame().x == x.data());  // already in order: a view, nothing copied
}

TEST_CASE("hostile input: batch folder names stay short and distinct, a varied key cannot be set") {
  const std::string dir = std::string(ARKSPH_SOURCE_DIR) + "/cases/sweeps/t.toml";
  const std::string a(300, 'a'), b = std::string(300, 'a') + "b";
  const Sweep sw = read_sweep_text("[sweep]\nscene = \"taylor_green_small.toml\"\n[[vary]]\nkey = \"scene.name\"\n"
                                   "values = [\"short\", \"" + a + "\", \"" + b + "\"]\n",
                                   dir);
  REQUIRE(sw.runs.size() == 3);
  CHECK(sw.runs[0].name == "0_name-short");
  CHECK(sw.runs[1].name.size() <= 60);
  CHECK(sw.runs[1].name.substr(2) != sw.runs[2].name.substr(2));  // the hash tells the two values apart
  CHECK(varied_key_overridden(sw, "scene.name=x") == "scene.name");
  CHECK(varied_key_overridden(sw, "scene={name=\"x\"}").empty() == false);
  CHECK(varied_key_overridden(sw, "time.end=1").empty());
  CHECK(varied_key_overridden(sw, "output.directory=x").rfind("output.directory", 0) == 0);
  CHECK_THROWS_WITH_AS(read_sweep_text("[sweep]\nscene = \"taylor_green_small.toml\"\nset = [\"scene.name=x\"]\n"
                                       "[[vary]]\nkey = \"scene.name\"\nvalues = [\"a\"]\n",
                                       dir),
                       doctest::Contains("sweep.set"), InputError);
}

// /dev/full accepts the open and fails every write with ENOSPC: the checkpoint write must throw
// OutputError, leave no temporary and no checkpoint, and leave HDF5 usable for the next write.
TEST_CASE("hostile input: a checkpoint write onto a full disk throws OutputError and the next write works") {
  if (!fs::exists("/dev/full")) return;
  ScratchDir dir("ck_full");
  const std::string path = dir / "checkpoint.h5";
  fs::create_symlink("/dev/full", temporary_path(path));
  CHECK_THROWS_WITH_AS(write_checkpoint(path, arksph::testing::sample_checkpoint(50, 2, true)),
                       ("cannot write " + path + ": No space left on device").c_str(), OutputError);
  CHECK_FALSE(fs::exists(path));
  CHECK_FALSE(fs::is_symlink(temporary_path(path)));
  write_checkpoint(path, arksph::testing::sample_checkpoint(50, 2, true));
  CHECK(read_checkpoint(path).n == 50);
}
