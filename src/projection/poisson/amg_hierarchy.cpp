// Aggregation AMG hierarchy and its symmetric V-cycle (sources in amg_hierarchy.hpp).
#include "projection/poisson/amg_hierarchy.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/errors.hpp"

namespace arksph {

namespace {
constexpr int kParallelMin = kSolverParallelMin;
}  // namespace

CsrOwned csr_product(const CsrRef& A, const CsrRef& B, int ncols) {
  CsrOwned C;
  C.n = A.n;
  C.ptr.assign(static_cast<std::size_t>(A.n) + 1, 0);
#pragma omp parallel if (A.n > kParallelMin)
  {
    std::vector<int> mark(static_cast<std::size_t>(ncols), -1);
#pragma omp for schedule(static)
    for (int i = 0; i < A.n; ++i) {
      int c = 0;
      for (int k = A.ptr[i]; k < A.ptr[i + 1]; ++k)
        for (int m = B.ptr[A.col[k]]; m < B.ptr[A.col[k] + 1]; ++m)
          if (mark[B.col[m]] != i) {
            mark[B.col[m]] = i;
            ++c;
          }
      C.ptr[i + 1] = c;
    }
  }
  for (int i = 0; i < A.n; ++i) C.ptr[i + 1] += C.ptr[i];
  C.col.resize(static_cast<std::size_t>(C.ptr[A.n]));
  C.val.resize(C.col.size());
#pragma omp parallel if (A.n > kParallelMin)
  {
    std::vector<int> pos(static_cast<std::size_t>(ncols), -1);  // slot of a column in the current row
#pragma omp for schedule(static)
    for (int i = 0; i < A.n; ++i) {
      const int row0 = C.ptr[i];
      int next = row0;
      for (int k = A.ptr[i]; k < A.ptr[i + 1]; ++k) {
        const double a = A.val[k];
        for (int m = B.ptr[A.col[k]]; m < B.ptr[A.col[k] + 1]; ++m) {
          const int c = B.col[m];
          if (pos[c] < row0) {  // rows of one thread increase, so older slots are < row0
            pos[c] = next;
            C.col[next] = c;
            C.val[next++] = a * B.val[m];
          } else {
            C.val[pos[c]] += a * B.val[m];
          }
        }
      }
    }
  }
  return C;
}

CsrOwned csr_transpose(const CsrRef& A, int ncols) {
  CsrOwned T;
  T.n = ncols;
  T.ptr.assign(static_cast<std::size_t>(ncols) + 1, 0);
  for (int k = 0; k < A.ptr[A.n]; ++k) ++T.ptr[A.col[k] + 1];
  for (int c = 0; c < ncols; ++c) T.ptr[c + 1] += T.ptr[c];
  T.col.resize(static_cast<std::size_t>(A.ptr[A.n]));
  T.val.resize(T.col.size());
  std::vector<int> next(T.ptr.begin(), T.ptr.end() - 1);
  for (int i = 0; i < A.n; ++i)
    for (int k = A.ptr[i]; k < A.ptr[i + 1]; ++k) {
      const int slot = next[A.col[k]]++;
      T.col[slot] = i;
      T.val[slot] = A.val[k];
    }
  return T;
}

std::vector<double> csr_inverse_diagonal(const CsrRef& A) {
  std::vector<double> d(static_cast<std::size_t>(A.n), 0.0);
#pragma omp parallel for schedule(static) if (A.n > kParallelMin)
  for (int i = 0; i < A.n; ++i)
    for (int k = A.ptr[i]; k < A.ptr[i + 1]; ++k)
      if (A.col[k] == i) {
        d[i] = 1.0 / A.val[k];
        break;  // one diagonal entry a row (duplicates merged)
      }
  for (double v : d)
    if (!(v > 0) || !std::isfinite(v)) throw NumericalFailure("cg_amg: matrix diagonal not positive");
  return d;
}

namespace {
// Largest eigenvalue of D^-1 A (similar to the SPD D^-1/2 A D^-1/2) by power iteration.
double spectral_radius(const CsrRef& A, const std::vector<double>& inv_diag) {
  const std::size_t n = static_cast<std::size_t>(A.n);
  std::vector<double> x(n), y(n);
  unsigned state = 12345u;  // fixed pseudo-random start: reproducible hierarchies
  for (double& v : x) {
    state = state * 1664525u + 1013904223u;
    v = 0.5 + static_cast<double>(state >> 8) / static_cast<double>(1u << 24);
  }
  double est = 0;
  for (int it = 0; it < 15; ++it) {
    csr_multiply(A, x.data(), y.data());
    double ny = 0, nx = 0;
    for (std::size_t i = 0; i < n; ++i) {
      y[i] *= inv_diag[i];
      ny += y[i] * y[i];
      nx += x[i] * x[i];
    }
    est = std::sqrt(ny / nx);
    const double s = 1.0 / std::sqrt(ny);
    for (std::size_t i = 0; i < n; ++i) x[i] = y[i] * s;
  }
  return est;
}
}  // namespace

void csr_multiply(const CsrRef& A, const double* x, double* y) {
#pragma omp parallel for schedule(static) if (A.n > kParallelMin)
  for (int i = 0; i < A.n; ++i) {
    double s = 0;
    for (int k = A.ptr[i]; k < A.ptr[i + 1]; ++k) s += A.val[k] * x[A.col[k]];
    y[i] = s;
  }
}

void csr_residual(const CsrRef& A, const double* b, const double* x, double* r) {
#pragma omp parallel for schedule(static) if (A.n > kParallelMin)
  for (int i = 0; i < A.n; ++i) {
    double s = b[i];
    for (int k = A.ptr[i]; k < A.ptr[i + 1]; ++k) s -= A.val[k] * x[A.col[k]];
    r[i] = s;
  }
}

CsrRef csr_view(const SparseMatrix& S) {
  if (!S.isCompressed()) throw std::logic_error("csr_view: matrix not compressed");
  return {static_cast<int>(S.rows()), S.outerIndexPtr(), S.innerIndexPtr(), S.valuePtr()};
}

double largest_off_diagonal(const CsrRef& A) {
  double largest = 0;
  for (int i = 0; i < A.n; ++i)
    for (int k = A.ptr[i]; k < A.ptr[i + 1]; ++k)
      if (A.col[k] != i) largest = std::max(largest, std::abs(A.val[k]));
  return largest;
}

void sparsify(const CsrRef& A, double fraction, CsrOwned& out) {
  sparsify_below(A, fraction * largest_off_diagonal(A), out);
}

void sparsify_below(const CsrRef& A, double drop, CsrOwned& out) {
  out.n = A.n;
  out.ptr.assign(static_cast<std::size_t>(A.n) + 1, 0);
  out.col.clear();
  out.val.clear();
  out.col.reserve(static_cast<std::size_t>(A.ptr[A.n]));
  out.val.reserve(static_cast<std::size_t>(A.ptr[A.n]));
  for (int i = 0; i < A.n; ++i) {
    std::size_t at_diagonal = out.col.size();
    double lumped = 0, diagonal = 0;
    bool has_diagonal = false;
    for (int k = A.ptr[i]; k < A.ptr[i + 1]; ++k) {
      if (A.col[k] != i && std::abs(A.val[k]) < drop) {
        lumped += A.val[k];
        continue;
      }
      if (A.col[k] == i) {
        at_diagonal = out.col.size();
        has_diagonal = true;
        diagonal = A.val[k];
      }
      out.col.push_back(A.col[k]);
      out.val.push_back(A.val[k]);
    }
    if (!has_diagonal && lumped != 0) {  // a row without a stored diagonal: keep the sorted order
      const auto pos = std::lower_bound(out.col.begin() + out.ptr[static_cast<std::size_t>(i)], out.col.end(), i);
      at_diagonal = static_cast<std::size_t>(pos - out.col.begin());
      out.col.insert(pos, i);
      out.val.insert(out.val.begin() + static_cast<std::ptrdiff_t>(at_diagonal), 0.0);
    }
    if (lumped != 0)
      out.val[at_diagonal] = std::max(out.val[at_diagonal] + lumped, kPreconditionerKeptDiagonal * diagonal);
    out.ptr[static_cast<std::size_t>(i) + 1] = static_cast<int>(out.col.size());
  }
}

long AmgHierarchy::nonzeros(int level) const { return op(level).ptr[size(level)]; }

void AmgHierarchy::setup(const CsrRef& A) {
  A0_ = A;
  agg_.clear();
  prolong_.clear();
  restrict_.clear();
  coarse_.clear();
  inv_diag_.clear();
  rho_.clear();
  while (levels() < opt_.max_levels && size(levels() - 1) > opt_.max_coarse) {
    const int l = levels() - 1;
    std::vector<int> agg;
    // Vanek et al. halve theta from level to level; halve it again while coarsening stalls.
    double theta = opt_.theta * std::pow(opt_.theta_decay, l);
    int nc = aggregate(op(l), theta, agg);
    for (int retry = 0; retry < 4 && nc > 0.5 * size(l); ++retry) nc = aggregate(op(l), theta *= 0.5, agg);
    if (nc > 0.9 * size(l)) break;  // coarsening stalled: solve this level directly
    agg_.push_back(std::move(agg));
    prolong_.emplace_back();
    restrict_.emplace_back();
    coarse_.emplace_back();
    build_level(l, nc);
  }
  finish();
}

void AmgHierarchy::rebind_finest(const CsrRef& A) {
  if (A.n != A0_.n) throw std::logic_error("AmgHierarchy::rebind_finest: size changed");
  A0_ = A;
  if (levels() > 1) inv_diag_[0] = csr_inverse_diagonal(A);
}

void AmgHierarchy::build_level(int l, int nc) {
  const CsrRef A = op(l);
  const std::vector<int>& agg = agg_[l];
  if (static_cast<int>(inv_diag_.size()) <= l) {
    inv_diag_.resize(l + 1);
    rho_.resize(l + 1);
  }
  inv_diag_[l] = csr_inverse_diagonal(A);
  rho_[l] = spectral_radius(A, inv_diag_[l]);
  CsrOwned P;  // tentative prolongator: piecewise constant on aggregates
  P.n = A.n;
  P.ptr.resize(static_cast<std::size_t>(A.n) + 1);
  for (int i = 0; i <= A.n; ++i) P.ptr[i] = i;
  P.col = agg;
  P.val.assign(static_cast<std::size_t>(A.n), 1.0);
  if (opt_.smoothed) {  // P = (I - omega D^-1 A) P_tent, Vanek et al. §4
    const double omega = opt_.omega_scale / rho_[l];
    CsrOwned S = csr_product(A, P.ref(), nc);
    for (int i = 0; i < A.n; ++i)
      for (int k = S.ptr[i]; k < S.ptr[i + 1]; ++k)
        S.val[k] = (S.col[k] == agg[i] ? 1.0 : 0.0) - omega * inv_diag_[l][i] * S.val[k];
    P = std::move(S);
  }
  restrict_[l] = csr_transpose(P.ref(), nc);
  const CsrOwned AP = csr_product(A, P.ref(), nc);
  prolong_[l] = std::move(P);
  coarse_[l] = csr_product(restrict_[l].ref(), AP.ref(), nc);
}

void AmgHierarchy::finish() {
  const int L = levels();
  const CsrRef C = op(L - 1);
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(C.n, C.n);
  for (int i = 0; i < C.n; ++i)
    for (int k = C.ptr[i]; k < C.ptr[i + 1]; ++k) dense(i, C.col[k]) += C.val[k];
  coarsest_.compute(dense);
  if (coarsest_.info() != Eigen::Success) throw NumericalFailure("cg_amg: coarsest matrix not positive definite");
  r_.resize(L);
  b_.resize(L);
  x_.resize(L);
  d_.resize(L);
  t_.resize(L);
  for (int l = 0; l < L; ++l) {
    const std::size_t n = static_cast<std::size_t>(size(l));
    r_[l].resize(n);
    b_[l].resize(n);
    x_[l].resize(n);
    d_[l].resize(n);
    t_[l].resize(n);
  }
}

// Chebyshev smoothing of A x = b preconditioned by D^-1 over [lower, 1.1] rho (Saad Alg. 12.1).
void AmgHierarchy::smooth(int l, const double* b, double* x, bool zero_guess) const {
  const CsrRef A = op(l);
  const int n = A.n;
  const double* inv_d = inv_diag_[l].data();
  double* r = r_[l].data();
  double* d = d_[l].data();
  double* t = t_[l].data();
  const double hi = 1.1 * rho_[l], lo = opt_.cheb_lower * hi;
  const double theta = 0.5 * (hi + lo), delta = 0.5 * (hi - lo), sigma = theta / delta;
  double rho_old = 1.0 / sigma;
  if (zero_guess) std::copy(b, b + n, r);
  else csr_residual(A, b, x, r);
#pragma omp parallel for schedule(static) if (n > kParallelMin)
  for (int i = 0; i < n; ++i) {
    d[i] = inv_d[i] * r[i] / theta;
    x[i] = zero_guess ? d[i] : x[i] + d[i];
  }
  const int degree = l == 0 ? opt_.chebyshev_degree : opt_.coarse_degree;
  for (int k = 1; k < degree; ++k) {
    csr_multiply(A, d, t);
    const double rho_new = 1.0 / (2.0 * sigma - rho_old);
    const double c1 = rho_new * rho_old, c2 = 2.0 * rho_new / delta;
#pragma omp parallel for schedule(static) if (n > kParallelMin)
    for (int i = 0; i < n; ++i) {
      r[i] -= t[i];
      d[i] = c1 * d[i] + c2 * inv_d[i] * r[i];
      x[i] += d[i];
    }
    rho_old = rho_new;
  }
}

void AmgHierarchy::cycle(int l, const double* b, double* x) const {
  const int L = levels();
  if (l == L - 1) {
    const Eigen::Map<const Eigen::VectorXd> bb(b, size(l));
    Eigen::Map<Eigen::VectorXd>(x, size(l)) = coarsest_.solve(bb);
    return;
  }
  const CsrRef A = op(l);
  const int n = A.n;
  smooth(l, b, x, true);
  double* r = r_[l].data();
  csr_residual(A, b, x, r);
  csr_multiply(restrict_[l].ref(), r, b_[l + 1].data());
  cycle(l + 1, b_[l + 1].data(), x_[l + 1].data());
  const CsrRef P = prolong_[l].ref();
  const double* xc = x_[l + 1].data();
#pragma omp parallel for schedule(static) if (n > kParallelMin)
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (int k = P.ptr[i]; k < P.ptr[i + 1]; ++k) s += P.val[k] * xc[P.col[k]];
    x[i] += s;
  }
  smooth(l, b, x, false);
}

void AmgHierarchy::vcycle(const double* r, double* z) const { cycle(0, r, z); }

}  // namespace arksph
