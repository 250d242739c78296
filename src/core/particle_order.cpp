#include "core/particle_order.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace arksph {

namespace {
// Cell coordinate of p, clamped at 0 below (particles in a stage may sit slightly outside the box).
std::uint64_t cell_of(double p, double p0, double inv_side) {
  const double c = std::floor((p - p0) * inv_side);
  return c > 0 && c < 4e9 ? static_cast<std::uint64_t>(c) : 0;
}
}  // namespace

std::vector<std::uint64_t> cell_keys(const double* x, const double* y, std::size_t n, double x0, double y0,
                                     double side) {
  const double inv = 1.0 / side;
  std::uint64_t nx = 1;
  for (std::size_t a = 0; a < n; ++a) nx = std::max(nx, cell_of(x[a], x0, inv) + 1);
  std::vector<std::uint64_t> key(n);
  for (std::size_t a = 0; a < n; ++a) key[a] = (y ? cell_of(y[a], y0, inv) * nx : 0) + cell_of(x[a], x0, inv);
  return key;
}

Permutation cell_order(const double* x, const double* y, std::size_t n, double x0, double y0, double side) {
  const std::vector<std::uint64_t> key = cell_keys(x, y, n, x0, y0, side);
  // Counting sort on the dense key range (n particles spread over at most ~n / (density) cells).
  const std::uint64_t kmax = n ? *std::max_element(key.begin(), key.end()) : 0;
  Permutation from(n);
  if (kmax <= 16 * static_cast<std::uint64_t>(n) + 1024) {
    std::vector<std::uint32_t> start(static_cast<std::size_t>(kmax) + 2, 0);
    for (std::uint64_t k : key) ++start[static_cast<std::size_t>(k) + 1];
    for (std::size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
    for (std::size_t a = 0; a < n; ++a) from[start[static_cast<std::size_t>(key[a])]++] = static_cast<std::uint32_t>(a);
  } else {  // a sparse grid (particles far apart): a comparison sort
    for (std::size_t a = 0; a < n; ++a) from[a] = static_cast<std::uint32_t>(a);
    std::stable_sort(from.begin(), from.end(), [&](std::uint32_t a, std::uint32_t b) { return key[a] < key[b]; });
  }
  return from;
}

void permute_block(double* p, const Permutation& from) {
  std::vector<double> old(p, p + from.size());
  for (std::size_t i = 0; i < from.size(); ++i) p[i] = old[from[i]];
}

void permute(ParticleSet& ps, const Permutation& from) {
  permute(ps.mass, from);
  permute(ps.rho0, from);
  permute(ps.id, from);
  permute(ps.phase, from);
  if (!ps.init_rho.empty()) permute(ps.init_rho, from);
  for (int k = 0; k < 2; ++k) {
    permute(ps.init_pos[k], from);
    permute(ps.init_vel[k], from);
  }
}

void permute_state(const StateLayout& L, double* y, const Permutation& from) {
  const std::size_t blocks = L.size() / std::max<std::size_t>(L.n, 1);
  for (std::size_t b = 0; b < blocks; ++b) permute_block(y + b * L.n, from);
}

Permutation permutation_to(const std::vector<std::int64_t>& current, const std::vector<std::int64_t>& target) {
  if (current.size() != target.size()) return {};
  std::unordered_map<std::int64_t, std::uint32_t> where;
  where.reserve(current.size());
  for (std::size_t a = 0; a < current.size(); ++a) where.emplace(current[a], static_cast<std::uint32_t>(a));
  if (where.size() != current.size()) return {};  // duplicate ids: no unique permutation
  Permutation from(target.size());
  std::vector<bool> used(current.size(), false);
  for (std::size_t i = 0; i < target.size(); ++i) {
    const auto it = where.find(target[i]);
    if (it == where.end() || used[it->second]) return {};
    used[it->second] = true;
    from[i] = it->second;
  }
  return from;
}

Permutation shuffled_order(std::size_t n, std::uint64_t seed) {
  Permutation from(n);
  for (std::size_t a = 0; a < n; ++a) from[a] = static_cast<std::uint32_t>(a);
  std::uint64_t s = seed;
  const auto next = [&s]() {  // splitmix64
    std::uint64_t z = (s += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  };
  for (std::size_t i = n; i > 1; --i) std::swap(from[i - 1], from[next() % i]);
  return from;
}

}  // namespace arksph
