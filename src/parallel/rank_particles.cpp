#include "parallel/rank_particles.hpp"

#include "core/particle_order.hpp"

namespace arksph::parallel {

RankParticles::RankParticles(const ParticleSet& all, const StateLayout& layout, const double* y,
                             const Decomposition& decomposition, int rank) {
  ix_.dim = layout.dim;
  ix_.density = layout.has_density;
  ix_.energy = layout.has_energy;
  blocks_ = ix_.state_blocks(false);
  p_ = ParticleFields(ix_.dim, ix_.count());
  double x[3] = {0, 0, 0};
  const Domain& domain = decomposition.grid().domain();
  for (std::size_t a = 0; a < layout.n; ++a) {
    for (int k = 0; k < ix_.dim; ++k) x[k] = y[layout.pos(k) + a];
    domain.wrap(x);
    if (decomposition.owner(x) != rank) continue;
    p_.id.push_back(static_cast<std::uint64_t>(all.id[a]));
    for (int k = 0; k < ix_.dim; ++k) {
      p_.field[static_cast<std::size_t>(ix_.seen(k))].push_back(x[k]);
      p_.field[static_cast<std::size_t>(ix_.state_pos(k))].push_back(y[layout.pos(k) + a]);
      p_.field[static_cast<std::size_t>(ix_.vel(k))].push_back(y[layout.vel(k) + a]);
    }
    if (ix_.density) p_.field[static_cast<std::size_t>(ix_.rho())].push_back(y[layout.rho() + a]);
    if (ix_.energy) p_.field[static_cast<std::size_t>(ix_.e())].push_back(y[layout.energy() + a]);
    p_.field[static_cast<std::size_t>(ix_.mass())].push_back(all.mass[a]);
    p_.field[static_cast<std::size_t>(ix_.rho0())].push_back(all.rho0[a]);
    p_.field[static_cast<std::size_t>(ix_.phase())].push_back(all.phase.empty() ? 0.0 : all.phase[a]);
  }
  refresh_ids();
}

StateLayout RankParticles::layout() const {
  StateLayout L;
  L.n = size();
  L.dim = ix_.dim;
  L.has_density = ix_.density;
  L.has_energy = ix_.energy;
  return L;
}

std::vector<double> RankParticles::state() const {
  const std::size_t n = size();
  std::vector<double> y(layout().size());
  std::size_t at = 0;
  for (int field : blocks_) {
    const auto& f = p_.field[static_cast<std::size_t>(field)];
    std::copy(f.begin(), f.end(), y.begin() + static_cast<long>(at));
    at += n;
  }
  return y;
}

void RankParticles::load(const double* y) {
  const std::size_t n = size();
  for (int field : blocks_) {
    p_.field[static_cast<std::size_t>(field)].assign(y, y + n);
    y += n;
  }
}

void RankParticles::sort_by_cell(const double* lo, double side) {
  const std::size_t n = p_.size();
  const double* y = ix_.dim == 2 ? p_.field[static_cast<std::size_t>(ix_.seen(1))].data() : nullptr;
  const Permutation from =
      cell_order(p_.field[static_cast<std::size_t>(ix_.seen(0))].data(), y, n, lo[0], ix_.dim == 2 ? lo[1] : 0.0, side);
  permute(p_.id, from);
  for (auto& f : p_.field) permute(f, from);
  refresh_ids();
}

void RankParticles::wrap_seen(const Domain& domain) {
  double x[3] = {0, 0, 0};
  for (std::size_t a = 0; a < p_.size(); ++a) {
    for (int k = 0; k < ix_.dim; ++k) x[k] = p_.field[static_cast<std::size_t>(ix_.state_pos(k))][a];
    domain.wrap(x);
    for (int k = 0; k < ix_.dim; ++k) p_.field[static_cast<std::size_t>(ix_.seen(k))][a] = x[k];
  }
}

void RankParticles::refresh_ids() { ids_.assign(p_.id.begin(), p_.id.end()); }

}  // namespace arksph::parallel
