// What a new user and a hostile one meet at the command line: per-command help, the console's
// report of a run, progress in a log, the frames' fields, and input that used to write outside the
// output folder, hang, crash or give silently wrong values. Each case starts the binary as a user
// would; ARKSPH_TEST_BINARY runs them against another build (run_arksph.hpp).
#include <doctest/doctest.h>

#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "io/json_reader.hpp"
#include "minimal_scene.hpp"
#include "run_arksph.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;
using arksph::testing::run_arksph_captured;
using arksph::testing::run_command_captured;
using arksph::testing::RunOutcome;
using arksph::testing::ScratchDir;
using arksph::testing::slurp;

namespace {

// 10 x 10 particles at rest in a closed box, 0.01 s: the smallest run that writes every output.
const char* const kBox = arksph::testing::kMinimalScene;

struct Scratch {
  ScratchDir dir;
  std::string scene, out;
  explicit Scratch(const std::string& tag) : dir(tag), scene(dir / "S.toml"), out(dir / "out") {
    std::ofstream(scene) << kBox;
  }
  RunOutcome arksph(const std::string& args, long max_file_bytes = -1) const {
    return run_arksph_captured(args, dir.dir.string(), max_file_bytes);
  }
};

bool says(const std::string& text, const std::string& what) { return text.find(what) != std::string::npos; }

int lines_of(const std::string& text) {
  int n = 0;
  for (char c : text) n += c == '\n';
  return n;
}

double summary_number(const std::string& dir, const char* key) {
  const arksph::JsonValue j = arksph::read_json_file(dir + "/summary.json");
  const arksph::JsonValue* v = j.find(key);
  REQUIRE(v != nullptr);
  return v->number;
}

// Overwrites the scalar 64-bit integer attribute `name` of the checkpoint's root group.
void set_checkpoint_attribute(const std::string& path, const char* name, std::int64_t value) {
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  REQUIRE(file >= 0);
  const hid_t attr = H5Aopen(file, name, H5P_DEFAULT);
  REQUIRE(attr >= 0);
  CHECK(H5Awrite(attr, H5T_NATIVE_INT64, &value) >= 0);
  H5Aclose(attr);
  H5Fclose(file);
}

}  // namespace

TEST_CASE("rough edges: item 3, every command answers --help with its own usage, exit 0") {
  const Scratch s("help");
  const struct {
    const char* args;
    const char* usage;
  } commands[] = {{"run --help", "usage: arksph run"},
                  {"default-scene --help", "usage: arksph default-scene"},
                  {"scene-reference -h", "usage: arksph scene-reference"},
                  {"list --help", "usage: arksph list"},
                  {"--help", "usage: arksph COMMAND"}};
  for (const auto& c : commands) {
    CAPTURE(c.args);
    const RunOutcome o = s.arksph(c.args);
    CHECK(o.code == 0);
    CHECK(says(o.out, c.usage));
    CHECK(o.err.empty());
    CHECK_FALSE(says(o.out, "[domain]"));  // not the default scene
  }
  // The run's help lists its options; the overview says that ISPH runs over ranks too.
  CHECK(says(s.arksph("run --help").out, "--progress-every"));
  CHECK(says(s.arksph("--help").out, "WCSPH or ISPH decomposed over P MPI ranks"));
  // Arguments a command does not take are bad input, named.
  const RunOutcome bad = s.arksph("default-scene --bogus");
  CHECK(bad.code == 2);
  CHECK(says(bad.err, "--bogus: unknown argument"));
}

TEST_CASE("rough edges: item 37, two --restart options are refused instead of the last one winning") {
  const Scratch s("two_restarts");
  const RunOutcome o = s.arksph("run --restart a.h5 --restart b.h5");
  CHECK(o.code == 2);
  CHECK(lines_of(o.err) == 1);
  CHECK(says(o.err, "--restart given twice"));
}

TEST_CASE("rough edges: item 5, the end of a run prints every metric the scene set") {
  const Scratch s("metrics");
  const std::string scene = s.dir / "tg.toml";
  std::ofstream(scene) << arksph::testing::test_scene("taylor_green_vortex_25.toml");
  const RunOutcome o = s.arksph("run " + scene + " --quiet --out " + s.out + " --set time.end=0.01");
  REQUIRE(o.code == 0);
  CHECK(says(o.out, "velocity L1 relative error"));
  CHECK(says(o.out, "CV"));
}

