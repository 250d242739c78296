// The point of the halo: an SPH sum over owned + halo particles on P ranks equals the sum over all
// particles on one rank. Density summation rho_a = sum_b m_b W(|r_a - r_b|) (self included), with
// the Wendland C2 kernel, on a jittered lattice, periodic and walled.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "kernels/kernel.hpp"
#include "mpi_test_support.hpp"
#include "parallel/halo.hpp"
#include "parallel/migration.hpp"

using namespace arksph::parallel;
using namespace arksph::parallel::testing;

namespace {

// n x n lattice of spacing 1/n in the unit square, each point moved by up to 0.3 spacing (the same
// on every rank), particle k given to rank k % P to begin with.
ParticleFields jittered_lattice(const Communicator& comm, int n) {
  ParticleFields p(2, N_FIELDS);
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  const double dx = 1.0 / n;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = (i + 0.5 + jitter(rng)) * dx, y = (j + 0.5 + jitter(rng)) * dx;
      const auto id = static_cast<std::uint64_t>(j * n + i);
      if (static_cast<int>(id % static_cast<std::uint64_t>(comm.size())) != comm.rank()) continue;
      p.id.push_back(id);
      p.field[X].push_back(x);
      p.field[Y].push_back(y);
      for (int f = U; f < N_FIELDS; ++f) p.field[static_cast<std::size_t>(f)].push_back(0.0);
      p.field[MASS].back() = dx * dx * (1.0 + 0.1 * static_cast<double>(id % 3));  // unequal masses
    }
  return p;
}

}  // namespace

TEST_CASE("density sum over owned + halo particles equals the one-rank sum over all particles") {
  const Communicator comm;
  const int n = 40;
  const double dx = 1.0 / n;
  const arksph::Kernel kernel = arksph::make_kernel("wendland_quintic", 1.3 * dx, 2);
  const double cutoff = 1.15 * kernel.radius();  // support + skin 0.15 R, as the Verlet candidates
  for (const bool periodic : {true, false}) {
    CAPTURE(periodic);
    const Domain dom = unit_domain(1.0, 1.0, periodic, periodic);
    ParticleFields p = jittered_lattice(comm, n);
    const Decomposition d = decompose(comm, CellGrid(dom, cutoff), p);
    migrate(comm, d, p);
    HaloExchange exchange;
    ParticleFields halo;
    exchange.exchange(comm, d, p, cutoff, halo);

    // P ranks: owned + halo, in storage order.
    const std::size_t n_own = p.size();
    std::vector<double> rho(n_own, 0.0);
    std::vector<int> neighbours(n_own, 0);
    std::int64_t halo_pairs = 0;
    for (std::size_t a = 0; a < n_own; ++a) {
      auto add = [&](double xb, double yb, double mb, bool from_halo) {
        const double r = std::hypot(p.field[X][a] - xb, p.field[Y][a] - yb);
        if (r >= kernel.radius()) return;
        rho[a] += mb * kernel.W(r);
        ++neighbours[a];
        halo_pairs += from_halo ? 1 : 0;
      };
      for (std::size_t b = 0; b < n_own; ++b) add(p.field[X][b], p.field[Y][b], p.field[MASS][b], false);
      for (std::size_t b = 0; b < halo.size(); ++b) add(halo.field[X][b], halo.field[Y][b], halo.field[MASS][b], true);
    }
    // One rank: every particle of every rank, with its periodic images, in id order.
    const std::vector<Record> all = gather_all(comm, p);
    double worst = 0;
    bool same_neighbours = true;
    for (std::size_t a = 0; a < n_own; ++a) {
      double ref = 0;
      int count = 0;
      for (const Record& b : all)
        for (int kx = periodic ? -1 : 0; kx <= (periodic ? 1 : 0); ++kx)
          for (int ky = periodic ? -1 : 0; ky <= (periodic ? 1 : 0); ++ky) {
            const double r = std::hypot(p.field[X][a] - (b.f[X] + kx * 1.0), p.field[Y][a] - (b.f[Y] + ky * 1.0));
            if (r >= kernel.radius()) continue;
            ref += b.f[MASS] * kernel.W(r);
            ++count;
          }
      worst = std::max(worst, std::abs(rho[a] - ref) / ref);
      same_neighbours = same_neighbours && count == neighbours[a];
    }
    CHECK(on_all_ranks(comm, same_neighbours));
    // Round-off of a sum of about 25 positive terms in another order: each ordering is within
    // 25 eps of the exact sum, so the two within 50 eps = 1.1e-14 of each other; a missing
    // neighbour changes rho by m W(R - skin) / rho ~ 1e-4 or more.
    const double tolerance = 1e-13;
    const double worst_all = comm.max(worst);
    CHECK(worst_all <= tolerance);
    const std::int64_t halo_pairs_all = comm.sum(halo_pairs);
    if (comm.size() > 1 || periodic) CHECK(halo_pairs_all > 0);  // the halo is used
    if (comm.rank() == 0)
      MESSAGE("periodic " << periodic << ", " << comm.size() << " ranks: largest relative difference " << worst_all
                          << ", pairs with a halo particle " << halo_pairs_all);
  }
}
