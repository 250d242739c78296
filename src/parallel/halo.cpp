#include "parallel/halo.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace arksph::parallel {

namespace {

// Every combination of {0, -L, +L} on the periodic axes (0 on the others); the zero shift first.
std::vector<std::array<double, 3>> period_shifts(const Domain& domain) {
  std::vector<std::array<double, 3>> shifts{{0.0, 0.0, 0.0}};
  for (int a = 0; a < domain.dim; ++a) {
    if (!domain.periodic[a]) continue;
    const std::size_t n = shifts.size();
    for (double k : {-1.0, 1.0})
      for (std::size_t s = 0; s < n; ++s) {
        std::array<double, 3> shifted = shifts[s];
        shifted[a] = k * domain.period(a);
        shifts.push_back(shifted);
      }
  }
  return shifts;
}

}  // namespace

void HaloExchange::exchange(const Communicator& comm, const Decomposition& decomposition, const ParticleFields& owned,
                            double cutoff, ParticleFields& halo) {
  if (decomposition.ranks() != comm.size()) throw std::invalid_argument("halo: the decomposition is for another number of ranks");
  std::vector<Box> boxes;
  for (int r = 0; r < decomposition.ranks(); ++r) boxes.push_back(decomposition.box(r));
  exchange(comm, decomposition.grid().domain(), boxes, owned, cutoff, halo);
}

void HaloExchange::exchange(const Communicator& comm, const Domain& domain, const std::vector<Box>& boxes,
                            const ParticleFields& owned, double cutoff, ParticleFields& halo) {
  const int dim = owned.dim, ranks = comm.size(), me = comm.rank();
  if (boxes.size() != static_cast<std::size_t>(ranks)) throw std::invalid_argument("halo: one box per rank expected");
  if (owned.size() > std::numeric_limits<std::uint32_t>::max()) throw std::length_error("halo: too many particles");
  for (int a = 0; a < dim; ++a)
    if (domain.periodic[a] && !(cutoff < domain.period(a)))
      throw std::invalid_argument("halo: the cut-off must be shorter than every periodic length");
  shifts_ = period_shifts(domain);
  const double cut2 = cutoff * cutoff;

  // The box around this rank's particles (its own box after migration), to list the (rank, shift)
  // pairs that can receive anything at all.
  Box around = boxes[static_cast<std::size_t>(me)];
  double x[3] = {0, 0, 0};
  for (std::size_t i = 0; i < owned.size(); ++i) {
    owned.position(i, x);
    for (int a = 0; a < dim; ++a) {
      around.lo[a] = std::min(around.lo[a], x[a]);
      around.hi[a] = std::max(around.hi[a], x[a]);
    }
  }
  struct Target {
    int rank;
    std::uint32_t shift;
    Box box;
  };
  std::vector<Target> targets;
  for (int r = 0; r < ranks; ++r)
    for (std::uint32_t s = 0; s < shifts_.size(); ++s) {
      if (r == me && s == 0) continue;
      const Box& box = boxes[static_cast<std::size_t>(r)];
      if (around.distance2(box, shifts_[s], dim) < cut2) targets.push_back({r, s, box});
    }

  send_.assign(static_cast<std::size_t>(ranks), {});
  std::vector<std::vector<double>> records(static_cast<std::size_t>(ranks));
  for (std::size_t i = 0; i < owned.size(); ++i) {
    owned.position(i, x);
    for (const Target& t : targets) {
      const auto& s = shifts_[t.shift];
      double xs[3] = {0, 0, 0};
      for (int a = 0; a < dim; ++a) xs[a] = x[a] + s[static_cast<std::size_t>(a)];
      if (!(t.box.distance2(xs, dim) < cut2)) continue;
      send_[static_cast<std::size_t>(t.rank)].push_back({static_cast<std::uint32_t>(i), t.shift});
      auto& out = records[static_cast<std::size_t>(t.rank)];
      const std::size_t at = out.size();
      owned.pack(i, out);
      for (int a = 0; a < dim; ++a) out[at + 1 + static_cast<std::size_t>(a)] = xs[a];
    }
  }
  // Per destination: by particle, then shift (the targets are listed by rank, then shift).
  const std::vector<double> received = comm.alltoallv(records, &received_per_rank_);
  for (auto& n : received_per_rank_) n /= owned.record_size();
  halo = owned.empty_like();
  received_ = received.size() / owned.record_size();
  halo.unpack(received.data(), received_);
}

void HaloExchange::update(const Communicator& comm, const ParticleFields& owned, const std::vector<int>& fields,
                          ParticleFields& halo) const {
  update_max(comm, owned, fields, halo, 0.0);
}

double HaloExchange::update_max(const Communicator& comm, const ParticleFields& owned, const std::vector<int>& fields,
                                ParticleFields& halo, double local) const {
  if (halo.size() != received_ || send_.size() != static_cast<std::size_t>(comm.size()))
    throw std::invalid_argument("halo update: not the halo of the last exchange");
  for (int f : fields)
    if (f < 0 || static_cast<std::size_t>(f) >= owned.n_fields()) throw std::invalid_argument("halo update: no such field");
  // Per destination: `local`, then the values of each listed copy.
  const std::size_t nf = fields.size();
  std::vector<std::vector<double>> records(send_.size());
  std::vector<std::size_t> receive(send_.size());
  for (std::size_t r = 0; r < send_.size(); ++r) {
    auto& out = records[r];
    out.reserve(1 + send_[r].size() * nf);
    out.push_back(local);
    for (const Entry& e : send_[r]) {
      if (e.index >= owned.size()) throw std::invalid_argument("halo update: fewer particles than at the exchange");
      for (int f : fields) {
        const double v = owned.field[static_cast<std::size_t>(f)][e.index];
        out.push_back(f < owned.dim ? v + shifts_[e.shift][static_cast<std::size_t>(f)] : v);
      }
    }
    receive[r] = 1 + received_per_rank_[r] * nf;
  }
  const std::vector<double> received = comm.alltoallv_known(records, receive);
  double largest = local;
  std::size_t at = 0, k = 0;
  for (std::size_t r = 0; r < send_.size(); ++r) {
    largest = std::max(largest, received[at++]);  // NaN from a rank is not larger: as Communicator::max on one rank
    for (std::size_t c = 0; c < received_per_rank_[r]; ++c, ++k)
      for (std::size_t j = 0; j < nf; ++j) halo.field[static_cast<std::size_t>(fields[j])][k] = received[at++];
  }
  return largest;
}

std::size_t HaloExchange::sent() const {
  std::size_t n = 0;
  for (const auto& s : send_) n += s.size();
  return n;
}

}  // namespace arksph::parallel
