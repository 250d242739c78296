#include "distributed/gather_state.hpp"

#include <bit>
#include <stdexcept>

namespace arksph::distributed {

StateGather::StateGather(const std::vector<std::int64_t>& ids, const StateLayout& layout)
    : layout_(layout), place_(ids.size(), kNowhere) {
  for (std::size_t i = 0; i < ids.size(); ++i) {
    if (ids[i] < 0 || static_cast<std::size_t>(ids[i]) >= ids.size())
      throw std::logic_error("state gather: the model's ids are not 0 .. n - 1");
    place_[static_cast<std::size_t>(ids[i])] = i;
  }
}

std::size_t StateGather::stride() const {
  return 1 + 2 * static_cast<std::size_t>(layout_.dim) + (layout_.has_density ? 1 : 0) + (layout_.has_energy ? 1 : 0);
}

std::vector<double> StateGather::records(const RankParticles& mine) const {
  const StateLayout L = mine.layout();
  const std::size_t per = L.n ? L.size() / L.n : 0;
  const std::size_t stride = this->stride();
  if (L.n && per + 1 != stride) throw std::logic_error("state gather: unexpected layout");
  // The state's fields in the layout's order (positions, velocities, density, energy), read from
  // the rank's records: no copy of the rank's state.
  const RankFieldIndex& ix = mine.index();
  std::vector<const double*> fields;
  for (int k = 0; k < ix.dim; ++k) fields.push_back(mine.fields().field[static_cast<std::size_t>(ix.state_pos(k))].data());
  for (int k = 0; k < ix.dim; ++k) fields.push_back(mine.fields().field[static_cast<std::size_t>(ix.vel(k))].data());
  if (ix.density) fields.push_back(mine.fields().field[static_cast<std::size_t>(ix.rho())].data());
  if (ix.energy) fields.push_back(mine.fields().field[static_cast<std::size_t>(ix.e())].data());
  std::vector<double> out;
  out.reserve(L.n * stride);
  for (std::size_t a = 0; a < L.n; ++a) {
    out.push_back(std::bit_cast<double>(mine.fields().id[a]));
    for (const double* field : fields) out.push_back(field[a]);
  }
  return out;
}

std::vector<double> StateGather::assemble(const std::vector<double>& all) const {
  const std::size_t stride = this->stride();
  std::vector<double> out(layout_.size());
  const std::size_t n = layout_.n;
  if (all.size() != n * stride) throw std::logic_error("state gather: the ranks hold another number of particles");
  for (std::size_t r = 0; r < n; ++r) {
    const double* rec = all.data() + r * stride;
    const auto id = std::bit_cast<std::uint64_t>(rec[0]);
    if (id >= place_.size() || place_[id] == kNowhere) throw std::logic_error("state gather: unknown particle id");
    for (std::size_t b = 0; b + 1 < stride; ++b) out[b * n + place_[id]] = rec[1 + b];
  }
  return out;
}

std::vector<double> StateGather::gather(const parallel::Communicator& comm, const RankParticles& mine) const {
  const std::vector<double> all = comm.gatherv(records(mine), 0);
  if (comm.rank() != 0) return {};
  return assemble(all);
}

std::vector<double> StateGather::allgather(const parallel::Communicator& comm, const RankParticles& mine) const {
  return assemble(comm.allgatherv(records(mine)));
}

std::vector<double> spread_by_id(const parallel::Communicator& comm, const std::vector<std::int64_t>& ids,
                                 const std::vector<double>& values, std::size_t n) {
  if (ids.size() != values.size()) throw std::logic_error("spread by id: one value per particle");
  struct Entry {
    std::int64_t id;
    double value;
  };
  std::vector<Entry> mine(ids.size());
  for (std::size_t a = 0; a < ids.size(); ++a) mine[a] = {ids[a], values[a]};
  const std::vector<Entry> all = comm.allgatherv(mine);
  if (all.size() != n) throw std::logic_error("spread by id: the ranks hold another number of particles");
  std::vector<double> out(n);
  for (const Entry& e : all) {
    if (e.id < 0 || static_cast<std::size_t>(e.id) >= n) throw std::logic_error("spread by id: particle id out of range");
    out[static_cast<std::size_t>(e.id)] = e.value;
  }
  return out;
}

}  // namespace arksph::distributed
