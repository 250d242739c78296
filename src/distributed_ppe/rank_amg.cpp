// The smoothed-aggregation V-cycle over ranks (sources and the distribution in rank_amg.hpp).
#include "distributed_ppe/rank_amg.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "core/errors.hpp"

namespace arksph::distributed_ppe {

namespace {

// Every rank's first index, then the total.
std::vector<std::int64_t> block_offsets(const parallel::Communicator& comm, int n) {
  const std::vector<std::int64_t> counts = comm.allgatherv(std::vector<std::int64_t>{n});
  std::vector<std::int64_t> offsets(counts.size() + 1, 0);
  for (std::size_t q = 0; q < counts.size(); ++q)
    offsets[q + 1] = offsets[q] + counts[q];
  return offsets;
}

// 1 / a_ii of the rank's rows, or NumericalFailure on every rank when any rank has a diagonal that
// is not positive (thrown together, so that no rank is left waiting in the next collective).
std::vector<double> inverse_diagonal_everywhere(const parallel::Communicator& comm, const CsrRef& A) {
  std::vector<double> d;
  std::string failure;
  try {
    d = csr_inverse_diagonal(A);
  } catch (const NumericalFailure& e) {
    failure = e.what();
  }
  if (comm.max(static_cast<std::int64_t>(failure.empty() ? 0 : 1)) > 0)
    throw NumericalFailure(failure.empty() ? "cg_amg over ranks: matrix diagonal not positive on another rank"
                                           : failure);
  return d;
}

// The global index of a level's local column.
std::int64_t global_of(const GhostExchange& halo, std::int64_t first, int local) {
  return local < halo.own() ? first + local : halo.ghost_globals()[static_cast<std::size_t>(local - halo.own())];
}

// Merges repeated columns of a row of few distinct columns (a prolongator row: the aggregates of a
// row's neighbours) by a linear search, then sorts the distinct ones.
void merge_small_row(std::vector<std::pair<std::int64_t, double>>& row) {
  std::size_t m = 0;
  for (std::size_t k = 0; k < row.size(); ++k) {
    std::size_t j = 0;
    while (j < m && row[j].first != row[k].first)
      ++j;
    if (j < m)
      row[j].second += row[k].second;
    else
      row[m++] = row[k];
  }
  row.resize(m);
  std::sort(row.begin(), row.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
}

// Sorts a row's (column, value) pairs by column and merges repeated columns.
template <class Col>
void merge_row(std::vector<std::pair<Col, double>>& row) {
  std::sort(row.begin(), row.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::size_t m = 0;
  for (std::size_t k = 0; k < row.size(); ++k) {
    if (m > 0 && row[m - 1].first == row[k].first)
      row[m - 1].second += row[k].second;
    else
      row[m++] = row[k];
  }
  row.resize(m);
}

struct Entry {  // one entry of a coarse row sent to the row's owner
  std::int64_t row, col;
  double val;
};

}  // namespace

double RankAmg::spectral_radius(int l) const {
  const CsrRef A = op(l);
  const GhostExchange& h = halo(l);
  const std::int64_t first = offsets(l)[static_cast<std::size_t>(comm_.rank())];
  std::vector<double> x(static_cast<std::size_t>(A.n + h.ghosts())), y(static_cast<std::size_t>(A.n));
  for (int i = 0; i < A.n; ++i) {  // a start fixed by the global index: the same on any rank count
    unsigned state = static_cast<unsigned>(first + i) * 2654435761u + 12345u;
    state = state * 1664525u + 1013904223u;
    x[static_cast<std::size_t>(i)] = 0.5 + static_cast<double>(state >> 8) / static_cast<double>(1u << 24);
  }
  double est = 0;
  for (int it = 0; it < 15; ++it) {
    h.forward(x.data());
    csr_multiply(A, x.data(), y.data());
    std::vector<double> norms{0.0, 0.0};
    for (int i = 0; i < A.n; ++i) {
      y[static_cast<std::size_t>(i)] *= inv_diag_[static_cast<std::size_t>(l)][static_cast<std::size_t>(i)];
      norms[0] += y[static_cast<std::size_t>(i)] * y[static_cast<std::size_t>(i)];
      norms[1] += x[static_cast<std::size_t>(i)] * x[static_cast<std::size_t>(i)];
    }
    comm_.sum_in_place(norms);
    if (!(norms[0] > 0))
      return est;
    est = std::sqrt(norms[0] / norms[1]);
    const double s = 1.0 / std::sqrt(norms[0]);
    for (int i = 0; i < A.n; ++i)
      x[static_cast<std::size_t>(i)] = y[static_cast<std::size_t>(i)] * s;
  }
  return est;
}

void RankAmg::setup(const CsrRef& A, const GhostExchange& h) {
  A0_ = A;
  halo0_ = &h;
  offsets0_ = block_offsets(comm_, A.n);
  coarse_.clear();
  prolong_.clear();
  restrict_.clear();
  inv_diag_.clear();
  rho_.clear();
  while (levels() < opt_.max_levels && global_size(levels() - 1) > opt_.max_coarse) {
    const int l = levels() - 1;
    const CsrRef Al = op(l);
    inv_diag_.push_back(inverse_diagonal_everywhere(comm_, Al));
    rho_.push_back(spectral_radius(l));
    std::vector<int> agg;  // over the rank's own rows: aggregate() leaves the halo's columns out
    double theta = opt_.theta * std::pow(opt_.theta_decay, l);
    const double n = static_cast<double>(global_size(l));
    int nc = aggregate(Al, theta, agg);
    double total = comm_.sum(static_cast<double>(nc));
    for (int retry = 0; retry < 4 && total > 0.5 * n; ++retry) {  // as one process: halve theta while coarsening stalls
      nc = aggregate(Al, theta *= 0.5, agg);
      total = comm_.sum(static_cast<double>(nc));
    }
    if (total > 0.9 * n) {  // coarsening stalled: solve this level directly
      inv_diag_.pop_back();
      rho_.pop_back();
      break;
    }
    build_level(l, agg, nc);
  }
  finish();
}

void RankAmg::rebind_finest(const CsrRef& A, const GhostExchange& h) {
  if (A.n != A0_.n)
    throw std::logic_error("RankAmg::rebind_finest: the rank's rows changed");
  A0_ = A;
  halo0_ = &h;
  if (levels() > 1)
    inv_diag_[0] = inverse_diagonal_everywhere(comm_, A);
  size_work(0);
  if (levels() == 1)
    finish();  // the finest level is the coarsest: factorise the new matrix
}

void RankAmg::build_level(int l, const std::vector<int>& agg, int nc) {
  const CsrRef A = op(l);
  const GhostExchange& h = halo(l);
  const int n = A.n, me = comm_.rank();
  const std::vector<std::int64_t> offc = block_offsets(comm_, nc);
  const std::int64_t firstc = offc[static_cast<std::size_t>(me)];
  // The aggregates of the level's ghosts, by their owners.
  std::vector<double> agg_of(static_cast<std::size_t>(n + h.ghosts()));
  for (int i = 0; i < n; ++i)
    agg_of[static_cast<std::size_t>(i)] = static_cast<double>(firstc + agg[static_cast<std::size_t>(i)]);
  h.forward(agg_of.data());
  // Smoothed prolongator rows, global coarse columns (compressed rows).
  const double omega = opt_.smoothed ? opt_.omega_scale / rho_[static_cast<std::size_t>(l)] : 0.0;
  std::vector<int> pptr(static_cast<std::size_t>(n) + 1, 0);
  std::vector<std::int64_t> pcol;
  std::vector<double> pval;
  pcol.reserve(static_cast<std::size_t>(A.ptr[n]));
  pval.reserve(pcol.capacity());
  std::vector<std::pair<std::int64_t, double>> row;
  for (int i = 0; i < n; ++i) {
    row.clear();
    row.emplace_back(firstc + agg[static_cast<std::size_t>(i)], 1.0);
    const double w = omega * inv_diag_[static_cast<std::size_t>(l)][static_cast<std::size_t>(i)];
    if (w != 0)
      for (int k = A.ptr[i]; k < A.ptr[i + 1]; ++k)
        row.emplace_back(static_cast<std::int64_t>(agg_of[static_cast<std::size_t>(A.col[k])]), -w * A.val[k]);
    merge_small_row(row);
    for (const auto& [c, v] : row) {
      pcol.push_back(c);
      pval.push_back(v);
    }
    pptr[static_cast<std::size_t>(i) + 1] = static_cast<int>(pcol.size());
  }
  // The rows of P at the ghosts, from their owners.
  std::vector<int> gstart;
  std::vector<double> gdata;
  h.forward_rows(
      [&](int i, std::vector<double>& out) {
        for (int k = pptr[static_cast<std::size_t>(i)]; k < pptr[static_cast<std::size_t>(i) + 1]; ++k) {
          out.push_back(static_cast<double>(pcol[static_cast<std::size_t>(k)]));
          out.push_back(pval[static_cast<std::size_t>(k)]);
        }
      },
      gstart, gdata);
  // Coarse columns in a local numbering: this rank's aggregates, then the others' met (sorted).
  std::vector<std::int64_t> foreign;
  const auto is_own = [&](std::int64_t c) { return c >= firstc && c < firstc + nc; };
  for (std::int64_t c : pcol)
    if (!is_own(c))
      foreign.push_back(c);
  for (std::size_t k = 0; k < gdata.size(); k += 2)
    if (!is_own(static_cast<std::int64_t>(gdata[k])))
      foreign.push_back(static_cast<std::int64_t>(gdata[k]));
  std::sort(foreign.begin(), foreign.end());
  foreign.erase(std::unique(foreign.begin(), foreign.end()), foreign.end());
  const int next = nc + static_cast<int>(foreign.size());
  const auto local_c = [&](std::int64_t c) {
    return is_own(c) ? static_cast<int>(c - firstc)
                     : nc + static_cast<int>(std::lower_bound(foreign.begin(), foreign.end(), c) - foreign.begin());
  };
  const auto global_c = [&](int c) { return c < nc ? firstc + c : foreign[static_cast<std::size_t>(c - nc)]; };
  CsrOwned Pall;  // rows: own, then ghosts
  Pall.n = n + h.ghosts();
  Pall.ptr.assign(pptr.begin(), pptr.end());
  Pall.ptr.resize(static_cast<std::size_t>(Pall.n) + 1);
  Pall.col.reserve(pcol.size() + gdata.size() / 2);
  Pall.val.reserve(Pall.col.capacity());
  for (std::int64_t c : pcol)
    Pall.col.push_back(local_c(c));
  Pall.val.assign(pval.begin(), pval.end());
  for (int g = 0; g < h.ghosts(); ++g) {
    for (int k = gstart[static_cast<std::size_t>(g)]; k < gstart[static_cast<std::size_t>(g) + 1]; k += 2) {
      Pall.col.push_back(local_c(static_cast<std::int64_t>(gdata[static_cast<std::size_t>(k)])));
      Pall.val.push_back(gdata[static_cast<std::size_t>(k) + 1]);
    }
    Pall.ptr[static_cast<std::size_t>(n + g) + 1] = static_cast<int>(Pall.col.size());
  }
  const CsrRef Pown{n, Pall.ptr.data(), Pall.col.data(), Pall.val.data()};
  const CsrOwned AP = csr_product(A, Pall.ref(), next);
  const CsrOwned R = csr_transpose(Pown, next);
  const CsrOwned Ac = csr_product(R.ref(), AP.ref(), next);  // rows: own aggregates, then foreign
  // Rows of other ranks' aggregates to their owners; this rank's rows with what arrives.
  std::vector<std::vector<Entry>> send(static_cast<std::size_t>(comm_.size()));
  for (int c = nc; c < next; ++c) {
    const std::int64_t row = global_c(c);
    const int owner = static_cast<int>(std::upper_bound(offc.begin(), offc.end(), row) - offc.begin()) - 1;
    for (int k = Ac.ptr[static_cast<std::size_t>(c)]; k < Ac.ptr[static_cast<std::size_t>(c) + 1]; ++k)
      send[static_cast<std::size_t>(owner)].push_back(
          {row, global_c(Ac.col[static_cast<std::size_t>(k)]), Ac.val[static_cast<std::size_t>(k)]});
  }
  std::vector<Entry> arrived = comm_.alltoallv(send);
  std::sort(arrived.begin(), arrived.end(), [](const Entry& a, const Entry& b) { return a.row < b.row; });
  std::vector<int> cptr(static_cast<std::size_t>(nc) + 1, 0);
  std::vector<std::int64_t> ccol;
  std::vector<double> cval;
  ccol.reserve(static_cast<std::size_t>(Ac.ptr[static_cast<std::size_t>(nc)]) + arrived.size());
  cval.reserve(ccol.capacity());
  std::vector<std::int64_t> ghosts;  // the coarse level's halo: the other ranks' aggregates its rows and P reference
  std::size_t next_arrived = 0;
  for (int c = 0; c < nc; ++c) {
    row.clear();
    for (int k = Ac.ptr[static_cast<std::size_t>(c)]; k < Ac.ptr[static_cast<std::size_t>(c) + 1]; ++k)
      row.emplace_back(global_c(Ac.col[static_cast<std::size_t>(k)]), Ac.val[static_cast<std::size_t>(k)]);
    for (; next_arrived < arrived.size() && arrived[next_arrived].row == firstc + c; ++next_arrived)
      row.emplace_back(arrived[next_arrived].col, arrived[next_arrived].val);
    merge_row(row);
    for (const auto& [col, v] : row) {
      ccol.push_back(col);
      cval.push_back(v);
      if (!is_own(col))
        ghosts.push_back(col);
    }
    cptr[static_cast<std::size_t>(c) + 1] = static_cast<int>(ccol.size());
  }
  for (std::int64_t c : pcol)
    if (!is_own(c))
      ghosts.push_back(c);
  std::sort(ghosts.begin(), ghosts.end());
  ghosts.erase(std::unique(ghosts.begin(), ghosts.end()), ghosts.end());
  Coarse level;
  level.offsets = offc;
  level.halo.build(comm_, offc, std::move(ghosts));
  level.A.n = nc;
  level.A.ptr = std::move(cptr);
  level.A.col.resize(ccol.size());
  for (std::size_t k = 0; k < ccol.size(); ++k)
    level.A.col[k] = level.halo.local(ccol[k]);
  level.A.val = std::move(cval);
  // P in the coarse level's numbering, and its transpose.
  CsrOwned Pl;
  Pl.n = n;
  Pl.ptr = std::move(pptr);
  Pl.col.resize(pcol.size());
  for (std::size_t k = 0; k < pcol.size(); ++k)
    Pl.col[k] = level.halo.local(pcol[k]);
  Pl.val = std::move(pval);
  restrict_.push_back(csr_transpose(Pl.ref(), nc + level.halo.ghosts()));
  prolong_.push_back(std::move(Pl));
  coarse_.push_back(std::move(level));
}

void RankAmg::finish() {
  const int L = levels();
  const CsrRef C = op(L - 1);
  const GhostExchange& h = halo(L - 1);
  const std::int64_t first = offsets(L - 1)[static_cast<std::size_t>(comm_.rank())];
  std::vector<Entry> mine;
  for (int i = 0; i < C.n; ++i)
    for (int k = C.ptr[i]; k < C.ptr[i + 1]; ++k)
      mine.push_back({first + i, global_of(h, first, C.col[k]), C.val[k]});
  const std::vector<Entry> all = comm_.allgatherv(mine);
  const auto N = static_cast<Eigen::Index>(global_size(L - 1));
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(N, N);
  for (const Entry& e : all)
    dense(e.row, e.col) += e.val;
  coarsest_.compute(dense);
  if (coarsest_.info() != Eigen::Success)
    throw NumericalFailure("rank AMG: coarsest matrix not positive definite");
  r_.resize(static_cast<std::size_t>(L));
  b_.resize(r_.size());
  x_.resize(r_.size());
  d_.resize(r_.size());
  t_.resize(r_.size());
  for (int l = 0; l < L; ++l)
    size_work(l);
}

void RankAmg::size_work(int l) {
  const std::size_t n = static_cast<std::size_t>(op(l).n), wide = n + static_cast<std::size_t>(halo(l).ghosts());
  const std::size_t s = static_cast<std::size_t>(l);
  r_[s].resize(n);
  b_[s].resize(wide);  // the restriction's sum lands in the ghost slots before it is sent on
  x_[s].resize(wide);
  d_[s].resize(wide);
  t_[s].resize(n);
}

// Chebyshev smoothing of A x = b preconditioned by D^-1 over [lower, 1.1] rho (Saad Alg. 12.1), as
// one process's; x and the search direction carry the level's ghosts for the products.
void RankAmg::smooth(int l, const double* b, double* x, bool zero_guess) const {
  const CsrRef A = op(l);
  const GhostExchange& h = halo(l);
  const int n = A.n;
  const std::size_t s = static_cast<std::size_t>(l);
  const double* inv_d = inv_diag_[s].data();
  double* r = r_[s].data();
  double* d = d_[s].data();
  double* t = t_[s].data();
  const double hi = 1.1 * rho_[s], lo = opt_.cheb_lower * hi;
  const double theta = 0.5 * (hi + lo), delta = 0.5 * (hi - lo), sigma = theta / delta;
  double rho_old = 1.0 / sigma;
  if (zero_guess) {
    std::copy(b, b + n, r);
  } else {
    h.forward(x);
    csr_residual(A, b, x, r);
  }
  for (int i = 0; i < n; ++i) {
    d[i] = inv_d[i] * r[i] / theta;
    x[i] = zero_guess ? d[i] : x[i] + d[i];
  }
  const int degree = l == 0 ? opt_.chebyshev_degree : opt_.coarse_degree;
  for (int k = 1; k < degree; ++k) {
    h.forward(d);
    csr_multiply(A, d, t);
    const double rho_new = 1.0 / (2.0 * sigma - rho_old);
    const double c1 = rho_new * rho_old, c2 = 2.0 * rho_new / delta;
    for (int i = 0; i < n; ++i) {
      r[i] -= t[i];
      d[i] = c1 * d[i] + c2 * inv_d[i] * r[i];
      x[i] += d[i];
    }
    rho_old = rho_new;
  }
}

void RankAmg::cycle(int l, const double* b, double* x) const {
  const int L = levels();
  const CsrRef A = op(l);
  const int n = A.n;
  if (l == L - 1) {  // every rank solves the gathered coarsest system and keeps its rows
    const std::vector<double> all = comm_.allgatherv(std::vector<double>(b, b + n));
    const Eigen::VectorXd z =
        coarsest_.solve(Eigen::Map<const Eigen::VectorXd>(all.data(), static_cast<Eigen::Index>(all.size())));
    const std::int64_t first = offsets(l)[static_cast<std::size_t>(comm_.rank())];
    for (int i = 0; i < n; ++i)
      x[i] = z(static_cast<Eigen::Index>(first + i));
    return;
  }
  const std::size_t s = static_cast<std::size_t>(l);
  smooth(l, b, x, true);
  double* r = r_[s].data();
  halo(l).forward(x);
  csr_residual(A, b, x, r);
  double* bc = b_[s + 1].data();
  csr_multiply(restrict_[s].ref(), r, bc);  // this rank's part of P^T r, the ghosts' to their owners
  halo(l + 1).reverse_add(bc);
  double* xc = x_[s + 1].data();
  cycle(l + 1, bc, xc);
  halo(l + 1).forward(xc);
  const CsrRef P = prolong_[s].ref();
  for (int i = 0; i < n; ++i) {
    double sum = 0;
    for (int k = P.ptr[i]; k < P.ptr[i + 1]; ++k)
      sum += P.val[k] * xc[P.col[k]];
    x[i] += sum;
  }
  smooth(l, b, x, false);
}

void RankAmg::vcycle(const double* r, double* z) const {
  cycle(0, r, z);
}

}  // namespace arksph::distributed_ppe
