// Halo exchange (src/parallel/halo.hpp) against a brute-force answer from every rank's particles,
// and the halo update.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <tuple>

#include "mpi_test_support.hpp"
#include "parallel/halo.hpp"
#include "parallel/migration.hpp"

using namespace arksph::parallel;
using namespace arksph::parallel::testing;

namespace {

using Copy = std::tuple<std::uint64_t, double, double>;  // id, shifted position

// Every (particle, period shift) within `cutoff` of `box`, this rank's own unshifted particles
// excepted (`is_mine`), from all particles of every rank: the halo this rank must receive.
template <class Mine>
std::vector<Copy> brute_force_halo(const Domain& dom, const Box& box, const std::vector<Record>& all, Mine&& is_mine,
                                   double cutoff) {
  std::vector<Copy> out;
  for (const Record& rec : all) {
    const bool mine = is_mine(rec);
    for (int kx = -1; kx <= 1; ++kx)
      for (int ky = -1; ky <= 1; ++ky) {
        if ((kx != 0 && !dom.periodic[0]) || (ky != 0 && !dom.periodic[1]) || (mine && kx == 0 && ky == 0)) continue;
        const double sx = kx == 0 ? 0.0 : kx * (dom.box.hi[0] - dom.box.lo[0]);
        const double sy = ky == 0 ? 0.0 : ky * (dom.box.hi[1] - dom.box.lo[1]);
        const double x = rec.f[X] + sx, y = rec.f[Y] + sy;
        const double cx = std::clamp(x, box.lo[0], box.hi[0]), cy = std::clamp(y, box.lo[1], box.hi[1]);
        if ((x - cx) * (x - cx) + (y - cy) * (y - cy) < cutoff * cutoff) out.emplace_back(rec.id, x, y);
      }
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<Copy> copies(const ParticleFields& halo) {
  std::vector<Copy> out;
  for (std::size_t k = 0; k < halo.size(); ++k) out.emplace_back(halo.id[k], halo.field[X][k], halo.field[Y][k]);
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

TEST_CASE("halo: equals the brute-force halo from all particles; the update moves the new values") {
  const Communicator comm;
  struct Setup {
    bool px, py;
    double lx, ly, cutoff;
  };
  // The last: a domain one cell high, periodic: every box spans it, so self-images along y.
  for (const Setup s : {Setup{true, true, 3.0, 2.0, 0.25}, Setup{false, false, 3.0, 2.0, 0.25},
                        Setup{true, false, 3.0, 2.0, 0.35}, Setup{true, true, 3.0, 0.3, 0.2}}) {
    CAPTURE(s.px);
    CAPTURE(s.py);
    CAPTURE(s.ly);
    const Domain dom = unit_domain(s.lx, s.ly, s.px, s.py);
    ParticleFields p = random_particles(comm, dom, 600 + 100 * static_cast<std::size_t>(comm.rank()), 21);
    const Decomposition d = decompose(comm, CellGrid(dom, s.cutoff), p);
    migrate(comm, d, p);
    HaloExchange exchange;
    ParticleFields halo;
    exchange.exchange(comm, d, p, s.cutoff, halo);

    // (b) the halo as a set of (id, shifted position)
    const std::vector<Record> all = gather_all(comm, p);
    const auto owned_here = [&](const Record& r) {
      const double x0[2] = {r.f[X], r.f[Y]};
      return d.owner(x0) == comm.rank();
    };
    const std::vector<Copy> expected = brute_force_halo(dom, d.box(comm.rank()), all, owned_here, s.cutoff);
    const std::vector<Copy> got = copies(halo);
    CHECK(got.size() == expected.size());
    CHECK(on_all_ranks(comm, got == expected));
    CHECK(halo.size() == exchange.received());
    CHECK(comm.sum(static_cast<std::int64_t>(exchange.sent())) == comm.sum(static_cast<std::int64_t>(exchange.received())));
    if (comm.size() > 1 || s.px || s.py) CHECK(comm.sum(static_cast<std::int64_t>(halo.size())) > 0);
    bool fields_ok = true;
    for (std::size_t k = 0; k < halo.size(); ++k)
      for (int f = U; f < N_FIELDS; ++f) fields_ok = fields_ok && halo.field[static_cast<std::size_t>(f)][k] == value_of(halo.id[k], f, 0);
    CHECK(on_all_ranks(comm, fields_ok));

    // (c) update: new densities and positions (each particle moved by a small id-dependent step,
    // no migration); the velocities are not in the list and must keep their old values.
    const ParticleFields old_halo = halo;
    std::vector<double> old_x = p.field[X], old_y = p.field[Y];
    for (std::size_t i = 0; i < p.size(); ++i) {
      p.field[X][i] += 1e-3 * static_cast<double>(p.id[i] % 7);
      p.field[Y][i] -= 1e-3 * static_cast<double>(p.id[i] % 5);
      p.field[RHO][i] = value_of(p.id[i], RHO, 1);
      p.field[U][i] = value_of(p.id[i], U, 1);
    }
    exchange.update(comm, p, {X, Y, RHO}, halo);
    const std::vector<Record> moved = gather_all(comm, p);
    auto find = [&](std::uint64_t id) {
      return *std::lower_bound(moved.begin(), moved.end(), id, [](const Record& r, std::uint64_t v) { return r.id < v; });
    };
    auto find_old = [&](std::uint64_t id) {
      return *std::lower_bound(all.begin(), all.end(), id, [](const Record& r, std::uint64_t v) { return r.id < v; });
    };
    bool update_ok = halo.size() == old_halo.size();
    for (std::size_t k = 0; update_ok && k < halo.size(); ++k) {
      const Record now = find(halo.id[k]), before = find_old(halo.id[k]);
      // The shift of this copy, a whole number of periods (0 on the wall axes).
      const double sx = old_halo.field[X][k] - before.f[X], sy = old_halo.field[Y][k] - before.f[Y];
      const double kx = std::round(sx / dom.period(0)), ky = std::round(sy / dom.period(1));
      const double ex = now.f[X] + (kx == 0 ? 0.0 : kx * dom.period(0));
      const double ey = now.f[Y] + (ky == 0 ? 0.0 : ky * dom.period(1));
      update_ok = halo.id[k] == old_halo.id[k] && halo.field[X][k] == ex && halo.field[Y][k] == ey &&
                  halo.field[RHO][k] == value_of(halo.id[k], RHO, 1) && halo.field[U][k] == value_of(halo.id[k], U, 0);
    }
    CHECK(on_all_ranks(comm, update_ok));

    // (d) update_max: the same values into the same slots, and the largest of each rank's number
    // (here 10 + rank, so the last rank's) on every rank; a halo of another size is refused.
    ParticleFields again = old_halo;
    const double largest = exchange.update_max(comm, p, {X, Y, RHO}, again, 10.0 + comm.rank());
    CHECK(largest == 10.0 + (comm.size() - 1));
    bool same = true;
    for (int f : {X, Y, RHO, U})
      same = same && again.field[static_cast<std::size_t>(f)] == halo.field[static_cast<std::size_t>(f)];
    CHECK(on_all_ranks(comm, same));
    ParticleFields wrong = old_halo;
    wrong.resize(old_halo.size() + 1);
    CHECK_THROWS_AS(exchange.update_max(comm, p, {X}, wrong, 0.0), std::invalid_argument);
  }
}

TEST_CASE("halo: with each rank's block grown around particles that left it, equals the brute-force halo") {
  // A decomposed run between migrations (distributed/halo_rhs.hpp): the particles have drifted up
  // to 0.3 out of their blocks (more than the cut-off), still held by the same ranks.
  const Communicator comm;
  for (const bool periodic : {true, false}) {
    CAPTURE(periodic);
    const Domain dom = unit_domain(3.0, 2.0, periodic, periodic);
    ParticleFields p = random_particles(comm, dom, 500 + 50 * static_cast<std::size_t>(comm.rank()), 33);
    const double cutoff = 0.25;
    const Decomposition d = decompose(comm, CellGrid(dom, cutoff), p);
    migrate(comm, d, p);
    Box grown = d.box(comm.rank());
    for (std::size_t i = 0; i < p.size(); ++i) {
      const std::uint64_t h = mix(p.id[i]);
      double x[2] = {p.field[X][i] + 0.3 * (static_cast<double>(h % 1001) / 500.0 - 1.0),
                     p.field[Y][i] + 0.3 * (static_cast<double>((h >> 20) % 1001) / 500.0 - 1.0)};
      dom.wrap(x);  // on the wall axes the drift stays inside the box
      for (int a = 0; a < 2; ++a) {
        x[a] = std::clamp(x[a], dom.box.lo[a], std::nextafter(dom.box.hi[a], dom.box.lo[a]));
        p.field[static_cast<std::size_t>(a)][i] = x[a];
        grown.lo[a] = std::min(grown.lo[a], x[a]);
        grown.hi[a] = std::max(grown.hi[a], x[a]);
      }
    }
    const std::vector<Box> boxes = comm.allgatherv(std::vector<Box>{grown});
    HaloExchange exchange;
    ParticleFields halo;
    exchange.exchange(comm, dom, boxes, p, cutoff, halo);
    std::vector<std::uint64_t> mine(p.id);
    std::sort(mine.begin(), mine.end());
    const auto held_here = [&](const Record& r) { return std::binary_search(mine.begin(), mine.end(), r.id); };
    const std::vector<Copy> expected = brute_force_halo(dom, grown, gather_all(comm, p), held_here, cutoff);
    CHECK(on_all_ranks(comm, copies(halo) == expected));
    if (comm.size() > 1 || periodic) CHECK(comm.sum(static_cast<std::int64_t>(halo.size())) > 0);
  }
}

TEST_CASE("halo: a cut-off as long as a period is refused") {
  const Communicator comm;
  const Domain dom = unit_domain(3.0, 0.3, true, true);
  ParticleFields p = random_particles(comm, dom, 50, 2);
  const Decomposition d = decompose(comm, CellGrid(dom, 0.1), p);
  migrate(comm, d, p);
  HaloExchange exchange;
  ParticleFields halo;
  CHECK_THROWS_AS(exchange.exchange(comm, d, p, 0.3, halo), std::invalid_argument);
}