TEST_CASE("rough edges: item 6, a rerun into a folder says that it replaces the earlier run") {
  const Scratch s("rerun");
  const std::string args = "run " + s.scene + " --quiet --out " + s.out + " --set output.every=0.005";
  REQUIRE(s.arksph(args).code == 0);
  const RunOutcome first_again = s.arksph(args);
  REQUIRE(first_again.code == 0);
  CHECK(says(first_again.out, "replacing the earlier run in " + s.out + ": 3 frames"));
  // A file of the user's that only looks like a checkpoint is not removed: the folder is refused.
  std::ofstream(s.out + "/checkpoint_backup_t5.h5") << "mine";
  const RunOutcome refused = s.arksph(args);
  CHECK(refused.code == 2);
  CHECK(says(refused.err, "checkpoint_backup_t5.h5"));
  CHECK(slurp(s.out + "/checkpoint_backup_t5.h5") == "mine");
}

TEST_CASE("rough edges: item 7, a log gets progress lines between frames (--progress-every)") {
  const Scratch s("progress");
  // The default cavity to t = 0.01 (several steps); output.every = 0: frames at t = 0 and at the end
  // only. stderr is a file here, not a terminal.
  const RunOutcome o = s.arksph("run --out " + s.out + " --set time.end=0.01 --set output.every=0 --progress-every 0");
  REQUIRE(o.code == 0);
  const long steps = static_cast<long>(summary_number(s.out, "steps"));
  REQUIRE(steps >= 3);
  int progress_lines = 0;
  for (std::size_t at = o.err.find("  t = "); at != std::string::npos; at = o.err.find("  t = ", at + 1))
    ++progress_lines;
  CHECK(progress_lines >= steps);  // one after every step with --progress-every 0, besides the frames'
  const RunOutcome bad = s.arksph("run " + s.scene + " --out " + s.out + " --progress-every soon");
  CHECK(bad.code == 2);
  CHECK(says(bad.err, "--progress-every soon: not a number of seconds"));
}

TEST_CASE("rough edges: item 8, frames carry the smoothing length h and the particle kind") {
  const Scratch s("frame_fields");
  REQUIRE(s.arksph("run " + s.scene + " --quiet --out " + s.out).code == 0);
  const std::string vtp = slurp(s.out + "/particles_000000.vtp");
  CHECK(says(vtp, "Name=\"h\""));
  CHECK(says(vtp, "Name=\"kind\""));
}

TEST_CASE("rough edges: item 12, a control character in --out stays in the folder name") {
  const Scratch s("control_char");
  // $(printf ...) puts a real newline into the argument; the folder is created with it in its name.
  const RunOutcome o = s.arksph("run " + s.scene + " --quiet --out \"$(printf '" + s.out + "\\nx\"y')\"");
  CHECK(o.code == 0);
  CHECK(fs::exists(s.out + "\nx\"y/summary.json"));
  int entries = 0;  // S.toml and the one output folder, nothing else
  for (const auto& e : fs::directory_iterator(s.dir.dir)) entries += e.path().filename().string()[0] != '.';
  CHECK(entries == 2);
}

TEST_CASE("rough edges: item 13, run outputs that are symbolic links refuse the folder and are not followed") {
  for (const char* name : {".arksph.lock", "timeseries.csv", "summary.json", "particles_000000.vtp"}) {
    CAPTURE(name);
    const Scratch s("links");
    const std::string victim = s.dir / "victim.txt";
    std::ofstream(victim) << "precious";
    fs::create_directories(s.out);
    fs::create_symlink(victim, s.out + "/" + name);
    const RunOutcome o = s.arksph("run " + s.scene + " --quiet --out " + s.out + " --overwrite");
    CHECK(o.code == 2);
    CHECK(lines_of(o.err) == 1);
    CHECK(says(o.err, "is a symbolic link"));
    CHECK(slurp(victim) == "precious");
  }
}

