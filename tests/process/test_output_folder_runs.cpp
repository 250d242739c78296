// The output folder as several runs see it (run/output_folder.hpp, docs/user-guide.md "The output
// folder"): the lock against a second run, an earlier run's files, foreign files, a restart into
// another run's folder or with a missing collection, restart keys that shape the particle set, and
// frame rows in id order. Each test runs the real binary (ARKSPH_TEST_BINARY selects another).
#include <doctest/doctest.h>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

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

namespace {

// The minimal scene: 10 x 10 particles in the unit box, two steps' worth of time.
const char* kFolderScene =
    "[domain]\nmin = [0.0, 0.0]\nmax = [1.0, 1.0]\n[fluid]\nspacing = 0.1\n[time]\nend = 0.01\n";

std::string write_folder_scene(const ScratchDir& scratch) {
  const std::string path = scratch / "S.toml";
  std::ofstream(path) << kFolderScene;
  return path;
}

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

// This process plays a first run in `dir`: it holds the lock and has written its pid into the file.
// Returns the descriptor (closing it releases the lock).
int hold_lock(const std::string& dir) {
  fs::create_directories(dir);
  const int fd = ::open((dir + "/.arksph.lock").c_str(), O_RDWR | O_CREAT, 0644);
  REQUIRE(fd >= 0);
  REQUIRE(::flock(fd, LOCK_EX | LOCK_NB) == 0);
  const std::string pid = std::to_string(::getpid()) + "\n";
  REQUIRE(::write(fd, pid.data(), pid.size()) == static_cast<ssize_t>(pid.size()));
  return fd;
}

}  // namespace

TEST_CASE("output folder: a second run into a folder locked by another run exits 2 naming its pid") {
  ScratchDir scratch("lock");
  const std::string scene = write_folder_scene(scratch), out = scratch / "out";
  const int fd = hold_lock(out);
  const std::string pid = std::to_string(::getpid());
  const RunOutcome o = run_arksph_captured("run " + scene + " --quiet --out " + out, scratch.dir.string());
  CHECK(o.code == 2);
  CHECK(o.err.find("pid " + pid) != std::string::npos);
  CHECK_FALSE(fs::exists(out + "/summary.json"));  // nothing written by the refused run
  ::close(fd);  // released: the same run now goes through
  CHECK(run_arksph_captured("run " + scene + " --quiet --out " + out, scratch.dir.string()).code == 0);
}

TEST_CASE("output folder: a second batch into a locked batch folder exits 2 naming the pid") {
  ScratchDir scratch("batch_lock");
  write_folder_scene(scratch);
  std::ofstream(scratch / "sweep.toml") << "[sweep]\nscene = \"S.toml\"\n[[vary]]\nkey = \"time.end\"\nvalues = [0.01]\n";
  const std::string out = scratch / "b";
  const int fd = hold_lock(out);
  const RunOutcome o = run_arksph_captured("batch " + (scratch / "sweep.toml") + " --quiet --out " + out,
                                           scratch.dir.string());
  CHECK(o.code == 2);
  CHECK(o.err.find("pid " + std::to_string(::getpid())) != std::string::npos);
  CHECK_FALSE(fs::exists(out + "/batch.csv"));
  ::close(fd);
}

TEST_CASE("output folder: a fresh run removes the frames of an earlier, longer run") {
  ScratchDir scratch("stale");
  const std::string scene = write_folder_scene(scratch), out = scratch / "out";
  REQUIRE(run_arksph_captured("run " + scene + " --quiet --out " + out + " --set output.every=0.0025",
                              scratch.dir.string()).code == 0);
  REQUIRE(fs::exists(out + "/particles_000004.vtp"));
  REQUIRE(run_arksph_captured("run " + scene + " --quiet --out " + out, scratch.dir.string()).code == 0);
  CHECK(fs::exists(out + "/particles_000001.vtp"));
  for (const char* stale : {"particles_000002.vtp", "particles_000003.vtp", "particles_000004.vtp"})
    CHECK_FALSE(fs::exists(out + "/" + stale));
  CHECK(count(slurp(out + "/particles.pvd"), "<DataSet") == 2);
}

TEST_CASE("output folder: files that are not run outputs refuse the folder unless --overwrite, and stay") {
  ScratchDir scratch("foreign");
  const std::string scene = write_folder_scene(scratch), out = scratch / "out";
  fs::create_directories(out);
  std::ofstream(out + "/notes.txt") << "mine\n";
  const RunOutcome refused = run_arksph_captured("run " + scene + " --quiet --out " + out, scratch.dir.string());
  CHECK(refused.code == 2);
  CHECK(refused.err.find("notes.txt") != std::string::npos);
  CHECK(refused.err.find("--overwrite") != std::string::npos);
  CHECK_FALSE(fs::exists(out + "/summary.json"));
  CHECK(run_arksph_captured("run " + scene + " --quiet --overwrite --out " + out, scratch.dir.string()).code == 0);
  CHECK(slurp(out + "/notes.txt") == "mine\n");
  CHECK(fs::exists(out + "/summary.json"));
}

