// Values of particles joined over the ranks by particle id (the ids of a model of n particles are
// 0 .. n - 1): the whole state for a checkpoint, a frame's rows, a value of every particle.
#pragma once
#include <algorithm>
#include <bit>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "parallel/communicator.hpp"

namespace arksph::parallel {

// Collective. Each rank's `count` particles (ids[a], `stride` values that fill(a, record) writes)
// go to `root`, or to every rank (root < 0), where place(id, record) is called once for every
// particle of every rank. The records travel in rounds of at most kJoinRecords a rank, so that a
// rank holds no copy of its records beyond one round's. Throws std::logic_error unless the ranks
// hold n particles, each with an id below n.
constexpr std::size_t kJoinRecords = 65536;
template <class Fill, class Place>
void join_by_id(const Communicator& comm, const std::int64_t* ids, std::size_t count, std::size_t stride, std::size_t n,
                int root, Fill&& fill, Place&& place) {
  const std::size_t width = stride + 1;  // the id's bits, then the values
  const bool receives = root < 0 || comm.rank() == root;
  const std::int64_t rounds = comm.max(static_cast<std::int64_t>((count + kJoinRecords - 1) / kJoinRecords));
  std::size_t received = 0;
  std::vector<double> chunk;
  for (std::int64_t r = 0; r < rounds; ++r) {
    const std::size_t first = std::min(count, static_cast<std::size_t>(r) * kJoinRecords);
    const std::size_t last = std::min(count, first + kJoinRecords);
    chunk.assign((last - first) * width, 0.0);
    for (std::size_t a = first; a < last; ++a) {
      double* record = chunk.data() + (a - first) * width;
      record[0] = std::bit_cast<double>(ids[a]);
      fill(a, record + 1);
    }
    const std::vector<double> all = root < 0 ? comm.allgatherv(chunk) : comm.gatherv(chunk, root);
    if (!receives) continue;
    for (std::size_t at = 0; at < all.size(); at += width) {
      const auto id = std::bit_cast<std::int64_t>(all[at]);
      if (id < 0 || static_cast<std::size_t>(id) >= n) throw std::logic_error("join by id: particle id out of range");
      place(static_cast<std::size_t>(id), all.data() + at + 1);
    }
    received += all.size() / width;
  }
  if (receives && received != n) throw std::logic_error("join by id: the ranks hold another number of particles");
}

// Collective. One value per particle on every rank, indexed by id, from each rank's values of its
// own particles (ids[i], values[i]).
inline std::vector<double> spread_by_id(const Communicator& comm, const std::vector<std::int64_t>& ids,
                                        const std::vector<double>& values, std::size_t n) {
  std::vector<double> out(n);
  join_by_id(
      comm, ids.data(), ids.size(), 1, n, -1, [&](std::size_t a, double* v) { v[0] = values[a]; },
      [&](std::size_t id, const double* v) { out[id] = v[0]; });
  return out;
}

}  // namespace arksph::parallel
