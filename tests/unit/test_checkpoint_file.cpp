// Checkpoint files (io/checkpoint): the HDF5 round trip is bit-exact, unreadable files are one-line
// input errors, a write cut short leaves the previous checkpoint valid, and the scene key
// output.checkpoint_every. Runs of the binary that stop and restart: process/test_checkpoint_runs.cpp.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "checkpoint_sample.hpp"
#include "core/errors.hpp"
#include "io/checkpoint.hpp"
#include "io/csv_writer.hpp"  // temporary_path
#include "io/scene_reader.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;
using namespace arksph;
using arksph::testing::check_equal;
using arksph::testing::sample_checkpoint;
using arksph::testing::ScratchDir;
using arksph::testing::slurp;

TEST_CASE("checkpoint: write + read round trip is bit-exact") {
  ScratchDir dir("roundtrip");
  for (const auto& [n, dim, rho] : {std::tuple{257ul, 2, true}, std::tuple{100000ul, 2, false}, std::tuple{5ul, 1, true}}) {
    CAPTURE(n);
    const Checkpoint c = sample_checkpoint(n, dim, rho);
    write_checkpoint(dir / "checkpoint.h5", c);
    CHECK_FALSE(fs::exists(temporary_path(dir / "checkpoint.h5")));
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
  CHECK_THROWS_AS(write_checkpoint(dir / "no/such/dir/checkpoint.h5", sample_checkpoint(3, 2, true)), OutputError);
}

// A kill -9 while the next checkpoint is written leaves its temporary cut short beside the
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
  std::ofstream(temporary_path(path), std::ios::binary).write(full.data(), static_cast<std::streamsize>(full.size() / 2));
  check_equal(read_checkpoint(path), before);
  CHECK_THROWS_AS(read_checkpoint(temporary_path(path)), InputError);  // the torn file itself is rejected cleanly

  // The next successful write replaces the stale temporary.
  write_checkpoint(path, next);
  CHECK_FALSE(fs::exists(temporary_path(path)));
  CHECK(read_checkpoint(path).time == 0.5);
}

TEST_CASE("checkpoint: output.checkpoint_every is read, validated and written back") {
  std::ostringstream warnings;
  const Scene s = read_scene_text(testing::test_scene("taylor_green_checkpoints.toml"), "tg", {}, warnings);
  CHECK(s.checkpoint_every == 0.1);
  CHECK(read_scene_text(s.resolved_toml, "resolved", {}, warnings).checkpoint_every == 0.1);
  CHECK(s.resolved_toml.find("checkpoint_every = 0.1") != std::string::npos);
  CHECK(read_scene_text(default_scene_toml(), "default", {}, warnings).checkpoint_every == 0.0);
  CHECK_THROWS_AS(read_scene_text(testing::test_scene("taylor_green_checkpoints.toml"), "tg", {"output.checkpoint_every=-1"}, warnings), InputError);
}
