#include "distributed/rank_frame.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>

#include "io/output_fields.hpp"
#include "parallel/join_by_id.hpp"

namespace arksph::distributed {

namespace {
// phase, x, y, u, v, p, rho, rho_sum, m, free_surface (0 where the frame has no such array)
constexpr std::size_t kRowValues = 10;
void row_of(const Frame& f, std::size_t a, double* row) {
  const bool two_d = f.dimension == 2;
  const double values[kRowValues] = {static_cast<double>(f.phase[a]), f.x[a], two_d ? f.y[a] : 0.0, f.u[a],
                                     two_d ? f.v[a] : 0.0, f.pressure[a], f.density[a], f.summation_density[a],
                                     f.mass[a], f.free_surface ? static_cast<double>(f.free_surface[a]) : 0.0};
  std::copy(values, values + kRowValues, row);
}

// Row k of `rows`: particle `id`, the values `w` of row_of.
void store_row(FrameStorage& rows, std::size_t k, std::int64_t id, const double* w) {
  rows.id[k] = id, rows.phase[k] = static_cast<std::int32_t>(w[0]);
  rows.x[k] = w[1], rows.y[k] = w[2], rows.u[k] = w[3], rows.v[k] = w[4];
  rows.pressure[k] = w[5], rows.density[k] = w[6], rows.summation_density[k] = w[7], rows.mass[k] = w[8];
}
}  // namespace

JoinedFrame::Copy::Copy(const Frame& mine) : frame(mine), id(mine.id, mine.id + mine.n), values(mine.n * kRowValues) {
  for (std::size_t a = 0; a < mine.n; ++a) row_of(mine, a, values.data() + a * kRowValues);
  frame.id = id.data();
}

JoinedFrame::JoinedFrame(const parallel::Communicator& comm, const Frame& mine, std::size_t n) {
  join(comm, mine, [&](std::size_t a, double* row) { row_of(mine, a, row); }, n);
}

JoinedFrame::JoinedFrame(const parallel::Communicator& comm, const Copy& mine, std::size_t n) {
  join(comm, mine.frame, [&](std::size_t a, double* row) {
    std::copy_n(mine.values.data() + a * kRowValues, kRowValues, row);
  }, n);
}

template <class Row>
void JoinedFrame::join(const parallel::Communicator& comm, const Frame& mine, Row&& row, std::size_t n) {
  const bool root = comm.rank() == 0;
  if (root) {
    rows_.resize(n, static_cast<std::int32_t>(ParticleKind::fluid));
    if (mine.free_surface) free_surface_.resize(n);
  }
  parallel::join_by_id(comm, mine.id, mine.n, kRowValues, n, 0, row, [&](std::size_t k, const double* w) {
    store_row(rows_, k, static_cast<std::int64_t>(k), w);
    if (mine.free_surface) free_surface_[k] = static_cast<std::uint8_t>(w[9]);
  });
  frame_ = rows_.view(mine.dimension, mine.time, 0.0);  // empty on the other ranks
  frame_.kind = nullptr;                                // every particle fluid
  if (root && mine.free_surface) frame_.free_surface = free_surface_.data();
}

JoinedWalls::JoinedWalls(const parallel::Communicator& comm, const Frame& mine) {
  const std::size_t width = kRowValues + 1;  // the id's bits, then the values
  std::vector<double> records(mine.n * width);
  for (std::size_t a = 0; a < mine.n; ++a) {
    records[a * width] = std::bit_cast<double>(mine.id[a]);
    row_of(mine, a, records.data() + a * width + 1);
  }
  const std::vector<double> all = comm.gatherv(records, 0);  // rank 0's, then rank 1's...
  const std::size_t n = all.size() / width;
  const auto id = [&](std::size_t k) { return std::bit_cast<std::int64_t>(all[k * width]); };
  std::vector<std::size_t> order(n);
  for (std::size_t k = 0; k < n; ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return id(a) < id(b); });
  rows_.resize(n, static_cast<std::int32_t>(ParticleKind::wall));
  for (std::size_t k = 0; k < n; ++k) {
    store_row(rows_, k, id(order[k]), all.data() + order[k] * width + 1);
  }
  frame_ = rows_.view(mine.dimension, mine.time, mine.smoothing_length);  // empty on the other ranks
}

}  // namespace arksph::distributed
