#include "distributed_ppe/hypre_poisson.hpp"

#include <HYPRE.h>
#include <HYPRE_krylov.h>
#include <HYPRE_parcsr_ls.h>
#include <_hypre_parcsr_mv.h>  // the ParCSR matrix written in place (make_matrices)

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>
#include <string>

#include "core/errors.hpp"
#include "core/seconds_since.hpp"
#include "projection/poisson/amg_hierarchy.hpp"

namespace arksph::distributed_ppe {

namespace {

// BoomerAMG as one V-cycle preconditioner for PCG on a 2D or 3D Laplacian over several ranks
// (hypre's reference manual, "BoomerAMG" and the parallel settings of its examples).
constexpr int kCoarsenHmis = 10;         // HMIS coarsening (De Sterck, Yang & Heys 2006)
// Extended+e interpolation in matrix-matrix form (hypre's type 18), a distance-two interpolation
// as the extended+i (type 6) that hypre recommends beside HMIS, built from sparse matrix products:
// on the Re = 1000 cavity's matrix on 2 ranks the same iterations (7-9) for a set-up in 0.60-0.65
// of type 6's time (N = 57,600 and 490,000; bench/RESULTS.md "hypre: interpolation").
constexpr int kInterpExtEMatrix = 18;
constexpr int kInterpMaxElements = 4;    // truncation of interpolation rows (operator complexity)
constexpr double kStrongThreshold = 0.25;  // strength of connection for 2D Laplacians
// Smoother: Chebyshev polynomials in D^-1 A (hypre's default order 2, on the upper part of the
// spectrum; Adams, Brezina, Hu & Tuminaro, J. Comput. Phys. 188, 2003), the same polynomial before
// and after the coarse correction, so the V-cycle stays symmetric for PCG. It needs only products
// with the matrix, so the preconditioner is the same on any rank count (Gauss-Seidel's is not, through
// the hybrid coupling across ranks). On the N = 57,600 cavity matrix (bench/bench_hypre_ppe.cpp,
// quiet machine) it takes the iterations of l1 symmetric Gauss-Seidel (7 and 8 for the two sources,
// on 1, 2, 3 and 4 ranks) at 0.45-0.76 of its solve time on 2 ranks: fewer passes over the fine
// matrix per cycle.
constexpr int kRelaxChebyshev = 16;
// The preconditioner's matrix: the rows without their off-diagonal entries below this fraction of
// the largest one (make_matrices), lumped into the diagonal, the diagonal kept at least the second
// fraction of the matrix's: cg_amg's rule (projection/poisson/amg_hierarchy.hpp, sparsify).
constexpr double kDropBelow = kPreconditionerDropBelow;
constexpr double kKeptDiagonal = kPreconditionerKeptDiagonal;

void check(HYPRE_Int err, const char* what) {
  if (err != 0) {
    char text[256] = {0};
    HYPRE_DescribeError(err, text);
    HYPRE_ClearAllErrors();
    throw NumericalFailure(std::string("hypre: ") + what + " failed: " + text);
  }
}


// hypre's 32-bit global indices (Debian's build has no HYPRE_BIGINT).
HYPRE_BigInt big(GlobalRow r) {
  if (r > std::numeric_limits<HYPRE_BigInt>::max() || r < 0)
    throw NumericalFailure("hypre: global row " + std::to_string(r) + " outside its index range");
  return static_cast<HYPRE_BigInt>(r);
}

}  // namespace

// A ParCSR matrix or vector, destroyed on every path out. (A named namespace: HyprePoisson's
// Hierarchy holds a Matrix.)
namespace parcsr {

struct Matrix {
  hypre_ParCSRMatrix* A = nullptr;
  Matrix() = default;
  Matrix(const Matrix&) = delete;
  Matrix& operator=(const Matrix&) = delete;
  Matrix& operator=(Matrix&& o) noexcept {
    std::swap(A, o.A);
    return *this;
  }
  ~Matrix() {
    if (A) hypre_ParCSRMatrixDestroy(A);
  }
  HYPRE_ParCSRMatrix handle() const { return reinterpret_cast<HYPRE_ParCSRMatrix>(A); }
};
struct Vector {
  hypre_ParVector* v = nullptr;
  Vector() = default;
  Vector(const Vector&) = delete;
  Vector& operator=(const Vector&) = delete;
  ~Vector() {
    if (v) hypre_ParVectorDestroy(v);
  }
  HYPRE_ParVector handle() const { return reinterpret_cast<HYPRE_ParVector>(v); }
  double* data() const { return hypre_VectorData(hypre_ParVectorLocalVector(v)); }
};
struct Pcg {
  HYPRE_Solver s = nullptr;
  ~Pcg() {
    if (s) HYPRE_ParCSRPCGDestroy(s);
  }
};

}  // namespace parcsr

namespace {

using parcsr::Matrix;
using parcsr::Pcg;
using parcsr::Vector;

// This rank's rows [lo, lo + n) of a matrix of `total` rows, and the vector over them with `values`.
void make_vector(MPI_Comm comm, HYPRE_BigInt lo, std::size_t n, HYPRE_BigInt total, const double* values, Vector& out) {
  HYPRE_BigInt part[2] = {lo, lo + static_cast<HYPRE_BigInt>(n)};
  out.v = hypre_ParVectorCreate(comm, total, part);
  check(hypre_ParVectorInitialize(out.v), "ParVectorInitialize");
  std::copy(values, values + n, out.data());
}

// One ParCSR matrix being written: its row and column counts, then its arrays.
struct Writer {
  HYPRE_Int nnz_diag = 0, nnz_offd = 0;
  std::vector<HYPRE_BigInt> offd_cols;  // global columns of the offd block, sorted and unique
  HYPRE_Int *di = nullptr, *dj = nullptr, *oi = nullptr, *oj = nullptr;
  double *dv = nullptr, *ov = nullptr;
  HYPRE_Int d = 0, o = 0, at_diagonal = 0;
  double diagonal = 0;

