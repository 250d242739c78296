// Helpers of the MPI tests: particle sets, global gathers and rank-wide checks.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <random>
#include <vector>

#include "parallel/communicator.hpp"
#include "parallel/particle_fields.hpp"
#include "parallel/rcb.hpp"

namespace arksph::parallel::testing {

// Fields of the test particles (2D): position, velocity, density, mass.
enum Field : int { X = 0, Y = 1, U = 2, V = 3, RHO = 4, MASS = 5, N_FIELDS = 6 };

inline Domain unit_domain(double lx, double ly, bool periodic_x, bool periodic_y) {
  Domain d;
  d.dim = 2;
  d.box.lo = {0.0, 0.0, 0.0};
  d.box.hi = {lx, ly, 0.0};
  d.periodic = {periodic_x, periodic_y, false};
  return d;
}

// A reproducible value of particle `id` (for the fields other than the position).
inline double value_of(std::uint64_t id, int field, int version) {
  return static_cast<double>(id % 1000) * 0.001 + field + 10.0 * version;
}

// n particles per rank at uniform random positions in the domain box, global ids
// rank * n .. rank * n + n - 1 (distinct also when n differs between the ranks but grows with rank).
inline ParticleFields random_particles(const Communicator& comm, const Domain& d, std::size_t n, unsigned seed) {
  ParticleFields p(2, N_FIELDS);
  std::mt19937_64 rng(seed * 7919u + static_cast<unsigned>(comm.rank()));
  std::uniform_real_distribution<double> ux(d.box.lo[0], d.box.hi[0]);
  std::uniform_real_distribution<double> uy(d.box.lo[1], d.box.hi[1]);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint64_t id = static_cast<std::uint64_t>(comm.rank()) * n + i;
    p.id.push_back(id);
    p.field[X].push_back(ux(rng));
    p.field[Y].push_back(uy(rng));
    for (int f = U; f < N_FIELDS; ++f) p.field[static_cast<std::size_t>(f)].push_back(value_of(id, f, 0));
  }
  return p;
}

// One particle as gathered from every rank: id and the fields.
struct Record {
  std::uint64_t id;
  std::array<double, N_FIELDS> f;
};

inline std::vector<Record> records(const ParticleFields& p) {
  std::vector<Record> out(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    out[i].id = p.id[i];
    for (int f = 0; f < N_FIELDS; ++f) out[i].f[static_cast<std::size_t>(f)] = p.field[static_cast<std::size_t>(f)][i];
  }
  return out;
}

// Every rank's particles, on every rank, sorted by id.
inline std::vector<Record> gather_all(const Communicator& comm, const ParticleFields& p) {
  std::vector<Record> all = comm.allgatherv(records(p));
  std::sort(all.begin(), all.end(), [](const Record& a, const Record& b) { return a.id < b.id; });
  return all;
}

// True on every rank when `ok` holds on every rank.
inline bool on_all_ranks(const Communicator& comm, bool ok) {
  return comm.sum(static_cast<std::int64_t>(ok ? 0 : 1)) == 0;
}

// The decomposition of the particles' current positions: counts per cell summed over the ranks.
inline Decomposition decompose(const Communicator& comm, const CellGrid& grid, const ParticleFields& p) {
  std::vector<std::int64_t> counts = count_per_cell(grid, p);
  comm.sum_in_place(counts);
  return Decomposition::rcb(grid, counts, comm.size());
}

// A well-mixed 64-bit hash (splitmix64 finaliser) for checksums of id sets.
inline std::uint64_t mix(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

}  // namespace arksph::parallel::testing
