// Input that no run can survive is refused before the run with exit code 2 and one line naming the
// key: lengths outside the arithmetic of doubles, NaN or infinite initial fields, runs that could
// never reach time.end, metrics and options that do not apply to the scene, and runs larger than the
// memory limit. An allocation that fails anyway exits 6 naming what was being allocated.
// ARKSPH_TEST_BINARY runs these against another build (cli_outcome.hpp).
#include <doctest/doctest.h>

#include <hdf5.h>

#include <cstdint>
#include <string>

#include "cli_outcome.hpp"
#include "io/scene_reader.hpp"
#include "test_support.hpp"

using arksph::testing::CliOutcome;
using arksph::testing::run_cli;
using arksph::testing::ScratchDir;

namespace {

const char* const kInputScene = arksph::testing::kMinimalScene;  // tests/process/cli_outcome.hpp

const char* kScene1d = R"(
[scene]
dimension = 1
[domain]
min = [0.0]
max = [1.0]
[fluid]
spacing = 0.1
[time]
end = 0.01
)";

struct Scenes {
  ScratchDir dir{"hostile_input"};
  std::string two_d = dir / "S.toml", one_d = dir / "S1.toml", out = dir / "out";
  Scenes() {
    std::ofstream(two_d) << kInputScene;
    std::ofstream(one_d) << kScene1d;
  }
  // `arksph run SCENE --quiet --out OUT ARGS`
  CliOutcome run(const std::string& args, const std::string& scene = "", const std::string& prefix = "",
                 int seconds = 300) const {
    return run_cli("run " + (scene.empty() ? two_d : scene) + " --quiet --out " + out + " " + args, prefix, seconds);
  }
};

// AddressSanitizer reserves terabytes of address space at start: a binary built with it cannot run
// under `ulimit -v`, so the checks of an address-space limit run in the normal build only.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSpaceLimits = false;
#else
constexpr bool kAddressSpaceLimits = true;
#endif

// Exit code 2, one line, naming `key` (and `also`, when given).
void check_refused(const CliOutcome& o, const std::string& key, const std::string& also = "") {
  CAPTURE(o.err);
  CHECK(o.code == 2);
  CHECK(o.lines() == 1);
  CHECK(o.says(key));
  if (!also.empty()) CHECK(o.says(also));
}

}  // namespace

TEST_CASE("hostile input: lengths whose squares or kernel constants leave the doubles exit 2 naming the key") {
  const Scenes s;
  // h^2 overflows (a segmentation fault in the neighbour search when it was not checked).
  check_refused(s.run("--set 'domain.max=[1e160,1e160]' --set fluid.spacing=1e159"), "fluid.spacing");
  // h^2 is subnormal, 1/h^4 overflows.
  check_refused(s.run("--set 'domain.max=[1e-159,1e-159]' --set fluid.spacing=1e-160"), "fluid.spacing");
  // h^2 is fine, but the gradient constant 1/h^4 of the 2D kernel underflows to zero.
  check_refused(s.run("--set 'domain.max=[1e101,1e101]' --set fluid.spacing=1e100"), "fluid.spacing", "1/h^4");
  // Coordinates near 1e12 (double resolution 1.2e-4) cannot tell particles 0.1 apart to a millionth.
  check_refused(s.run("--set 'domain.min=[1e12,0]' --set 'domain.max=[1000000000001,1]'"), "fluid.spacing");
  // Within the range, a rescaled scene runs (lengths 1e10: the scales, not the sizes, matter).
  CHECK(s.run("--set 'domain.max=[1e10,1e10]' --set fluid.spacing=1e9 --set time.end=1e8").code == 0);
}

