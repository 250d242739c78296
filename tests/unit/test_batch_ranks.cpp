// The launcher environment and the rank files of `arksph batch` under mpirun (study/batch_ranks.hpp),
// in process: rank and size from Open MPI's or PMI's variables, and the rows of a rank > 0 read back
// by rank 0 field for field. The batch under a real mpiexec: tests/mpi/check_batch_ranks.py.
#include <doctest/doctest.h>

#include <unistd.h>

#include <cstdlib>
#include <map>
#include <string>

#include "core/errors.hpp"
#include "study/batch_ranks.hpp"
#include "test_support.hpp"

using namespace arksph;

namespace {
const char* const kVars[] = {"OMPI_COMM_WORLD_SIZE", "OMPI_COMM_WORLD_RANK", "OMPI_COMM_WORLD_LOCAL_SIZE",
                             "PMI_SIZE",             "PMI_RANK",             "MPI_LOCALNRANKS",
                             "PMIX_NAMESPACE",       "OMPI_MCA_ess_base_jobid", "PMI_KVSNAME"};

// Sets the given launcher variables (and unsets the others) for its lifetime.
struct LauncherEnv {
  std::map<std::string, std::string> saved;
  explicit LauncherEnv(const std::map<std::string, std::string>& set) {
    for (const char* v : kVars) {
      if (const char* old = std::getenv(v)) saved[v] = old;
      unsetenv(v);
    }
    for (const auto& [k, v] : set) setenv(k.c_str(), v.c_str(), 1);
  }
  ~LauncherEnv() {
    for (const char* v : kVars) unsetenv(v);
    for (const auto& [k, v] : saved) setenv(k.c_str(), v.c_str(), 1);
  }
};
}  // namespace

TEST_CASE("batch ranks: rank and size from Open MPI's or PMI's variables, one process without them") {
  {
    LauncherEnv e({});
    const LauncherRanks r = launcher_ranks_from_environment();
    CHECK(r.size == 1);
    CHECK(r.rank == 0);
  }
  {
    LauncherEnv e({{"OMPI_COMM_WORLD_SIZE", "3"}, {"OMPI_COMM_WORLD_RANK", "2"}, {"OMPI_COMM_WORLD_LOCAL_SIZE", "3"},
                   {"PMIX_NAMESPACE", "4711"}});
    const LauncherRanks r = launcher_ranks_from_environment();
    CHECK(r.size == 3);
    CHECK(r.rank == 2);
    CHECK(r.local_size == 3);
    CHECK(r.launch == "PMIX_NAMESPACE=4711");
  }
  {
    LauncherEnv e({{"PMI_SIZE", "4"}, {"PMI_RANK", "1"}, {"PMI_KVSNAME", "kvs_7"}});
    const LauncherRanks r = launcher_ranks_from_environment();
    CHECK(r.size == 4);
    CHECK(r.rank == 1);
    CHECK(r.launch == "PMI_KVSNAME=kvs_7");
  }
  {  // no launch id: host and parent pid, the same for the ranks a local launcher started
    LauncherEnv e({{"PMI_SIZE", "2"}, {"PMI_RANK", "0"}});
    CHECK(launcher_ranks_from_environment().launch.find(":" + std::to_string(getppid())) != std::string::npos);
  }
  {
    LauncherEnv e({{"OMPI_COMM_WORLD_SIZE", "2"}, {"OMPI_COMM_WORLD_RANK", "2"}});
    CHECK_THROWS_AS(launcher_ranks_from_environment(), InputError);
  }
  {
    LauncherEnv e({{"OMPI_COMM_WORLD_SIZE", "two"}, {"OMPI_COMM_WORLD_RANK", "0"}});
    CHECK_THROWS_AS(launcher_ranks_from_environment(), InputError);
  }
}

// Rank 1 of 2 writes the rows of runs 1 and 3; rank 0 reads them into its result unchanged and
// leaves runs 0 and 2 (its own) alone; the rank files are gone afterwards.
TEST_CASE("batch ranks: the rows of a rank > 0 reach rank 0 field for field") {
  testing::ScratchDir scratch("batch_ranks_rows");
  const std::string folder = scratch.dir.string();
  LauncherRanks r0{0, 2, 1, "test-launch"}, r1{1, 2, 1, "test-launch"};
  publish_batch_group(folder, r0);
  join_batch_group(folder, r1, 5);

  BatchResult theirs;
  theirs.runs.resize(4);
  theirs.runs[1] = {"1_a", "", {"x"}, "failed", 3, false, 0.125, 17, 35, {{"kinetic_energy", "0.24616027516505956"}, {"l2", "nan"}}, true};
  theirs.runs[3] = {"3_b", "", {"y"}, "ok", 0, true, 2.5, 4, 9, {{"kinetic_energy", "1e-300"}}};
  write_rank_rows(folder, r1, theirs);

  BatchResult mine;
  mine.runs.resize(4);
  mine.runs[0].status = mine.runs[2].status = "ok";
  mine.runs[1].status = mine.runs[3].status = "unset";
  CHECK(collect_rank_rows(folder, r0, mine, 5).empty());
  CHECK(mine.runs[0].status == "ok");
  CHECK(mine.runs[2].status == "ok");
  for (const int i : {1, 3}) {
    const BatchRunResult &a = mine.runs[i], &b = theirs.runs[i];
    CHECK(a.status == b.status);
    CHECK(a.exit_code == b.exit_code);
    CHECK(a.skipped == b.skipped);
    CHECK(a.resumed == b.resumed);
    CHECK(a.wall_seconds == b.wall_seconds);
    CHECK(a.steps == b.steps);
    CHECK(a.rhs_evals == b.rhs_evals);
    CHECK(a.metrics == b.metrics);
  }
  int left = 0;
  for (const auto& e : std::filesystem::directory_iterator(folder)) left += e.path().filename().string().rfind(".arksph.batch_", 0) == 0;
  CHECK(left == 0);
}

// A rank > 0 starts only on its own launch's group file (id and rank count): the group file of
// another launch, an earlier batch or one holding the folder, makes it give up after the timeout.
TEST_CASE("batch ranks: a rank waits for its own launch's group file, not another's") {
  testing::ScratchDir scratch("batch_ranks_group");
  const std::string folder = scratch.dir.string();
  publish_batch_group(folder, LauncherRanks{0, 2, 1, "other-launch"});
  CHECK_THROWS_AS(join_batch_group(folder, LauncherRanks{1, 2, 1, "this-launch"}, 0.5), InputError);
  publish_batch_group(folder, LauncherRanks{0, 2, 1, "this-launch"});
  CHECK_NOTHROW(join_batch_group(folder, LauncherRanks{1, 2, 1, "this-launch"}, 0.5));
  CHECK_THROWS_AS(join_batch_group(folder, LauncherRanks{1, 3, 1, "this-launch"}, 0.5), InputError);  // another size
}
