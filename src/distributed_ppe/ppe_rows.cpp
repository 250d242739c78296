#include "distributed_ppe/ppe_rows.hpp"

#include <stdexcept>
#include <string>

#include "projection/ppe_row.hpp"

namespace arksph::distributed_ppe {

RowRange global_rows(const parallel::Communicator& comm, std::size_t n_owned) {
  const std::vector<std::int64_t> counts = comm.allgatherv(std::vector<std::int64_t>{static_cast<std::int64_t>(n_owned)});
  RowRange r;
  for (int q = 0; q < comm.size(); ++q) {
    if (q < comm.rank()) r.first += counts[static_cast<std::size_t>(q)];
    r.total += counts[static_cast<std::size_t>(q)];
  }
  return r;
}

GlobalRow row_of_id(const parallel::Communicator& comm, const std::vector<std::int64_t>& owned_ids,
                    const RowRange& range, std::int64_t id) {
  std::int64_t found = -1;
  for (std::size_t i = 0; i < owned_ids.size(); ++i)
    if (owned_ids[i] == id) found = range.first + static_cast<std::int64_t>(i);
  return comm.max(found);
}

namespace {
// A column of a row: the unknown's global row, and the local point it was found through (to look
// up a given P). Two columns are the same unknown when their rows are.
struct Column {
  GlobalRow row;
  std::uint32_t point;
  bool operator==(const Column& o) const { return row == o.row; }
};
}  // namespace

void assemble_rows(const parallel::Communicator& comm, const FluidFields& f, std::size_t n_owned,
                   const std::vector<GlobalRow>& row_of, const RowRange& range, GlobalRow pinned_row,
                   const std::vector<double>& divergence, double dt, LocalRows& out, const DirichletRows& given) {
  const bool neumann = given.empty();
  // Checked on every rank together, so that a mismatch on one rank stops all (no rank left waiting).
  const bool sizes_match = n_owned <= f.n_real && row_of.size() >= f.n_real && divergence.size() >= n_owned &&
                           (neumann || (given.fixed.size() >= f.n_real && given.value.size() >= f.n_real));
  if (comm.sum(static_cast<std::int64_t>(sizes_match ? 0 : 1)) > 0)
    throw std::invalid_argument(!sizes_match ? "distributed PPE: " + std::to_string(n_owned) + " owned particles, " +
                                std::to_string(f.n_real) + " real points, " + std::to_string(row_of.size()) +
                                " rows, " + std::to_string(divergence.size()) + " divergences and " +
                                std::to_string(given.fixed.size()) + " given flags do not match"
                                                  : std::string("distributed PPE: sizes do not match on another rank"));
  if (neumann && (pinned_row < 0 || pinned_row >= range.total))
    throw std::invalid_argument("distributed PPE: pinned row " + std::to_string(pinned_row) + " is not one of the " +
                                std::to_string(range.total) + " rows (no rank owns the pinned particle)");
  if (!neumann) pinned_row = -1;  // the given rows fix the level
  out.range = range;
  // Source: zero mean over all ranks' particles (Neumann only), scaled like the rows (assemble_ppe).
  double mean = 0;
  if (neumann) {
    double local = 0;
    for (std::size_t a = 0; a < n_owned; ++a) local += divergence[a];
    mean = comm.sum(local) / static_cast<double>(range.total);
  }
  out.b.resize(n_owned);
  for (std::size_t a = 0; a < n_owned; ++a) {
    out.b[a] = row_of[a] == pinned_row ? 0.0 : -(f.m[a] / f.rho[a]) * (divergence[a] - mean) / dt;
  }
  // Rows: room for the pairs plus the diagonal, filled, sorted and merged per row, then closed up.
  out.start.assign(n_owned + 1, 0);
  for (std::size_t a = 0; a < n_owned; ++a) out.start[a + 1] = out.start[a] + static_cast<int>(f.pairs.count[a]) + 1;
  out.col.resize(static_cast<std::size_t>(out.start[n_owned]));
  out.val.resize(out.col.size());
  const double eta2 = ppe_eta2(f);
  const auto column = [&](std::uint32_t s) { return Column{row_of[s], s}; };
  std::size_t end = 0;
  for (std::size_t a = 0; a < n_owned; ++a) {
    GlobalRow* col = out.col.data() + out.start[a];
    double* val = out.val.data() + out.start[a];
    const bool fixed_row = row_of[a] == pinned_row || (!neumann && given.fixed[a]);
    double moved = 0;  // given P of the columns dropped, carried to the source
    int len = 0;
    const double diag = ppe_row(f, a, eta2, column, [&](Column c, double v) {
      if (fixed_row || c.row == pinned_row) return;
      if (!neumann && given.fixed[c.point]) {
        moved += v * given.value[c.point];
        return;
      }
      col[len] = c.row;
      val[len++] = v;
    });
    col[len] = row_of[a];
    val[len++] = close_row(row_of[a] == pinned_row, fixed_row, diag, neumann ? 0.0 : given.value[a], moved, out.b[a]);
    const int m = sort_merge_row(col, val, len);
    // Close up: row a moves to `end` (end <= its start).
    const std::size_t from = static_cast<std::size_t>(out.start[a]);
    for (int k = 0; k < m; ++k) {
      out.col[end + static_cast<std::size_t>(k)] = out.col[from + static_cast<std::size_t>(k)];
      out.val[end + static_cast<std::size_t>(k)] = out.val[from + static_cast<std::size_t>(k)];
    }
    out.start[a] = static_cast<int>(end);
    end += static_cast<std::size_t>(m);
  }
  out.start[n_owned] = static_cast<int>(end);
  out.col.resize(end);
  out.val.resize(end);
}

}  // namespace arksph::distributed_ppe