TEST_CASE("hostile input: a NaN or infinite initial velocity or body force at t = 0 exits 2 naming key and particle") {
  const Scenes s;
  check_refused(s.run("--set 'initial.velocity=[\"sqrt(x - 0.5)\", \"0\"]'"), "initial.velocity",
                "NaN at the particle at (0.05, 0.05)");
  check_refused(s.run("--set 'initial.velocity=[\"0\", \"log(x - 0.05)\"]'"), "initial.velocity",
                "-inf at the particle at (0.05, 0.05)");
  check_refused(s.run("--set 'fluid.body_force=[\"x > 0.5 ? 0/0 : 0\", \"0\"]'"), "fluid.body_force",
                "NaN at t = 0 at the particle at (0.55, 0.05)");
}

TEST_CASE("hostile input: runs that could never reach time.end exit 2 naming the key") {
  const Scenes s;
  // t + dt == t: the run would loop for ever (time limit 60 s for a version that does not check).
  check_refused(s.run("--set time.dt=5e-324", "", "", 60), "time.dt", "spacing of doubles");
  check_refused(s.run("--set time.end=1 --set output.every=1e-9", "", "", 60), "output.every", "999999999 frames");
  check_refused(s.run("--set time.end=1 --set output.checkpoint_every=1e-9", "", "", 60), "output.checkpoint_every",
                "999999999 checkpoints");
  // The limit itself, 100,000 frames or checkpoints, is allowed (read only: the run is not started).
  CHECK_NOTHROW(arksph::read_scene_text(kInputScene, "S.toml", {"time.end=1", "output.every=1e-5"}));
  CHECK_NOTHROW(arksph::read_scene_text(kInputScene, "S.toml", {"time.end=1", "output.checkpoint_every=1e-5"}));
}

TEST_CASE("hostile input: metrics and options that do not apply to the scene exit 2 naming the keys") {
  const Scenes s;
  // Ghia et al.'s errors on a scene that is no lid-driven cavity read as a perfect 0.
  check_refused(s.run("--set metrics.ghia_re=100", s.one_d), "metrics.ghia_re");
  check_refused(s.run("--set metrics.ghia_re=100 --set 'boundary.top.velocity=[1,0]' --set boundary.left.kind=periodic "
                      "--set boundary.right.kind=periodic"),
                "metrics.ghia_re");
  check_refused(s.run("--set metrics.ghia_re=100"), "metrics.ghia_re");  // no moving lid
  // The Poiseuille error needs a driven channel (on a cavity it is null).
  check_refused(s.run("--set metrics.poiseuille=true --set 'boundary.top.velocity=[1,0]'"), "metrics.poiseuille");
  check_refused(s.run("--set metrics.poiseuille=true --set boundary.left.kind=periodic --set boundary.right.kind=periodic"),
                "metrics.poiseuille", "body force");
  // Options the scene would silently ignore.
  check_refused(s.run("--set boundary.wall_particles=true", s.one_d), "boundary.wall_particles");
  check_refused(s.run("--set method.scheme=isph-gpps --set method.ppe_operator=exact"), "method.ppe_operator");
  // The valid combinations still run.
  CHECK(s.run("--set metrics.ghia_re=100 --set 'boundary.top.velocity=[1,0]'").code == 0);
  CHECK(s.run("--set metrics.poiseuille=true --set boundary.left.kind=periodic --set boundary.right.kind=periodic "
              "--set 'fluid.body_force=[8,0]'")
            .code == 0);
}

