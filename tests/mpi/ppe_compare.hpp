// Brute-force comparison of a rank's distributed PPE rows with the one-process matrix, by the
// particles' one-process indices (ppe_fixture.hpp).
#pragma once
#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <utility>
#include <vector>

#include "ppe_fixture.hpp"

namespace arksph::parallel::testing {

struct RowComparison {
  std::int64_t rows = 0;               // rows compared, over all ranks
  std::int64_t pattern_mismatches = 0; // rows whose set of columns differs, over all ranks
  double max_value_diff = 0;           // largest |A_ij - A'_ij| / |A_ii| over all ranks
  double max_source_diff = 0;          // largest |b_i - b'_i| / max |b|
};

// Collective.
inline RowComparison compare_rows(const Communicator& comm, const OneProcessPpe& one, const RankPpe& mine) {
  std::unordered_map<distributed_ppe::GlobalRow, std::size_t> index_of_row;
  for (std::size_t s = 0; s < mine.row_of.size(); ++s) index_of_row[mine.row_of[s]] = mine.index_of[s];
  double bmax = 0;
  for (double v : one.sys.b) bmax = std::max(bmax, std::abs(v));
  RowComparison c;
  const distributed_ppe::LocalRows& rows = mine.rows;
  for (std::size_t a = 0; a < rows.size(); ++a) {
    const long i = static_cast<long>(mine.index_of[a]);
    std::vector<std::pair<long, double>> ref, got;
    double diag = 0;
    for (SparseMatrix::InnerIterator it(one.sys.A, i); it; ++it) {  // column i of A^T = row i
      ref.emplace_back(it.index(), it.value());
      if (it.index() == i) diag = std::abs(it.value());
    }
    for (int k = rows.start[a]; k < rows.start[a + 1]; ++k) {
      const auto at = index_of_row.find(rows.col[static_cast<std::size_t>(k)]);
      got.emplace_back(at == index_of_row.end() ? -1L : static_cast<long>(at->second), rows.val[static_cast<std::size_t>(k)]);
    }
    std::sort(got.begin(), got.end());
    bool same = ref.size() == got.size() && diag > 0;
    for (std::size_t k = 0; same && k < ref.size(); ++k) {
      same = ref[k].first == got[k].first;
      if (same) c.max_value_diff = std::max(c.max_value_diff, std::abs(ref[k].second - got[k].second) / diag);
    }
    c.pattern_mismatches += same ? 0 : 1;
    c.max_source_diff = std::max(c.max_source_diff, std::abs(one.sys.b[static_cast<std::size_t>(i)] - rows.b[a]) / bmax);
    ++c.rows;
  }
  c.rows = comm.sum(c.rows);
  c.pattern_mismatches = comm.sum(c.pattern_mismatches);
  c.max_value_diff = comm.max(c.max_value_diff);
  c.max_source_diff = comm.max(c.max_source_diff);
  return c;
}

// Every rank's values by one-process index (x: the rank's owned values), on every rank.
inline std::vector<double> by_index(const Communicator& comm, const OneProcessPpe& one, const RankPpe& mine,
                                    const std::vector<double>& x) {
  std::vector<double> all(one.particles.n, 0.0);
  for (std::size_t a = 0; a < x.size(); ++a) all[mine.index_of[a]] = x[a];
  comm.sum_in_place(all);
  return all;
}

}  // namespace arksph::parallel::testing
