// `arksph batch` started by an MPI launcher (`mpirun -n K arksph batch SWEEP.toml`): the K processes
// share the sweep's runs without MPI itself (the binary is not linked against MPI and never calls
// MPI_Init). Each process learns its rank and the rank count from the launcher's environment, runs
// the runs whose index is its rank modulo K as child processes, and hands its rows to rank 0 through
// files in the batch folder; rank 0 writes batch.csv and batch.json with every run in sweep order.
//
// Files in the batch folder (names start with ".arksph.batch_", all written atomically):
//   .arksph.batch_group        rank 0, after taking the folder lock: the launch id and K. A rank > 0
//                              starts only when it finds its own launch id there, so the K ranks of
//                              one launch share the folder and a rank of another launch is refused.
//   .arksph.batch_rank<r>.pid  rank r > 0 on joining: host and pid (rank 0 notices a rank that ended
//                              on the same host without results instead of waiting forever).
//   .arksph.batch_rank<r>      rank r > 0 when its runs are finished: launch id, then one row per run.
// Rank 0 removes them when it has merged the rows.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "run/launcher_ranks.hpp"
#include "study/batch.hpp"

namespace arksph {

// Rank 0, holding the folder lock: removes the files of an earlier launch, writes the group file.
void publish_batch_group(const std::string& folder, const LauncherRanks& ranks);

// Rank r > 0: waits up to `timeout_seconds` for the group file of its own launch, then writes its
// pid file. InputError (exit 2) when it does not appear: rank 0 refused the folder (another batch
// holds it) or failed.
void join_batch_group(const std::string& folder, const LauncherRanks& ranks, double timeout_seconds);

// Rank r > 0: its rows (the runs with index ≡ r mod K) for rank 0.
void write_rank_rows(const std::string& folder, const LauncherRanks& ranks, const BatchResult& result);

// Rank 0: waits for the rows of every other rank and puts them into `result.runs` (status and counts
// not yet summed). A rank that ended, or did not join within `join_timeout_seconds`, without writing
// its rows leaves its runs as they are; its number is returned (a message per rank on stderr).
std::vector<int> collect_rank_rows(const std::string& folder, const LauncherRanks& ranks, BatchResult& result,
                                   double join_timeout_seconds);

}  // namespace arksph
