#include "distributed_ppe/rank_amg_poisson.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/errors.hpp"
#include "core/seconds_since.hpp"

namespace arksph::distributed_ppe {

CsrRef rows_in_local_columns(const parallel::Communicator& comm, const LocalRows& rows, GhostExchange& halo,
                             std::vector<int>& local_col) {
  const int n = static_cast<int>(rows.size());
  const GlobalRow lo = rows.range.first, hi = lo + n;
  std::vector<std::int64_t> ghosts;
  for (GlobalRow c : rows.col)
    if (c < lo || c >= hi)
      ghosts.push_back(c);
  std::sort(ghosts.begin(), ghosts.end());
  ghosts.erase(std::unique(ghosts.begin(), ghosts.end()), ghosts.end());
  const std::vector<std::int64_t> counts = comm.allgatherv(std::vector<std::int64_t>{n});
  std::vector<std::int64_t> offsets(counts.size() + 1, 0);
  for (std::size_t q = 0; q < counts.size(); ++q)
    offsets[q + 1] = offsets[q] + counts[q];
  halo.build(comm, offsets, std::move(ghosts));
  local_col.resize(rows.col.size());
  for (std::size_t k = 0; k < rows.col.size(); ++k)
    local_col[k] = halo.local(rows.col[k]);
  return {n, rows.start.data(), local_col.data(), rows.val.data()};
}

RankSolveReport RankAmgPoisson::solve(const LocalRows& rows, std::vector<double>& p) {
  const auto t0 = std::chrono::steady_clock::now();
  const int n = static_cast<int>(rows.size());
  if (p.size() != rows.size())
    p.assign(rows.size(), 0.0);
  RankSolveReport rep;
  std::vector<double> sums{0.0, 0.0};
  for (double v : rows.b)
    sums[0] += v * v;
  sums[1] = rows.range.first != first_ || rows.range.total != total_ ? 1.0 : 0.0;
  comm_.sum_in_place(sums);
  const double nb2 = sums[0];
  if (nb2 == 0) {  // zero source: the solution is zero (as cg_amg)
    std::fill(p.begin(), p.end(), 0.0);
    return rep;
  }
  A_ = rows_in_local_columns(comm_, rows, halo_, local_col_);
  sparsify_below(A_, kPreconditionerDropBelow * comm_.max(largest_off_diagonal(A_)), M_);

  bool setup = !amg_.ready() || must_setup_ || sums[1] > 0 || solves_since_setup_ >= kReuseMax;
  const std::size_t wide = rows.size() + static_cast<std::size_t>(halo_.ghosts());
  x_.resize(wide);
  z_.resize(wide);
  d_.resize(wide);
  r_.resize(rows.size());
  q_.resize(rows.size());
  const GlobalRow max_it = std::max<GlobalRow>(200, rows.range.total);  // as cg_amg
  for (int attempt = 0;; ++attempt) {
    const auto ts = std::chrono::steady_clock::now();
    if (setup) {
      amg_.setup(M_.ref(), halo_);
      first_ = rows.range.first;
      total_ = rows.range.total;
      must_setup_ = false;
      solves_since_setup_ = 0;
      baseline_ = -1;
      ++setups_;
    } else {
      amg_.rebind_finest(M_.ref(), halo_);
    }
    rep.refactored_symbolic = rep.refactored_symbolic || setup;
    rep.setup_seconds += seconds_since(ts);
    std::copy(p.begin(), p.end(), x_.begin());
    const auto t1 = std::chrono::steady_clock::now();
    int it = 0;
    bool broke_down = false;
    pcg(rows.b.data(), nb2, static_cast<int>(std::min<GlobalRow>(max_it, 1 << 30)), it, rep.relative_residual,
        broke_down);
    rep.solve_seconds += seconds_since(t1);
    rep.iterations += it;
    if (!setup && attempt == 0 && (broke_down || rep.relative_residual > kReuseRetryAbove * tolerance_)) {
      setup = true;  // global decision: the residual and the breakdown are global
      continue;
    }
    if (broke_down)
      throw NumericalFailure("rank AMG: preconditioner not positive definite");
    ++solves_since_setup_;
    if (baseline_ < 0)
      baseline_ = it;
    else if (it > std::max(kReuseGrowth * baseline_, baseline_ + 2.0))
      must_setup_ = true;  // +2: not on noise of small counts
    break;
  }
  std::copy(x_.begin(), x_.begin() + n, p.begin());
  rep.setup_seconds = seconds_since(t0) - rep.solve_seconds;  // the rows' hand-over included
  return rep;
}

bool RankAmgPoisson::pcg(const double* b, double nb2, int max_it, int& it, double& relative_residual,
                         bool& broke_down) {
  const CsrRef A = A_;
  const int n = A.n;
  double* x = x_.data();
  double* r = r_.data();
  double* z = z_.data();
  double* d = d_.data();
  double* q = q_.data();
  const auto dot = [&](const double* u, const double* v) {
    double s = 0;
    for (int i = 0; i < n; ++i)
      s += u[i] * v[i];
    return comm_.sum(s);
  };
  halo_.forward(x);
  csr_residual(A, b, x, r);
  double rr = dot(r, r);
  const double target2 = tolerance_ * tolerance_ * nb2;
  double rz = 0;
  it = 0;
  while (rr > target2 && it < max_it) {
    amg_.vcycle(r, z);
    const double rz_new = dot(r, z);
    if (!(rz_new > 0)) {
      broke_down = true;
      break;
    }
    const double beta = it == 0 ? 0.0 : rz_new / rz;
    rz = rz_new;
    for (int i = 0; i < n; ++i)
      d[i] = z[i] + beta * d[i];
    halo_.forward(d);
    csr_multiply(A, d, q);
    const double dq = dot(d, q);
    if (!(dq > 0)) {
      broke_down = true;
      break;
    }
    const double alpha = rz / dq;
    double local = 0;
    for (int i = 0; i < n; ++i) {
      x[i] += alpha * d[i];
      r[i] -= alpha * q[i];
      local += r[i] * r[i];
    }
    rr = comm_.sum(local);
    ++it;
  }
  // The true residual (the recursive one drifts by round-off).
  halo_.forward(x);
  csr_residual(A, b, x, q);
  relative_residual = std::sqrt(dot(q, q) / nb2);
  return rr <= target2 && !broke_down;
}

}  // namespace arksph::distributed_ppe
