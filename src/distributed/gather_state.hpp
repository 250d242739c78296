// The whole state of a decomposed run on rank 0, for the output: every rank sends its particles'
// ids and state fields (one gather), rank 0 puts them at their particles' places in its own model
// (a one-process model of the whole scene) and writes frames, timeseries.csv and summary.json as a
// one-process run does. Rank 0 thus holds the whole state: the size limit of this output
// (docs/parallel.md).
#pragma once
#include <cstdint>
#include <vector>

#include "core/particles.hpp"
#include "distributed/rank_particles.hpp"
#include "parallel/communicator.hpp"

namespace arksph::distributed {

class StateGather {
 public:
  // `ids`: the particle ids of the model on rank 0, in the order of its state vector (`layout`).
  StateGather(const std::vector<std::int64_t>& ids, const StateLayout& layout);
  // Collective. Rank 0: the whole state in the model's layout; other ranks: empty.
  std::vector<double> gather(const parallel::Communicator& comm, const RankParticles& mine) const;
  // Collective. The whole state in the model's layout on every rank (checkpoints: every rank then
  // deals the particles anew from it, distributed/distributed_run.cpp).
  std::vector<double> allgather(const parallel::Communicator& comm, const RankParticles& mine) const;

 private:
  // This rank's particles as records: the id's bits, then the state entries in layout order.
  std::vector<double> records(const RankParticles& mine) const;
  // The whole state from every rank's records.
  std::vector<double> assemble(const std::vector<double>& all) const;
  std::size_t stride() const;
  StateLayout layout_;
  static constexpr std::size_t kNowhere = static_cast<std::size_t>(-1);
  std::vector<std::size_t> place_;  // id -> index in the model (ids are 0 .. n - 1)
};

// Collective. One value per particle on every rank, indexed by particle id (the ids of a model of n
// particles are 0 .. n - 1), from each rank's values of its own particles (ids[i], values[i]).
std::vector<double> spread_by_id(const parallel::Communicator& comm, const std::vector<std::int64_t>& ids,
                                 const std::vector<double>& values, std::size_t n);

}  // namespace arksph::distributed
