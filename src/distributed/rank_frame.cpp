#include "distributed/rank_frame.hpp"

#include <algorithm>
#include <stdexcept>

#include "io/frame_order.hpp"
#include "io/output_fields.hpp"
#include "projection/ppe_assembly.hpp"
#include "io/vtp_writer.hpp"

namespace arksph::distributed {

RankFrame::RankFrame(double t, const HaloRhs& f, const RankParticles& mine, const parallel::Domain& domain,
                     const double* pressure, const std::vector<double>& number_density, bool free_surface) {
  const FluidFields& ff = f.evaluator().fields();
  const std::size_t n = mine.size();
  const int dim = mine.index().dim;
  x_.resize(n);
  y_.resize(n);
  for (std::size_t a = 0; a < n; ++a) {
    double p[3] = {ff.x[a], dim == 2 ? ff.y[a] : 0.0, 0.0};
    domain.wrap(p);
    x_[a] = p[0];
    y_[a] = p[1];
  }
  rho_sum_.resize(n);
  for (std::size_t a = 0; a < n; ++a) rho_sum_[a] = ff.m[a] * number_density[a];  // Szewc eq. 21
  const auto& phase_field = mine.fields().field[static_cast<std::size_t>(mine.index().phase())];
  phase_.assign(phase_field.begin(), phase_field.end());
  frame_.dimension = dim;
  frame_.smoothing_length = f.evaluator().kernel().h();
  frame_.n = n;
  frame_.time = t;
  frame_.x = x_.data();
  frame_.y = dim == 2 ? y_.data() : nullptr;
  frame_.u = ff.u.data();
  frame_.v = dim == 2 ? ff.v.data() : nullptr;
  frame_.pressure = pressure ? pressure : ff.p.data();
  frame_.density = ff.rho.data();
  frame_.summation_density = rho_sum_.data();
  frame_.mass = ff.m.data();
  frame_.id = mine.ids().data();
  frame_.phase = phase_.data();
  if (free_surface) {  // the rank's particles come first in the fields, the halo copies after them
    const std::vector<char> s = free_surface_particles(ff, free_surface_threshold(dim));
    free_surface_.assign(s.begin(), s.begin() + static_cast<long>(n));
    frame_.free_surface = free_surface_.data();
  }
}

void RankFrame::write_piece(const std::string& path) const { write_vtp(path, FrameInIdOrder(frame_).frame()); }

namespace {
FrameRow row_of(const Frame& f, std::size_t a) {
  const bool two_d = f.dimension == 2;
  return {f.id[a],      f.phase[a],    f.free_surface ? f.free_surface[a] : 0, f.x[a],
          two_d ? f.y[a] : 0.0, f.u[a], two_d ? f.v[a] : 0.0, f.pressure[a], f.density[a], f.summation_density[a],
          f.mass[a]};
}

// Row k of `rows` from a row sent to rank 0.
void store_row(FrameStorage& rows, std::size_t k, const FrameRow& w) {
  rows.id[k] = w.id, rows.phase[k] = w.phase;
  rows.x[k] = w.x, rows.y[k] = w.y, rows.u[k] = w.u, rows.v[k] = w.v;
  rows.pressure[k] = w.p, rows.density[k] = w.rho, rows.summation_density[k] = w.rho_sum, rows.mass[k] = w.m;
}
}  // namespace

std::vector<FrameRow> frame_rows(const Frame& mine) {
  std::vector<FrameRow> rows(mine.n);
  for (std::size_t a = 0; a < mine.n; ++a) rows[a] = row_of(mine, a);
  return rows;
}

JoinedFrame::JoinedFrame(const parallel::Communicator& comm, const Frame& mine, std::size_t n) {
  join(comm, mine.n, [&](std::size_t a) { return row_of(mine, a); }, mine.dimension, mine.time, n);
  if (mine.free_surface && comm.rank() == 0) frame_.free_surface = free_surface_.data();
}

JoinedFrame::JoinedFrame(const parallel::Communicator& comm, const std::vector<FrameRow>& mine, int dimension,
                         double time, std::size_t n, bool free_surface) {
  join(comm, mine.size(), [&](std::size_t a) { return mine[a]; }, dimension, time, n);
  if (free_surface && comm.rank() == 0) frame_.free_surface = free_surface_.data();
}

template <class Row>
void JoinedFrame::join(const parallel::Communicator& comm, std::size_t count, Row&& row, int dimension, double time,
                       std::size_t n) {
  const bool root = comm.rank() == 0;
  if (root) {
    rows_.resize(n, static_cast<std::int32_t>(ParticleKind::fluid));
    rows_.id.assign(n, -1);
    free_surface_.resize(n);
  }
  const auto rounds = static_cast<std::int64_t>((count + kJoinRows - 1) / kJoinRows);
  const std::int64_t all_rounds = comm.max(rounds);
  std::size_t received = 0;
  std::vector<FrameRow> chunk;
  for (std::int64_t r = 0; r < all_rounds; ++r) {
    const std::size_t first = std::min(count, static_cast<std::size_t>(r) * kJoinRows);
    const std::size_t last = std::min(count, first + kJoinRows);
    chunk.clear();
    for (std::size_t a = first; a < last; ++a) chunk.push_back(row(a));
    const std::vector<FrameRow> all = comm.gatherv(chunk, 0);
    received += all.size();
    for (const FrameRow& w : all) {
      if (w.id < 0 || static_cast<std::size_t>(w.id) >= n)
        throw std::logic_error("joined frame: particle id out of range");
      const auto k = static_cast<std::size_t>(w.id);
      store_row(rows_, k, w);
      free_surface_[k] = static_cast<std::uint8_t>(w.free_surface);
    }
  }
  if (root && received != n) throw std::logic_error("joined frame: the ranks hold another number of particles");
  frame_ = rows_.view(dimension, time, 0.0);  // empty on the other ranks
  frame_.kind = nullptr;                       // every particle fluid
}

JoinedWalls::JoinedWalls(const parallel::Communicator& comm, const Frame& mine) {
  std::vector<FrameRow> all = comm.gatherv(frame_rows(mine), 0);
  std::stable_sort(all.begin(), all.end(), [](const FrameRow& a, const FrameRow& b) { return a.id < b.id; });
  rows_.resize(all.size(), static_cast<std::int32_t>(ParticleKind::wall));
  for (std::size_t k = 0; k < all.size(); ++k) store_row(rows_, k, all[k]);
  frame_ = rows_.view(mine.dimension, mine.time, mine.smoothing_length);  // empty on the other ranks
}

}  // namespace arksph::distributed