TEST_CASE("hostile input: a run beyond the memory limit exits 2 with the estimate before allocating") {
  const Scenes s;
  // A 10^10-cell projection grid.
  check_refused(s.run("--set method.scheme=isph-gpps --set method.gpps_spacing=1e-5"), "method.gpps_spacing",
                "1e+10 grid cells");
  // 10^8 particles under a 4 GB address-space limit (ulimit -v takes kB).
  if (kAddressSpaceLimits) {
    const CliOutcome big = s.run("--set fluid.spacing=1e-4", "", "ulimit -v 4194304;", 120);
    check_refused(big, "fluid.spacing", "1e+08 particles");
    CHECK((big.says("RLIMIT_AS") || big.says("MemAvailable")));  // MemAvailable when the machine has less
  }
  check_refused(s.run("--set fluid.spacing=1e-4", "", "ARKSPH_MEMORY_LIMIT=4G"), "fluid.spacing", "1e+08 particles");
  // The limit of the environment variable, in bytes or with a unit.
  const CliOutcome tiny = s.run("", "", "ARKSPH_MEMORY_LIMIT=10K");  // 100 particles need ~100 kB
  check_refused(tiny, "fluid.spacing", "ARKSPH_MEMORY_LIMIT");
  CHECK(tiny.says("memory limit of 10.2 kB"));
  check_refused(s.run("", "", "ARKSPH_MEMORY_LIMIT=lots"), "ARKSPH_MEMORY_LIMIT");
  CHECK(s.run("", "", "ARKSPH_MEMORY_LIMIT=4G").code == 0);
}

TEST_CASE("hostile input: an allocation that fails although the estimate passed exits 6 naming what") {
  if (!kAddressSpaceLimits) {
    MESSAGE("skipped: needs ulimit -v, which an AddressSanitizer build cannot run under");
    return;
  }
  const Scenes s;
  // The estimate is told there is a terabyte; the address space holds 2 GB: the lattice of 10^8
  // particles (0.8 GB an array) fails at once.
  const CliOutcome o = s.run("--set fluid.spacing=1e-4", "", "ulimit -v 2097152; ARKSPH_MEMORY_LIMIT=1T", 120);
  CAPTURE(o.err);
  CHECK(o.code == 6);
  CHECK(o.lines() == 1);
  CHECK(o.says("out of memory"));
  CHECK(o.says("lattice of 100000000 particles"));
}

TEST_CASE("hostile input: a checkpoint claiming more particles than memory holds exits 2 before allocating") {
  const Scenes s;
  REQUIRE(s.run("").code == 0);
  const std::string checkpoint = s.out + "/checkpoint.h5";
  {  // the particle count of the file raised to 10^15 (the arrays stay those of 100 particles)
    const hid_t file = H5Fopen(checkpoint.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    REQUIRE(file >= 0);
    const hid_t attr = H5Aopen(file, "particles", H5P_DEFAULT);
    REQUIRE(attr >= 0);
    const std::int64_t huge = 1000000000000000;
    CHECK(H5Awrite(attr, H5T_NATIVE_INT64, &huge) >= 0);
    H5Aclose(attr);
    H5Fclose(file);
  }
  const CliOutcome o = run_cli("run --restart " + checkpoint + " --quiet --set time.end=0.02", "", 120);
  check_refused(o, "particles = 1000000000000000", "memory limit");
}

TEST_CASE("hostile input: a checkpoint attribute larger than the memory limit exits 2 before allocating") {
  const Scenes s;
  REQUIRE(s.run("").code == 0);
  const std::string checkpoint = s.out + "/checkpoint.h5";
  {  // scene_toml replaced by a fixed-length string of 30,000 bytes (compact storage holds < 64 kB)
    const hid_t file = H5Fopen(checkpoint.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    REQUIRE(file >= 0);
    REQUIRE(H5Adelete(file, "scene_toml") >= 0);
    const std::string text(30000, '#');
    const hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, text.size());
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t attr = H5Acreate2(file, "scene_toml", type, space, H5P_DEFAULT, H5P_DEFAULT);
    REQUIRE(attr >= 0);
    CHECK(H5Awrite(attr, type, text.data()) >= 0);
    H5Aclose(attr);
    H5Sclose(space);
    H5Tclose(type);
    H5Fclose(file);
  }
  // A limit of 20 kB: the 100 particles fit (6 kB), the attribute does not.
  const CliOutcome o =
      run_cli("run --restart " + checkpoint + " --quiet --set time.end=0.02", "ARKSPH_MEMORY_LIMIT=20K", 120);
  check_refused(o, "attribute 'scene_toml' of 30 kB", "memory limit of 20.5 kB");
}