TEST_CASE("rough edges: item 15, a checkpoint attribute out of range is refused at once, not looped over") {
  const Scratch s("checkpoint_attributes");
  REQUIRE(s.arksph("run " + s.scene + " --quiet --out " + s.out).code == 0);
  const std::string original = s.dir / "original.h5";
  fs::copy_file(s.out + "/checkpoint.h5", original);
  const struct {
    const char* attribute;
    std::int64_t value;
  } edits[] = {{"output_frame", std::int64_t{1} << 62}, {"steps", -5}, {"checkpoint_index", std::int64_t{1} << 40}};
  for (const auto& e : edits) {
    const std::string attribute = e.attribute;
    CAPTURE(attribute);
    const std::string edited = s.dir / "edited.h5";
    fs::copy_file(original, edited, fs::copy_options::overwrite_existing);
    set_checkpoint_attribute(edited, e.attribute, e.value);
    const RunOutcome o = run_command_captured("timeout -s KILL 60 " + arksph::testing::arksph_binary() + " run --quiet --restart " +
                                                  edited + " --out " + (s.dir / "continued") + " --set time.end=0.02",
                                              s.dir.dir.string());
    CAPTURE(o.err);
    CHECK(o.code == 2);  // 137 (SIGKILL from timeout) when the restart loops
    CHECK(says(o.err, attribute + " = "));
  }
}

