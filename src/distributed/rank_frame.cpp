#include "distributed/rank_frame.hpp"

#include <algorithm>

#include "parallel/join_by_id.hpp"

namespace arksph::distributed {

namespace {
constexpr std::size_t kRowValues = 9;  // phase, x, y, u, v, p, rho, rho_sum, m
void row_of(const Frame& f, std::size_t a, double* row) {
  const bool two_d = f.dimension == 2;
  const double values[kRowValues] = {static_cast<double>(f.phase[a]), f.x[a], two_d ? f.y[a] : 0.0, f.u[a],
                                     two_d ? f.v[a] : 0.0, f.pressure[a], f.density[a], f.summation_density[a],
                                     f.mass[a]};
  std::copy(values, values + kRowValues, row);
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
  const bool two_d = mine.dimension == 2;
  frame_.dimension = mine.dimension;
  frame_.time = mine.time;
  if (root) {
    for (auto* v : {&x_, &y_, &u_, &v_, &p_, &rho_, &rho_sum_, &m_}) v->resize(n);
    id_.assign(n, -1);
    phase_.resize(n);
  }
  parallel::join_by_id(comm, mine.id, mine.n, kRowValues, n, 0, row, [&](std::size_t k, const double* w) {
    id_[k] = static_cast<std::int64_t>(k);
    phase_[k] = static_cast<std::int32_t>(w[0]);
    x_[k] = w[1];
    y_[k] = w[2];
    u_[k] = w[3];
    v_[k] = w[4];
    p_[k] = w[5];
    rho_[k] = w[6];
    rho_sum_[k] = w[7];
    m_[k] = w[8];
  });
  if (!root) return;
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