TEST_CASE("output folder: a restart into the folder of another run exits 2 and leaves it alone") {
  ScratchDir scratch("other_run");
  const std::string scene = write_folder_scene(scratch), a = scratch / "a", b = scratch / "b";
  REQUIRE(run_arksph_captured("run " + scene + " --quiet --out " + a, scratch.dir.string()).code == 0);
  REQUIRE(run_arksph_captured("run " + scene + " --quiet --out " + b + " --set output.every=0.005",
                              scratch.dir.string()).code == 0);
  const std::string pvd_before = slurp(b + "/particles.pvd");
  const RunOutcome o = run_arksph_captured("run --restart " + a + "/checkpoint.h5 --quiet --out " + b +
                                               " --set time.end=0.02", scratch.dir.string());
  CHECK(o.code == 2);
  CHECK(o.err.find("another run") != std::string::npos);
  CHECK(slurp(b + "/particles.pvd") == pvd_before);
  // A collection without a run id (written by a run that records none) is not this run's either.
  const std::string d = scratch / "d";
  fs::create_directories(d);
  std::ofstream(d + "/particles.pvd") << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\">\n  <Collection>\n"
                                         "    <DataSet timestep=\"0\" file=\"particles_000000.vtp\"/>\n  </Collection>\n</VTKFile>\n";
  CHECK(run_arksph_captured("run --restart " + a + "/checkpoint.h5 --quiet --out " + d + " --set time.end=0.02",
                            scratch.dir.string()).code == 2);
  // Its own folder, and an empty one, are fine.
  CHECK(run_arksph_captured("run --restart " + a + "/checkpoint.h5 --quiet --out " + (scratch / "c") +
                                " --set time.end=0.02", scratch.dir.string()).code == 0);
  CHECK(run_arksph_captured("run --restart " + a + "/checkpoint.h5 --quiet --set time.end=0.02",
                            scratch.dir.string()).code == 0);
}

TEST_CASE("output folder: a restart with particles.pvd missing or garbage warns and rebuilds it from the frames") {
  for (const bool garbage : {false, true}) {
    CAPTURE(garbage);
    ScratchDir scratch(garbage ? "pvd_garbage" : "pvd_missing");
    const std::string scene = write_folder_scene(scratch), out = scratch / "out";
    REQUIRE(run_arksph_captured("run " + scene + " --quiet --out " + out + " --set output.every=0.005",
                                scratch.dir.string()).code == 0);
    REQUIRE(count(slurp(out + "/particles.pvd"), "<DataSet") == 3);
    if (garbage) std::ofstream(out + "/particles.pvd") << "\x01\x02 not xml";
    else fs::remove(out + "/particles.pvd");
    const RunOutcome o = run_arksph_captured("run --restart " + out + "/checkpoint.h5 --quiet --set time.end=0.02",
                                             scratch.dir.string());
    CHECK(o.code == 0);
    CHECK(o.err.find("particles.pvd") != std::string::npos);
    const std::string pvd = slurp(out + "/particles.pvd");
    for (int k = 0; k <= 4; ++k) CHECK(pvd.find("particles_00000" + std::to_string(k) + ".vtp") != std::string::npos);
    CHECK(pvd.find("timestep=\"0.005") != std::string::npos);  // the time from timeseries.csv
  }
}

TEST_CASE("output folder: a restart that changes a key shaping the particle set or the walls exits 2 naming it") {
  ScratchDir scratch("restart_keys");
  const std::string scene = write_folder_scene(scratch), out = scratch / "out";
  REQUIRE(run_arksph_captured("run " + scene + " --quiet --out " + out, scratch.dir.string()).code == 0);
  const std::string ck = out + "/checkpoint.h5";
  // Each keeps the particle count (100) so that the particle-array check alone would pass.
  const std::pair<const char*, const char*> changes[] = {
      {"'domain.max=[2.0, 0.5]'", "domain.max"},
      {"'domain.min=[0.5, 0.0]' --set 'domain.max=[1.5, 1.0]'", "domain.min"},
      {"'boundary.top={kind=\"wall\", slip=\"free_slip\"}'", "boundary.top.slip"},
      {"'initial.offset=[\"0.01\", \"0\"]'", "initial.offset"},
  };
  for (const auto& [set, key] : changes) {
    CAPTURE(set);
    const RunOutcome o = run_arksph_captured("run --restart " + ck + " --quiet --set time.end=0.02 --set " + set,
                                             scratch.dir.string());
    CHECK(o.code == 2);
    CHECK(o.err.find(key) != std::string::npos);
  }
  // A key that does not shape the particle set still may change.
  CHECK(run_arksph_captured("run --restart " + ck + " --quiet --set time.end=0.02 --set fluid.viscosity=0.02",
                            scratch.dir.string()).code == 0);
}

// method.reorder_every = 1 re-sorts the particles by cell after every step; the frames still list
// them by id, so that row k of every frame is the same particle.
TEST_CASE("output folder: VTP rows are in id order with re-sorting on") {
  ScratchDir scratch("id_order");
  const std::string scene = write_folder_scene(scratch), out = scratch / "out";
  REQUIRE(run_arksph_captured("run " + scene + " --quiet --out " + out +
                                  " --set method.reorder_every=1 --set time.dt=0.001 --set output.every=0.005 "
                                  "--set 'initial.velocity=[\"sin(6*y)\", \"cos(5*x)\"]'",
                              scratch.dir.string()).code == 0);
  for (const char* frame : {"particles_000001.vtp", "particles_000002.vtp"}) {
    CAPTURE(frame);
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName((out + "/" + frame).c_str());
    reader->Update();
    vtkDataArray* id = reader->GetOutput()->GetPointData()->GetArray("id");
    REQUIRE(id != nullptr);
    REQUIRE(id->GetNumberOfTuples() == 100);
    int out_of_order = 0;
    for (vtkIdType k = 1; k < id->GetNumberOfTuples(); ++k) out_of_order += id->GetTuple1(k) < id->GetTuple1(k - 1);
    CHECK(out_of_order == 0);
  }
}
