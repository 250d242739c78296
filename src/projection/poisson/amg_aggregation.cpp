// Greedy aggregation of Vanek, Mandel & Brezina (Computing 56, 1996, §3 "Algorithm 1"):
//   strong connection: |a_ij| >= theta sqrt(|a_ii a_jj|), j != i (their eq. 3.2, epsilon = theta^2);
//   phase 1: every node whose strong neighbourhood is still wholly unaggregated founds an aggregate
//            made of itself and that neighbourhood (the neighbourhoods are disjoint);
//   phase 2: every remaining node joins the phase-1 aggregate it is most strongly connected to;
//   phase 3: nodes still left (no strong link to any phase-1 aggregate) form aggregates with their
//            unaggregated strong neighbours.
// Nodes without strong off-diagonal links (the pinned unknown, isolated particles) are singletons.
// Columns at or beyond A.n (a rank's halo) are not nodes of the graph and are left out.
#include <cmath>

#include "projection/poisson/amg_hierarchy.hpp"

namespace arksph {

int aggregate(const CsrRef& A, double theta, std::vector<int>& agg) {
  const int n = A.n;
  std::vector<double> diag(static_cast<std::size_t>(n), 0.0);
  for (int i = 0; i < n; ++i)
    for (int k = A.ptr[i]; k < A.ptr[i + 1]; ++k)
      if (A.col[k] == i) diag[i] = std::abs(A.val[k]);
  const double t2 = theta * theta;
  // Strong neighbours of every row, compressed (the three phases read them several times).
  std::vector<int> sptr(static_cast<std::size_t>(n) + 1, 0), scol;
  scol.reserve(static_cast<std::size_t>(A.ptr[n]));
  for (int i = 0; i < n; ++i) {
    for (int k = A.ptr[i]; k < A.ptr[i + 1]; ++k) {
      const int j = A.col[k];
      if (j != i && j < n && A.val[k] * A.val[k] >= t2 * diag[i] * diag[j]) scol.push_back(j);
    }
    sptr[i + 1] = static_cast<int>(scol.size());
  }
  agg.assign(static_cast<std::size_t>(n), -1);
  int count = 0;
  // Phase 1.
  for (int i = 0; i < n; ++i) {
    if (agg[i] >= 0 || sptr[i] == sptr[i + 1]) continue;
    bool free = true;
    for (int k = sptr[i]; k < sptr[i + 1] && free; ++k) free = agg[scol[k]] < 0;
    if (!free) continue;
    agg[i] = count;
    for (int k = sptr[i]; k < sptr[i + 1]; ++k) agg[scol[k]] = count;
    ++count;
  }
  // Phase 2: join the phase-1 aggregate of the strongest aggregated neighbour.
  const std::vector<int> phase1 = agg;
  for (int i = 0; i < n; ++i) {
    if (phase1[i] >= 0) continue;
    double best = -1;
    for (int k = A.ptr[i]; k < A.ptr[i + 1]; ++k) {
      const int j = A.col[k];
      if (j == i || j >= n || phase1[j] < 0) continue;
      const double s = A.val[k] * A.val[k];
      if (s >= t2 * diag[i] * diag[j] && s > best) {
        best = s;
        agg[i] = phase1[j];
      }
    }
  }
  // Phase 3: what is left aggregates with its free strong neighbours (or alone).
  for (int i = 0; i < n; ++i) {
    if (agg[i] >= 0) continue;
    agg[i] = count;
    for (int k = sptr[i]; k < sptr[i + 1]; ++k)
      if (agg[scol[k]] < 0) agg[scol[k]] = count;
    ++count;
  }
  return count;
}

}  // namespace arksph