TEST_CASE("rough edges: item 28, a dataset stored with another datatype than arksph writes is refused") {
  const Scratch s("checkpoint_datatype");
  REQUIRE(s.arksph("run " + s.scene + " --quiet --out " + s.out).code == 0);
  const std::string edited = s.dir / "edited.h5";
  fs::copy_file(s.out + "/checkpoint.h5", edited);
  {  // /state/u again, as big-endian doubles: HDF5 would convert them silently on reading
    const hid_t file = H5Fopen(edited.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    REQUIRE(file >= 0);
    const hid_t old_set = H5Dopen2(file, "/state/u", H5P_DEFAULT);
    REQUIRE(old_set >= 0);
    const hid_t space = H5Dget_space(old_set);
    std::vector<double> u(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
    CHECK(H5Dread(old_set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, u.data()) >= 0);
    H5Dclose(old_set);
    CHECK(H5Ldelete(file, "/state/u", H5P_DEFAULT) >= 0);
    const hsize_t n[1] = {u.size()};
    const hid_t fixed = H5Screate_simple(1, n, nullptr);
    const hid_t set = H5Dcreate2(file, "/state/u", H5T_IEEE_F64BE, fixed, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    REQUIRE(set >= 0);
    CHECK(H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, u.data()) >= 0);
    H5Dclose(set);
    H5Sclose(fixed);
    H5Sclose(space);
    H5Fclose(file);
  }
  const RunOutcome o = s.arksph("run --quiet --restart " + edited + " --out " + (s.dir / "continued"));
  CAPTURE(o.err);
  CHECK(o.code == 2);
  CHECK(says(o.err, "/state/u is not stored as a little-endian 64-bit float"));
}

TEST_CASE("rough edges: item 18, a file-size limit ends the run with exit 5 and a message, no temporaries left") {
  const Scratch s("file_size_limit");
  // The shell's ulimit -f counts 512-byte blocks: 32 KiB, enough for the small files, not a 1600-particle frame.
  const RunOutcome o = run_command_captured("sh -c 'ulimit -f 64; exec " + arksph::testing::arksph_binary() +
                                                " run --quiet --out " + s.out + " --set time.end=0.001'",
                                            s.dir.dir.string());
  CHECK(o.code == 5);
  CHECK(says(o.err, "cannot write"));
  for (const auto& e : fs::directory_iterator(s.out)) {
    CAPTURE(e.path().string());
    CHECK_FALSE(says(e.path().filename().string(), ".tmp."));
  }
}

TEST_CASE("rough edges: item 20, an absurd OMP_NUM_THREADS is bounded with a message") {
  const Scratch s("threads");
  const RunOutcome o = run_command_captured("env OMP_NUM_THREADS=100000 " + arksph::testing::arksph_binary() + " run " +
                                                s.scene + " --quiet --out " + s.out,
                                            s.dir.dir.string());
  CHECK(o.code == 0);
  CHECK(says(o.err, "OMP_NUM_THREADS asks for 100000 threads"));
}

TEST_CASE("rough edges: item 24, printing the default scene or the reference to a full disk exits 5") {
  const Scratch s("stdout_full");
  for (const char* command : {"default-scene", "scene-reference"}) {
    CAPTURE(command);
    const RunOutcome o = s.arksph(command, 1000);  // stdout is a file limited to 1000 bytes
    CHECK(o.code == 5);
    CHECK(says(o.err, "standard output could not be written"));
  }
}

TEST_CASE("rough edges: item 25, summary.json's final_time is the time reached, not the last frame's") {
  const Scratch s("final_time");
  // The default cavity (about 7 steps to t = 0.01), frames at t = 0 and at the end only; the step
  // budget stops the run after 4 steps.
  const RunOutcome o = s.arksph("run --quiet --out " + s.out +
                                " --set time.end=0.01 --set output.every=0 --set time.max_steps=4");
  CHECK(o.code == 3);
  const double reached = summary_number(s.out, "final_time");
  CHECK(reached > 0);
  CHECK(reached < 0.01);
  CHECK(summary_number(s.out, "steps") == 4);
}

TEST_CASE("rough edges: item 26, an orthogonal-projection run is labelled orthogonal") {
  const Scratch s("orthogonal_label");
  const std::string scene = s.dir / "tg.toml";
  std::ofstream(scene) << arksph::testing::test_scene("taylor_green_vortex_25.toml");
  const RunOutcome o = s.arksph("run " + scene + " --quiet --out " + s.out +
                                " --set time.end=0.002 --set method.scheme=isph --set method.projection=orthogonal");
  REQUIRE(o.code == 0);
  CHECK(says(o.out, "orthogonal projection"));
  CHECK_FALSE(says(o.out, "constrained"));
}

TEST_CASE("rough edges: items 27, 30, 31, 35, values the reference used to admit and that fail are refused, named") {
  const Scratch s("admitted_values");
  const struct {
    const char* set;
    const char* key;
  } values[] = {{"method.ppe_tolerance=1e-300", "method.ppe_tolerance"},
                {"method.h_over_dx=0.5", "method.h_over_dx"},
                {"method.projection=orthogonal --set method.orthogonal_spacing=1", "method.orthogonal_spacing"},
                {"time.end=1e-300", "time.end"}};
  for (const auto& v : values) {
    CAPTURE(v.set);
    const RunOutcome o = s.arksph("run " + s.scene + " --quiet --out " + s.out + " --set method.scheme=isph --set " + v.set);
    CHECK(o.code == 2);
    CHECK(lines_of(o.err) == 1);
    CHECK(says(o.err, v.key));
  }
}

TEST_CASE("rough edges: item 36, a solver failure names where: the particle, its position and the quantity") {
  const Scratch s("failure_location");
  // The default cavity with nu = 1e6 under IMEX: ARKODE's error test fails (ARK_ERR_FAILURE).
  const RunOutcome imex = s.arksph("run --quiet --out " + s.out +
                                   " --set time.end=0.01 --set fluid.viscosity=1e6 --set time.imex=true");
  CAPTURE(imex.err);
  CHECK(imex.code == 3);
  CHECK(lines_of(imex.err) == 1);
  CHECK(says(imex.err, "ARK_ERR_FAILURE"));
  CHECK(says(imex.err, "the largest acceleration is "));
  CHECK(says(imex.err, "(particle id "));
  // A body force of 1e300: the adaptive step underflows.
  const RunOutcome force = s.arksph("run " + s.scene + " --quiet --out " + s.out + " --set 'fluid.body_force=[1e300, 0]'");
  CAPTURE(force.err);
  CHECK(force.code == 3);
  CHECK(says(force.err, "underflowed"));
  CHECK(says(force.err, "the largest acceleration is 1e+300 (particle id "));
}

TEST_CASE("rough edges: item 10, a fixed step solves the IMEX stages below its truncation error and says so") {
  const Scratch s("imex_fixed_step");
  const RunOutcome o = s.arksph("run --quiet --out " + s.out +
                                " --set time.end=0.002 --set time.imex=true --set time.dt=0.001");
  REQUIRE(o.code == 0);
  CHECK(says(o.out, "fixed dt 0.001 (implicit stages solved to rtol 1e-10, atol 1e-12)"));
}

TEST_CASE("rough edges: item 32, SIGTERM to a batch reaches its running child, which checkpoints, exit 143") {
  const Scratch s("batch_signal");
  // One run long enough to be caught running: the default cavity to t = 50 (minutes of work).
  const std::string sweep = s.dir / "sweep.toml";
  std::ofstream(s.dir / "cavity.toml") << s.arksph("default-scene").out;
  std::ofstream(sweep) << "[sweep]\nscene = \"cavity.toml\"\nset = [\"time.end=50\"]\n[[vary]]\n"
                          "key = \"fluid.viscosity\"\nvalues = [0.01]\n";
  const std::string bin = arksph::testing::arksph_binary();
  // Start the batch in the background, give its child time to start stepping, then SIGTERM the batch.
  const RunOutcome o = run_command_captured(
      "sh -c '" + bin + " batch " + sweep + " --out " + s.out + " & b=$!; sleep 4; kill -TERM $b; wait $b'",
      s.dir.dir.string());
  CAPTURE(o.err);
  CHECK(o.code == 143);
  CHECK(says(o.err, "SIGTERM"));
  bool checkpoint = false;
  for (const auto& e : fs::recursive_directory_iterator(s.out))
    checkpoint = checkpoint || e.path().filename() == "checkpoint.h5";
  CHECK(checkpoint);  // the child wrote its checkpoint when the signal reached it
}

TEST_CASE("rough edges: item 1, the tour's MPI wrapper runs as root and with more ranks than cores") {
  if (std::system("command -v mpirun >/dev/null 2>&1") != 0) {
    MESSAGE("no mpirun on this machine: nothing to check");
    return;
  }
  const Scratch s("mpirun_wrapper");
  const std::string wrapper = std::string(ARKSPH_SOURCE_DIR) + "/scripts/mpirun.sh";
  // Under AddressSanitizer, no leak report at exit: Open MPI keeps its own allocations past MPI_Finalize.
  const RunOutcome o = run_command_captured("env ASAN_OPTIONS=detect_leaks=0 " + wrapper + " -n 3 " +
                                                arksph::testing::arksph_binary() + " run " + s.scene +
                                                " --quiet --out " + s.out,
                                            s.dir.dir.string());
  CAPTURE(o.err);
  REQUIRE(o.code == 0);
  const arksph::JsonValue j = arksph::read_json_file(s.out + "/summary.json");
  const arksph::JsonValue* mpi = j.find("mpi");
  REQUIRE(mpi != nullptr);
  const arksph::JsonValue* ranks = mpi->find("ranks");
  REQUIRE(ranks != nullptr);
  CHECK(ranks->number == 3);
}

TEST_CASE("rough edges: item 2, rendering without ParaView names the install step and installs nothing") {
  const Scratch s("pvbatch_consent");
  const std::string modules = s.dir / "paraview_modules";  // an empty cache: the modules are missing
  const RunOutcome o = run_command_captured("env ARKSPH_PV_DIR=" + modules + " " + ARKSPH_SOURCE_DIR +
                                                "/scripts/pvbatch.sh paraview/render.py " + s.out,
                                            s.dir.dir.string());
  CHECK(o.code == 2);
  CHECK(says(o.err, "is not installed"));
  CHECK(says(o.err, "scripts/install-paraview.sh"));
  CHECK_FALSE(fs::exists(modules));  // nothing downloaded or unpacked
}

TEST_CASE("rough edges: item 9, the README's tour gives runnable commands and no figures that drift") {
  const std::string readme = slurp(std::string(ARKSPH_SOURCE_DIR) + "/README.md");
  REQUIRE_FALSE(readme.empty());
  CHECK_FALSE(says(readme, "cut -c1-160"));                       // cut off every result column
  CHECK(says(readme, "--set method.scheme=isph --out runs/tour_isph"));  // "switch the scheme" has a command
  CHECK(says(readme, "into `runs/order_wcsph/`"));                // the order study's folder is named
  CHECK(says(readme, "Against PySPH"));                           // the PySPH comparison, linked
  CHECK(says(readme, "bench/RESULTS.md#cavity-re--100-50--50-to-t--10-against-pysph"));
  CHECK_FALSE(says(readme, "1.10, 1.92, 3.05"));                  // measured orders live in the case READMEs
  CHECK_FALSE(says(readme, "0.013\n(isph), 0.0089"));
  CHECK_FALSE(says(readme, "\nOMP_NUM_THREADS=1 mpirun"));        // as root mpirun refuses without a flag
}

TEST_CASE("rough edges: items 23, 37, options that do not apply to the scene are refused, named") {
  const Scratch s("not_applicable");
  const std::string line = s.dir / "line.toml";
  std::ofstream(line) << "[scene]\ndimension = 1\n[domain]\nmin = [0.0]\nmax = [1.0]\n[fluid]\nspacing = 0.1\n"
                         "[time]\nend = 0.01\n";
  const struct {
    std::string args, key;
  } cases[] = {
      // The default cavity stretched to 2 x 1: Ghia's points would not be its centrelines.
      {"run --quiet --out " + s.out + " --set 'domain.max=[2.0, 1.0]'", "metrics.ghia_re"},
      {"run " + line + " --quiet --out " + s.out + " --set boundary.wall_velocity=linear", "boundary.wall_velocity"},
  };
  for (const auto& c : cases) {
    CAPTURE(c.args);
    const RunOutcome o = s.arksph(c.args);
    CHECK(o.code == 2);
    CHECK(lines_of(o.err) == 1);
    CHECK(says(o.err, c.key));
  }
}

TEST_CASE("rough edges: item 37, batch messages name what is wrong") {
  const Scratch s("batch_messages");
  // A sweep whose scene is a folder.
  const std::string sweep = s.dir / "sweep.toml";
  std::ofstream(sweep) << "[sweep]\nscene = \".\"\n[[vary]]\nkey = \"fluid.viscosity\"\nvalues = [0.01]\n";
  const RunOutcome folder = s.arksph("batch " + sweep + " --out " + s.out);
  CHECK(folder.code == 2);
  CHECK(says(folder.err, "is a directory"));
  // --set output.directory: the batch chooses the runs' folders; the message says to use --out.
  std::ofstream(sweep) << "[sweep]\nscene = \"S.toml\"\n[[vary]]\nkey = \"fluid.viscosity\"\nvalues = [0.01]\n";
  const RunOutcome directory = s.arksph("batch " + sweep + " --out " + s.out + " --set output.directory=elsewhere");
  CHECK(directory.code == 2);
  CHECK(says(directory.err, "choose that folder with --out DIR"));
  CHECK_FALSE(says(directory.err, "is varied by"));
}

TEST_CASE("rough edges: item 37, a long scene check of a sweep says how far it got") {
  // Six runs, the last with a bad value: every scene is read before anything runs, and with
  // --progress-every 0 each check prints its line (the default, 5 s, prints only for long checks).
  const Scratch s("batch_check_progress");
  const std::string sweep = s.dir / "sweep.toml";
  std::ofstream(sweep) << "[sweep]\nscene = \"S.toml\"\n[[vary]]\nkey = \"fluid.viscosity\"\n"
                          "values = [0.01, 0.02, -1.0]\n[[vary]]\nkey = \"time.end\"\nvalues = [0.01, 0.02]\n";
  const RunOutcome o = s.arksph("batch " + sweep + " --out " + s.out + " --progress-every 0");
  CHECK(o.code == 2);  // the bad viscosity: nothing runs
  CHECK(says(o.err, "checked the scenes of 1 of 6 runs"));
  CHECK(says(o.err, "fluid.viscosity"));
  CHECK_FALSE(fs::exists(s.out + "/batch.csv"));
  const RunOutcome quiet = s.arksph("batch " + sweep + " --out " + s.out + " --progress-every 0 --quiet");
  CHECK(quiet.code == 2);
  CHECK_FALSE(says(quiet.err, "checked the scenes"));
}

TEST_CASE("rough edges: item 37, a scene warning of a run over MPI ranks is printed once, not once per rank") {
  if (std::system("command -v mpirun >/dev/null 2>&1") != 0) {
    MESSAGE("no mpirun on this machine: nothing to check");
    return;
  }
  const Scratch s("mpi_warning_once");
  const std::string wrapper = std::string(ARKSPH_SOURCE_DIR) + "/scripts/mpirun.sh";
  const RunOutcome o = run_command_captured("sh -c 'ASAN_OPTIONS=detect_leaks=0 " + wrapper + " -n 3 " +
                                                arksph::testing::arksph_binary() + " run " + s.scene + " --quiet --out " + s.out +
                                                " --set method.scheme=isph --set method.sound_speed=12'",
                                            s.dir.dir.string());
  CAPTURE(o.err);
  CHECK(o.code == 0);
  std::size_t count = 0;  // the warning names the key
  for (std::size_t at = o.err.find("method.sound_speed: unused"); at != std::string::npos;
       at = o.err.find("method.sound_speed: unused", at + 1))
    ++count;
  CHECK(count == 1);
}

TEST_CASE("rough edges: item 33, SIGTERM to mpirun: the ranks checkpoint and summary.json says interrupted") {
  if (std::system("command -v mpirun >/dev/null 2>&1") != 0) {
    MESSAGE("no mpirun on this machine: nothing to check");
    return;
  }
  const Scratch s("mpirun_signal");
  const std::string wrapper = std::string(ARKSPH_SOURCE_DIR) + "/scripts/mpirun.sh";
  // The default cavity to t = 50 on 2 ranks (minutes of work), stopped after a few seconds.
  const RunOutcome o = run_command_captured("sh -c 'ASAN_OPTIONS=detect_leaks=0 " + wrapper + " -n 2 " +
                                                arksph::testing::arksph_binary() +
                                                " run --quiet --out " + s.out +
                                                " --set time.end=50 & m=$!; sleep 6; kill -TERM $m; wait $m'",
                                            s.dir.dir.string());
  CAPTURE(o.err);
  CHECK(says(o.err, "interrupted by SIGTERM"));
  CHECK(fs::exists(s.out + "/checkpoint.h5"));
  const arksph::JsonValue j = arksph::read_json_file(s.out + "/summary.json");
  const arksph::JsonValue* status = j.find("status");
  REQUIRE(status != nullptr);
  CHECK(status->text == "interrupted");  // mpirun's own exit code is Open MPI's (docs/parallel.md)
}

TEST_CASE("rough edges: item 37, refusals on restart name the checkpoint they read the scene from") {
  const Scratch s("restart_refusals");
  REQUIRE(s.arksph("run --quiet --out " + s.out + " --set time.end=0.005").code == 0);
  const std::string checkpoint = s.out + "/checkpoint.h5";
  const RunOutcome o = s.arksph("run --quiet --restart " + checkpoint + " --out " + (s.dir / "continued") +
                                " --set time.end=0.01 --set method.density_mode=summation");
  CAPTURE(o.err);
  CHECK(o.code == 2);
  CHECK(lines_of(o.err) == 1);
  CHECK(says(o.err, checkpoint));
  CHECK(says(o.err, "method.density_mode"));
}

TEST_CASE("rough edges: item 29, with a fixed step, checkpoints change the trajectory by round-off only") {
  // docs/user-guide.md, "What the output schedule changes": with time.dt fixed and the checkpoint
  // times on its multiples no step is cut; what is left is the re-initialisation at a checkpoint,
  // which changes sums' order: round-off. timeseries.csv prints 10 significant digits, so the rows
  // may differ in their last digit (1e-9 relative), far below any change of the steps (a cut step
  // would move them by the step's error, ~1e-6).
  const Scratch s("checkpoint_trajectory");
  const std::string common = " --quiet --set time.end=0.1 --set time.dt=0.001 --set output.every=0.1";
  REQUIRE(s.arksph("run --out " + (s.dir / "plain") + common + " --set output.checkpoint_every=0").code == 0);
  REQUIRE(s.arksph("run --out " + (s.dir / "checkpointed") + common + " --set output.checkpoint_every=0.025").code == 0);
  const auto last_row = [](const std::string& csv) {
    std::string text = slurp(csv), row;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) row = line;
    std::vector<double> v;
    std::istringstream cells(row);
    for (std::string cell; std::getline(cells, cell, ',');) v.push_back(std::stod(cell));
    return v;
  };
  const std::vector<double> a = last_row(s.dir / "plain/timeseries.csv"), b = last_row(s.dir / "checkpointed/timeseries.csv");
  REQUIRE(a.size() == b.size());
  REQUIRE(a.size() >= 5);
  for (std::size_t k = 0; k < a.size(); ++k) {
    CAPTURE(k);
    CHECK(std::abs(a[k] - b[k]) <= 1e-9 * std::max(1.0, std::abs(a[k])));
  }
}