  void create(MPI_Comm comm, HYPRE_BigInt lo, HYPRE_BigInt hi, HYPRE_BigInt total, Matrix& out) {
    std::sort(offd_cols.begin(), offd_cols.end());
    offd_cols.erase(std::unique(offd_cols.begin(), offd_cols.end()), offd_cols.end());
    HYPRE_BigInt part[2] = {lo, hi};
    out.A = hypre_ParCSRMatrixCreate(comm, total, total, part, part, static_cast<HYPRE_Int>(offd_cols.size()),
                                     nnz_diag, nnz_offd);
    check(hypre_ParCSRMatrixInitialize(out.A), "ParCSRMatrixInitialize");
    hypre_CSRMatrix* diag = hypre_ParCSRMatrixDiag(out.A);
    hypre_CSRMatrix* offd = hypre_ParCSRMatrixOffd(out.A);
    di = hypre_CSRMatrixI(diag);
    dj = hypre_CSRMatrixJ(diag);
    dv = hypre_CSRMatrixData(diag);
    oi = hypre_CSRMatrixI(offd);
    oj = hypre_CSRMatrixJ(offd);
    ov = hypre_CSRMatrixData(offd);
    std::copy(offd_cols.begin(), offd_cols.end(), hypre_ParCSRMatrixColMapOffd(out.A));
  }
  void begin_row(std::size_t a) {
    di[a] = d;
    oi[a] = o;
    at_diagonal = d++;
    diagonal = 0;
  }
  void end_row(std::size_t a) {
    dj[at_diagonal] = static_cast<HYPRE_Int>(a);
    dv[at_diagonal] = diagonal;
  }
  void add_diag(HYPRE_Int local, double v) {
    dj[d] = local;
    dv[d++] = v;
  }
  void add_offd(HYPRE_BigInt c, double v) {
    oj[o] = static_cast<HYPRE_Int>(std::lower_bound(offd_cols.begin(), offd_cols.end(), c) - offd_cols.begin());
    ov[o++] = v;
  }
  void finish(std::size_t n, Matrix& out) {
    di[n] = d;
    oi[n] = o;
    check(hypre_ParCSRMatrixSetNumNonzeros(out.A), "ParCSRMatrixSetNumNonzeros");
    check(hypre_MatvecCommPkgCreate(out.A), "MatvecCommPkgCreate");
  }
};

// The rows as hypre's ParCSR matrices A (every entry) and M (the preconditioner's: off-diagonal
// entries with |a_ij| < drop_below left out and added to the diagonal, so the row sums stay),
// written in place: what HYPRE_IJMatrixAssemble would build, without its per-entry insertion, in
// two passes over the rows for both. The "diag" block holds the columns of this rank's rows in
// local numbers, each row's diagonal first (hypre's smoothers read it there), the "offd" block the
// other ranks' columns, numbered by their place in the sorted list col_map_offd.
void make_matrices(MPI_Comm comm, const LocalRows& rows, HYPRE_BigInt lo, double drop_below, Matrix& A, Matrix& M) {
  const std::size_t n = rows.size();
  const HYPRE_BigInt hi = lo + static_cast<HYPRE_BigInt>(n);  // one past this rank's last row
  big(rows.range.total);  // every column below it fits hypre's index
  Writer wa, wm;
  wa.nnz_diag = wm.nnz_diag = static_cast<HYPRE_Int>(n);  // the diagonals
  for (std::size_t a = 0; a < n; ++a) {
    const GlobalRow row = lo + static_cast<GlobalRow>(a);
    for (int k = rows.start[a]; k < rows.start[a + 1]; ++k) {
      const GlobalRow c = rows.col[static_cast<std::size_t>(k)];
      if (c == row) continue;
      const bool kept = std::abs(rows.val[static_cast<std::size_t>(k)]) >= drop_below;
      if (c >= lo && c < hi) {
        ++wa.nnz_diag;
        wm.nnz_diag += kept;
      } else {
        ++wa.nnz_offd;
        wa.offd_cols.push_back(static_cast<HYPRE_BigInt>(c));
        if (kept) {
          ++wm.nnz_offd;
          wm.offd_cols.push_back(static_cast<HYPRE_BigInt>(c));
        }
      }
    }
  }
  const HYPRE_BigInt total = static_cast<HYPRE_BigInt>(rows.range.total);
  wa.create(comm, lo, hi, total, A);
  wm.create(comm, lo, hi, total, M);
  for (std::size_t a = 0; a < n; ++a) {
    const GlobalRow row = lo + static_cast<GlobalRow>(a);
    wa.begin_row(a);
    wm.begin_row(a);
    for (int k = rows.start[a]; k < rows.start[a + 1]; ++k) {
      const GlobalRow c = rows.col[static_cast<std::size_t>(k)];
      const double v = rows.val[static_cast<std::size_t>(k)];
      if (c == row) {
        wa.diagonal += v;
        wm.diagonal += v;
        continue;
      }
      const bool kept = std::abs(v) >= drop_below;
      if (c >= lo && c < hi) {
        wa.add_diag(static_cast<HYPRE_Int>(c - lo), v);
        if (kept) wm.add_diag(static_cast<HYPRE_Int>(c - lo), v);
      } else {
        wa.add_offd(static_cast<HYPRE_BigInt>(c), v);
        if (kept) wm.add_offd(static_cast<HYPRE_BigInt>(c), v);
      }
      if (!kept) wm.diagonal += v;
    }
    wm.diagonal = std::max(wm.diagonal, kKeptDiagonal * wa.diagonal);
    wa.end_row(a);
    wm.end_row(a);
  }
  wa.finish(n, A);
  wm.finish(n, M);
}

}  // namespace

// BoomerAMG set up on the preconditioner matrix `M` of one solve, which it keeps (its finest level
// points at it until a solve passes another); `m_next`: the matrix the next V-cycles run on.
struct HyprePoisson::Hierarchy {
  HYPRE_Solver amg = nullptr;
  parcsr::Matrix M;
  hypre_ParCSRMatrix* m_next = nullptr;
  bool set_up = false;  // whether PCG's preconditioner set-up builds the hierarchy
  ~Hierarchy() {
    if (amg) HYPRE_BoomerAMGDestroy(amg);
  }
};

namespace {

// PCG's preconditioner: one V-cycle on the hierarchy's matrix of this solve (the sparsified rows),
// whatever matrix PCG multiplies by (the full rows).
HYPRE_Int vcycle(HYPRE_Solver solver, HYPRE_Matrix, HYPRE_Vector b, HYPRE_Vector x) {
  auto* h = reinterpret_cast<HyprePoisson::Hierarchy*>(solver);
  return HYPRE_BoomerAMGSolve(h->amg, reinterpret_cast<HYPRE_ParCSRMatrix>(h->m_next), reinterpret_cast<HYPRE_ParVector>(b),
                              reinterpret_cast<HYPRE_ParVector>(x));
}
HYPRE_Int vcycle_setup(HYPRE_Solver solver, HYPRE_Matrix, HYPRE_Vector b, HYPRE_Vector x) {
  auto* h = reinterpret_cast<HyprePoisson::Hierarchy*>(solver);
  if (!h->set_up) return 0;
  return HYPRE_BoomerAMGSetup(h->amg, reinterpret_cast<HYPRE_ParCSRMatrix>(h->m_next), reinterpret_cast<HYPRE_ParVector>(b),
                              reinterpret_cast<HYPRE_ParVector>(x));
}

}  // namespace

HyprePoisson::HyprePoisson(const parallel::Communicator& comm, double tolerance) : comm_(comm), tolerance_(tolerance) {
  static std::once_flag init;
  std::call_once(init, [] { HYPRE_Init(); });
}

HyprePoisson::~HyprePoisson() = default;

HypreSolveReport HyprePoisson::solve(const LocalRows& rows, std::vector<double>& p) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::size_t n = rows.size();
  if (p.size() != n) p.assign(n, 0.0);
  HypreSolveReport rep;
  // |b|^2 and whether any rank's row range changed since the set-up, in one all-reduce; then the
  // largest off-diagonal magnitude, the scale of the preconditioner's sparsification.
  std::vector<double> sums{0.0, 0.0};
  for (double v : rows.b) sums[0] += v * v;
  sums[1] = rows.range.first != first_ || rows.range.total != total_ || n != rows_ ? 1.0 : 0.0;
  comm_.sum_in_place(sums);
  const double nb2 = sums[0];
  if (nb2 == 0) {  // zero source: the solution is zero (as cg_amg)
    std::fill(p.begin(), p.end(), 0.0);
    return rep;
  }
  double largest = 0;
  for (std::size_t a = 0; a < n; ++a)
    for (int k = rows.start[a]; k < rows.start[a + 1]; ++k)
      if (rows.col[static_cast<std::size_t>(k)] != rows.range.first + static_cast<GlobalRow>(a))
        largest = std::max(largest, std::abs(rows.val[static_cast<std::size_t>(k)]));
  largest = comm_.max(largest);
  bool setup = !amg_ || must_setup_ || sums[1] > 0 || solves_since_setup_ >= kReuseMax;
  const MPI_Comm comm = comm_.comm();
  const HYPRE_BigInt lo = big(rows.range.first), total = big(rows.range.total);

