#include "parallel/migration.hpp"

#include <stdexcept>

namespace arksph::parallel {

MigrationCounts migrate(const Communicator& comm, const Decomposition& decomposition, ParticleFields& particles) {
  if (decomposition.ranks() != comm.size())
    throw std::invalid_argument("migrate: the decomposition is for another number of ranks");
  const Domain& domain = decomposition.grid().domain();
  const int me = comm.rank();
  std::vector<std::vector<double>> send(static_cast<std::size_t>(comm.size()));
  MigrationCounts counts;
  std::size_t kept = 0;
  double x[3] = {0, 0, 0};
  for (std::size_t i = 0; i < particles.size(); ++i) {
    particles.position(i, x);
    domain.wrap(x);
    for (int a = 0; a < particles.dim; ++a) particles.field[static_cast<std::size_t>(a)][i] = x[a];
    const int owner = decomposition.owner(x);
    if (owner == me) {
      if (kept != i) particles.move(i, kept);
      ++kept;
    } else {
      particles.pack(i, send[static_cast<std::size_t>(owner)]);
      ++counts.sent;
    }
  }
  particles.resize(kept);
  const std::vector<double> received = comm.alltoallv(send);
  counts.received = received.size() / particles.record_size();
  particles.unpack(received.data(), counts.received);
  return counts;
}

}  // namespace arksph::parallel
