// Migration (src/parallel/migration.hpp): afterwards every particle sits on the rank whose box holds
// it, inside the domain, with its fields, and none is lost or duplicated.
#include <doctest/doctest.h>

#include <random>

#include "mpi_test_support.hpp"
#include "parallel/migration.hpp"

using namespace arksph::parallel;
using namespace arksph::parallel::testing;

namespace {

struct Census {
  std::int64_t count = 0;
  std::uint64_t checksum = 0;  // sum of mix(id) modulo 2^64
};

Census census(const Communicator& comm, const ParticleFields& p) {
  std::uint64_t h = 0;
  for (auto id : p.id) h += mix(id);
  return {comm.sum(static_cast<std::int64_t>(p.size())), comm.sum(h)};
}

// Every particle of this rank is in the domain and in this rank's box, owned by this rank, and
// carries the field values of its id.
bool all_placed(const Communicator& comm, const Decomposition& d, const ParticleFields& p, const Domain& dom) {
  const Box box = d.box(comm.rank());
  double x[3] = {0, 0, 0};
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.position(i, x);
    if (!dom.box.contains(x, 2) || !box.contains(x, 2) || d.owner(x) != comm.rank()) return false;
    for (int f = U; f < N_FIELDS; ++f)
      if (p.field[static_cast<std::size_t>(f)][i] != value_of(p.id[i], f, 0)) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("migration: each particle on the rank whose box holds it, none lost or duplicated") {
  const Communicator comm;
  struct Setup {
    bool px, py;
    double spill;  // beyond the periodic sides only
  };
  for (const Setup s : {Setup{true, true, 0.4}, Setup{false, false, 0.0}, Setup{true, false, 0.0}}) {
    CAPTURE(s.px);
    CAPTURE(s.py);
    const Domain dom = unit_domain(3.0, 2.0, s.px, s.py);
    const std::size_t n = 400 + 150 * static_cast<std::size_t>(comm.rank());
    ParticleFields p = random_particles(comm, dom, n, 11);
    if (s.spill > 0) {  // push some particles beyond the periodic sides (up to a period and a half away)
      std::mt19937_64 rng(99 + static_cast<unsigned>(comm.rank()));
      std::uniform_real_distribution<double> u(-1.5, 1.5);
      for (std::size_t i = 0; i < n; i += 3) p.field[X][i] += u(rng) * dom.period(0), p.field[Y][i] += u(rng) * dom.period(1);
    }
    const Census before = census(comm, p);
    const Decomposition d = decompose(comm, CellGrid(dom, 0.2), p);
    const MigrationCounts moved = migrate(comm, d, p);
    CHECK(comm.sum(static_cast<std::int64_t>(moved.sent)) == comm.sum(static_cast<std::int64_t>(moved.received)));
    if (comm.size() > 1) CHECK(comm.sum(static_cast<std::int64_t>(moved.sent)) > 0);
    CHECK(on_all_ranks(comm, all_placed(comm, d, p, dom)));
    const Census after = census(comm, p);
    CHECK(after.count == before.count);
    CHECK(after.checksum == before.checksum);
    // The exact set: rank r's ids r * n_r + i, i < n_r, each once.
    const std::vector<Record> all = gather_all(comm, p);
    std::vector<std::uint64_t> expected;
    for (int r = 0; r < comm.size(); ++r)
      for (std::size_t i = 0; i < 400 + 150 * static_cast<std::size_t>(r); ++i)
        expected.push_back(static_cast<std::uint64_t>(r) * (400 + 150 * static_cast<std::size_t>(r)) + i);
    std::sort(expected.begin(), expected.end());
    std::vector<std::uint64_t> got;
    for (const Record& rec : all) got.push_back(rec.id);
    CHECK(got == expected);

    // Move every particle by up to 0.3 (a cell and a half) and migrate again with the same boxes.
    std::mt19937_64 rng(5 + static_cast<unsigned>(comm.rank()));
    std::uniform_real_distribution<double> step(-0.3, 0.3);
    for (std::size_t i = 0; i < p.size(); ++i) {
      for (int a = 0; a < 2; ++a) {
        double& x = p.field[static_cast<std::size_t>(a)][i];
        x += step(rng);
        if (!dom.periodic[static_cast<std::size_t>(a)])  // stay inside the walls
          x = std::clamp(x, dom.box.lo[static_cast<std::size_t>(a)], std::nextafter(dom.box.hi[static_cast<std::size_t>(a)], 0.0));
      }
    }
    migrate(comm, d, p);
    CHECK(on_all_ranks(comm, all_placed(comm, d, p, dom)));
    const Census again = census(comm, p);
    CHECK(again.count == before.count);
    CHECK(again.checksum == before.checksum);
  }
}

TEST_CASE("migration: wrap brings far points into the periodic box") {
  const Domain dom = unit_domain(3.0, 2.0, true, false);
  for (double x0 : {-7.5, -3.0, -1e-17, 0.0, 2.999, 3.0, 4.5, 10.25}) {
    CAPTURE(x0);
    double x[2] = {x0, 5.0};
    dom.wrap(x);
    CHECK(x[0] >= 0.0);
    CHECK(x[0] < 3.0);
    CHECK(std::abs(std::remainder(x[0] - x0, 3.0)) < 1e-12);  // a whole number of periods (round-off)
    CHECK(x[1] == 5.0);  // a wall axis is left alone
  }
}
