#include "distributed/rank_frame.hpp"

#include <stdexcept>

#include "io/frame_order.hpp"
#include "io/vtp_writer.hpp"

namespace arksph::distributed {

RankFrame::RankFrame(double t, const HaloRhs& f, const RankParticles& mine, const parallel::Domain& domain,
                     const double* pressure, const std::vector<double>& number_density) {
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
}

void RankFrame::write_piece(const std::string& path) const { write_vtp(path, FrameInIdOrder(frame_).frame()); }

std::vector<FrameRow> frame_rows(const Frame& mine) {
  const bool two_d = mine.dimension == 2;
  std::vector<FrameRow> rows(mine.n);
  for (std::size_t a = 0; a < mine.n; ++a)
    rows[a] = {mine.id[a],          mine.phase[a],   0,
               mine.x[a],           two_d ? mine.y[a] : 0.0,
               mine.u[a],           two_d ? mine.v[a] : 0.0,
               mine.pressure[a],    mine.density[a],
               mine.summation_density[a], mine.mass[a]};
  return rows;
}

JoinedFrame::JoinedFrame(const parallel::Communicator& comm, const std::vector<FrameRow>& mine, int dimension,
                         double time, std::size_t n) {
  const bool two_d = dimension == 2;
  const std::vector<FrameRow> all = comm.gatherv(mine, 0);
  frame_.dimension = dimension;
  frame_.time = time;
  if (comm.rank() != 0) return;
  if (all.size() != n) throw std::logic_error("joined frame: the ranks hold another number of particles");
  for (auto* v : {&x_, &y_, &u_, &v_, &p_, &rho_, &rho_sum_, &m_}) v->resize(n);
  id_.resize(n);
  phase_.resize(n);
  for (const FrameRow& r : all) {
    if (r.id < 0 || static_cast<std::size_t>(r.id) >= n) throw std::logic_error("joined frame: particle id out of range");
    const auto k = static_cast<std::size_t>(r.id);
    id_[k] = r.id;
    phase_[k] = r.phase;
    x_[k] = r.x;
    y_[k] = r.y;
    u_[k] = r.u;
    v_[k] = r.v;
    p_[k] = r.p;
    rho_[k] = r.rho;
    rho_sum_[k] = r.rho_sum;
    m_[k] = r.m;
  }
  frame_.n = n;
  frame_.x = x_.data();
  frame_.y = two_d ? y_.data() : nullptr;
  frame_.u = u_.data();
  frame_.v = two_d ? v_.data() : nullptr;
  frame_.pressure = p_.data();
  frame_.density = rho_.data();
  frame_.summation_density = rho_sum_.data();
  frame_.mass = m_.data();
  frame_.id = id_.data();
  frame_.phase = phase_.data();
}

}  // namespace arksph::distributed
