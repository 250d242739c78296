#include "distributed/rank_verdict.hpp"

#include <cstdint>

namespace arksph::distributed {

Verdict agree(const parallel::Communicator& comm, const Verdict& mine) {
  Verdict v;
  v.code = static_cast<int>(comm.max(static_cast<std::int64_t>(mine.code)));
  if (v.code == 0) return v;
  // The lowest rank with that code: the largest of size - rank over the ranks that have it.
  const std::int64_t size = comm.size();
  const int from = static_cast<int>(size - comm.max(mine.code == v.code ? size - comm.rank() : std::int64_t{0}));
  int length = comm.rank() == from ? static_cast<int>(mine.message.size()) : 0;
  MPI_Bcast(&length, 1, MPI_INT, from, comm.comm());
  v.message = comm.rank() == from ? mine.message : std::string(static_cast<std::size_t>(length), ' ');
  MPI_Bcast(v.message.data(), length, MPI_CHAR, from, comm.comm());
  return v;
}

}  // namespace arksph::distributed
