#include "parallel/agreement.hpp"

#include <cstdint>
#include <vector>

namespace arksph::parallel {

Verdict agree(const Communicator& comm, const Verdict& mine) {
  std::int64_t none = 0;
  return agree(comm, mine, none);
}

Verdict agree(const Communicator& comm, const Verdict& mine, std::int64_t& flag) {
  Verdict v;
  // Ranked by code, then by whether the message names the particle.
  const std::int64_t key = 2 * static_cast<std::int64_t>(mine.code) + (mine.names_particle ? 1 : 0);
  std::vector<std::int64_t> both{key, flag};
  comm.max_in_place(both);
  const std::int64_t best = both[0];
  flag = both[1];
  v.code = static_cast<int>(best / 2);
  v.names_particle = best % 2 == 1;
  if (v.code == 0) return v;
  // The lowest rank with that key: the largest of size - rank over the ranks that have it.
  const std::int64_t size = comm.size();
  const int from = static_cast<int>(size - comm.max(key == best ? size - comm.rank() : std::int64_t{0}));
  int length = comm.rank() == from ? static_cast<int>(mine.message.size()) : 0;
  MPI_Bcast(&length, 1, MPI_INT, from, comm.comm());
  v.message = comm.rank() == from ? mine.message : std::string(static_cast<std::size_t>(length), ' ');
  MPI_Bcast(v.message.data(), length, MPI_CHAR, from, comm.comm());
  return v;
}

}  // namespace arksph::parallel
