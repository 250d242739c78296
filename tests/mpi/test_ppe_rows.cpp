// The distributed PPE rows (distributed_ppe/ppe_rows.hpp) against the one-process assembly
// (assemble_ppe), row by row by particle, on 1, 2 and 3 ranks: a walled and a periodic 30 x 30 box.
#include <doctest/doctest.h>

#include <stdexcept>
#include <string>

#include "ppe_compare.hpp"

using namespace arksph;
using namespace arksph::parallel;
using namespace arksph::parallel::testing;

namespace {
// Values: the same pair terms in another order. The diagonal sums its ~50 terms in the rank's pair
// order, and a periodic copy's separation is (x + L) - x' instead of x - x' - L: each value differs
// from one process's by a few rounding errors of the diagonal (measured up to 6.2e-16 of it).
constexpr double kValueTolerance = 1e-13;
// Source: the divergence summed over other pair orders, and its mean over the ranks in another order
// (measured up to 1.5e-15 of max |b|).
constexpr double kSourceTolerance = 1e-13;
}  // namespace

TEST_CASE("distributed ppe rows: equal to the one-process matrix, walled and periodic box") {
  const Communicator comm;
  for (const bool periodic : {false, true}) {
    const OneProcessPpe one(ppe_scene(periodic));
    const RankPpe mine(comm, one);
    const RowComparison c = compare_rows(comm, one, mine);
    if (comm.rank() == 0)
      MESSAGE(std::string(periodic ? "periodic" : "walls"), ", ", comm.size(), " ranks: ", c.rows, " rows, ", c.pattern_mismatches,
              " with other columns, largest value difference ", c.max_value_diff, " of the diagonal, source ", c.max_source_diff);
    CHECK(mine.range.total == static_cast<std::int64_t>(one.particles.n));
    CHECK(c.rows == static_cast<std::int64_t>(one.particles.n));
    CHECK(c.pattern_mismatches == 0);
    CHECK(c.max_value_diff <= kValueTolerance);
    CHECK(c.max_source_diff <= kSourceTolerance);
    CHECK(mine.pinned >= 0);
  }
}

// The comparison can fail: a rank that keeps only half its halo copies misses neighbours of its
// particles next to the other ranks' (and next to periodic sides), and those rows differ.
TEST_CASE("distributed ppe rows: a halo cut in half gives other rows") {
  const Communicator comm;
  for (const bool periodic : {false, true}) {
    const OneProcessPpe one(ppe_scene(periodic));
    const RankPpe mine(comm, one, 0.5);
    const std::int64_t halo = comm.sum(static_cast<std::int64_t>(mine.halo.size()));
    if (halo == 0) continue;  // walls on one rank: no halo to cut
    const RowComparison c = compare_rows(comm, one, mine);
    if (comm.rank() == 0)
      MESSAGE(std::string(periodic ? "periodic" : "walls"), ", ", comm.size(), " ranks, half the halo: ",
              c.pattern_mismatches, " of ", c.rows, " rows with other columns");
    CHECK(c.pattern_mismatches > 0);
  }
}

// Bad input stops every rank with an exception, also when only one rank's sizes are wrong.
TEST_CASE("distributed ppe rows: a pinned row outside the rows or a size mismatch on one rank throws on all") {
  const Communicator comm;
  const OneProcessPpe one(ppe_scene(true));
  const RankPpe mine(comm, one);
  const FluidFields& f = mine.rhs->fields();
  const std::vector<double> div = divergence_cummins_rudman(f);
  distributed_ppe::LocalRows rows;
  CHECK_THROWS_AS(distributed_ppe::assemble_rows(comm, f, mine.owned.size(), mine.row_of, mine.range, -1, div, kPpeDt, rows),
                  std::invalid_argument);
  std::vector<distributed_ppe::GlobalRow> short_rows = mine.row_of;
  if (comm.rank() == comm.size() - 1) short_rows.pop_back();
  CHECK_THROWS_AS(distributed_ppe::assemble_rows(comm, f, mine.owned.size(), short_rows, mine.range, mine.pinned, div, kPpeDt, rows),
                  std::invalid_argument);
}

// Rows of given P (a free surface): the rank's rows equal one process's, the given rows' columns
// carried to the source of their neighbours' rows across the rank boundary, with the same
// tolerances (the same sums in another order; the carried values add terms of the same size).
TEST_CASE("distributed ppe rows: with rows of given P, equal to the one-process matrix") {
  const Communicator comm;
  for (const bool periodic : {false, true}) {
    const OneProcessPpe one(ppe_scene(periodic), true);
    const RankPpe mine(comm, one);
    const RowComparison c = compare_rows(comm, one, mine);
    std::int64_t fixed = 0;
    for (char v : one.given.fixed) fixed += v;
    if (comm.rank() == 0)
      MESSAGE(std::string(periodic ? "periodic" : "walls"), ", ", comm.size(), " ranks, ", fixed, " given rows: ", c.rows,
              " rows, ", c.pattern_mismatches, " with other columns, largest value difference ", c.max_value_diff,
              " of the diagonal, source ", c.max_source_diff);
    CHECK(fixed > 0);
    CHECK(fixed < static_cast<std::int64_t>(one.particles.n) / 2);
    CHECK(c.rows == static_cast<std::int64_t>(one.particles.n));
    CHECK(c.pattern_mismatches == 0);
    CHECK(c.max_value_diff <= kValueTolerance);
    CHECK(c.max_source_diff <= kSourceTolerance);
  }
}

// ... and the comparison can fail: halo copies that do not carry their owners' flags leave columns
// of given rows in the rows next to the rank boundary (2 and 3 ranks; one rank has no halo copies
// unless the box is periodic).
TEST_CASE("distributed ppe rows: halo copies without their owners' flags give other rows") {
  const Communicator comm;
  const OneProcessPpe one(ppe_scene(true), true);
  const RankPpe mine(comm, one, 1.0, false);
  const RowComparison c = compare_rows(comm, one, mine);
  if (comm.rank() == 0)
    MESSAGE(comm.size(), " ranks, halo flags dropped: ", c.pattern_mismatches, " of ", c.rows, " rows with other columns");
  CHECK(c.pattern_mismatches > 0);
}