  Matrix A, M;
  make_matrices(comm, rows, lo, kDropBelow * largest, A, M);
  Vector b, x, r;
  make_vector(comm, lo, n, total, rows.b.data(), b);
  make_vector(comm, lo, n, total, p.data(), x);
  make_vector(comm, lo, n, total, rows.b.data(), r);
  for (int attempt = 0;; ++attempt) {
    if (setup) {  // a new hierarchy, which keeps this solve's preconditioner matrix
      amg_.reset();
      auto h = std::make_unique<Hierarchy>();
      check(HYPRE_BoomerAMGCreate(&h->amg), "BoomerAMGCreate");
      HYPRE_BoomerAMGSetPrintLevel(h->amg, 0);
      HYPRE_BoomerAMGSetCoarsenType(h->amg, kCoarsenHmis);
      HYPRE_BoomerAMGSetInterpType(h->amg, kInterpExtEMatrix);
      HYPRE_BoomerAMGSetPMaxElmts(h->amg, kInterpMaxElements);
      HYPRE_BoomerAMGSetStrongThreshold(h->amg, kStrongThreshold);
      HYPRE_BoomerAMGSetRelaxType(h->amg, kRelaxChebyshev);
      HYPRE_BoomerAMGSetNumSweeps(h->amg, 1);
      HYPRE_BoomerAMGSetTol(h->amg, 0.0);  // preconditioner: exactly one V-cycle
      HYPRE_BoomerAMGSetMaxIter(h->amg, 1);
      h->M = std::move(M);
      h->m_next = h->M.A;
      amg_ = std::move(h);
      first_ = rows.range.first;
      total_ = rows.range.total;
      rows_ = n;
      must_setup_ = true;  // until PCG's set-up below has built the hierarchy
      solves_since_setup_ = 0;
      baseline_ = -1;
      ++setups_;
    } else {
      amg_->m_next = M.A;
    }
    amg_->set_up = setup;
    rep.refactored_symbolic = rep.refactored_symbolic || setup;

    Pcg pcg;
    check(HYPRE_ParCSRPCGCreate(comm, &pcg.s), "ParCSRPCGCreate");
    const GlobalRow max_it = std::max<GlobalRow>(200, rows.range.total);  // as cg_amg
    HYPRE_PCGSetMaxIter(pcg.s, static_cast<HYPRE_Int>(std::min<GlobalRow>(max_it, std::numeric_limits<HYPRE_Int>::max())));
    HYPRE_PCGSetTol(pcg.s, tolerance_);
    HYPRE_PCGSetAbsoluteTol(pcg.s, 0.0);
    HYPRE_PCGSetTwoNorm(pcg.s, 1);  // |r|_2 / |b|_2, the one-process solvers' test
    HYPRE_PCGSetPrintLevel(pcg.s, 0);
    HYPRE_PCGSetLogging(pcg.s, 0);
    HYPRE_PCGSetPrecond(pcg.s, vcycle, vcycle_setup, reinterpret_cast<HYPRE_Solver>(amg_.get()));
    check(HYPRE_ParCSRPCGSetup(pcg.s, A.handle(), b.handle(), x.handle()), "PCG setup");
    must_setup_ = false;
    rep.setup_seconds = seconds_since(t0) - rep.solve_seconds;
    const auto t1 = std::chrono::steady_clock::now();
    const HYPRE_Int solved = HYPRE_ParCSRPCGSolve(pcg.s, A.handle(), b.handle(), x.handle());
    rep.solve_seconds += seconds_since(t1);
    HYPRE_Int it = 0;
    HYPRE_PCGGetNumIterations(pcg.s, &it);
    rep.iterations += it;
    amg_->m_next = amg_->M.A;  // this solve's preconditioner matrix goes with it
    if (solved != 0 && !HYPRE_CheckError(solved, HYPRE_ERROR_CONV)) check(solved, "PCG solve");
    HYPRE_ClearAllErrors();

    // True residual |b - A p| / |b| (the recursive one drifts by round-off), as cg_amg reports it.
    check(hypre_ParVectorCopy(b.v, r.v), "ParVectorCopy");
    check(HYPRE_ParCSRMatrixMatvec(-1.0, A.handle(), x.handle(), 1.0, r.handle()), "ParCSRMatrixMatvec");
    double rr = 0;
    check(HYPRE_ParVectorInnerProd(r.handle(), r.handle(), &rr), "ParVectorInnerProd");
    rep.relative_residual = std::sqrt(rr / nb2);
    // A kept hierarchy that no longer preconditions the moved particles' matrix (PCG stops on a
    // breakdown, far from the tolerance): set up anew on this matrix and solve again from the same
    // start. The residual is global, so every rank decides alike.
    if (!setup && attempt == 0 && rep.relative_residual > kReuseRetryAbove * tolerance_) {
      setup = true;
      std::copy(p.begin(), p.end(), x.data());
      continue;
    }
    ++solves_since_setup_;
    if (baseline_ < 0)
      baseline_ = it;
    else if (it > std::max(kReuseGrowth * baseline_, baseline_ + 2.0))  // +2: not on noise of small counts
      must_setup_ = true;
    break;
  }
  std::copy(x.data(), x.data() + n, p.begin());
  return rep;
}

}  // namespace arksph::distributed_ppe
