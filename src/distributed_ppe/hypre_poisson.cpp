#include "distributed_ppe/hypre_poisson.hpp"

#include <HYPRE.h>
#include <HYPRE_krylov.h>
#include <HYPRE_parcsr_ls.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>
#include <string>

#include "core/errors.hpp"
#include "core/seconds_since.hpp"

namespace arksph::distributed_ppe {

namespace {

// BoomerAMG as one V-cycle preconditioner for PCG on a 2D or 3D Laplacian over several ranks
// (hypre's reference manual, "BoomerAMG" and the parallel settings of its examples).
constexpr int kCoarsenHmis = 10;         // HMIS coarsening (De Sterck, Yang & Heys 2006)
constexpr int kInterpExtI = 6;           // extended+i interpolation, the partner of HMIS
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
// Reuse of the hierarchy (the header), cg_amg's constants and measured choice.
constexpr double kGrowth = 1.25;  // set up anew when iterations exceed this x the count after the last set-up
constexpr int kMaxReuse = 25;     // ... or after this many solves

// PCG's preconditioner set-up while the hierarchy is reused: nothing to do.
HYPRE_Int keep_hierarchy(HYPRE_Solver, HYPRE_Matrix, HYPRE_Vector, HYPRE_Vector) { return 0; }

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

// The IJ objects of one solve, destroyed on every path out (the matrix unless a new hierarchy
// keeps it).
struct IjSystem {
  HYPRE_IJMatrix A = nullptr;
  HYPRE_IJVector b = nullptr, x = nullptr, r = nullptr;
  HYPRE_Solver pcg = nullptr;
  ~IjSystem() {
    if (pcg) HYPRE_ParCSRPCGDestroy(pcg);
    if (r) HYPRE_IJVectorDestroy(r);
    if (x) HYPRE_IJVectorDestroy(x);
    if (b) HYPRE_IJVectorDestroy(b);
    if (A) HYPRE_IJMatrixDestroy(A);
  }
};

void make_vector(MPI_Comm comm, HYPRE_BigInt lo, HYPRE_BigInt hi, const std::vector<HYPRE_BigInt>& idx,
                           const double* values, HYPRE_IJVector& v) {
  check(HYPRE_IJVectorCreate(comm, lo, hi, &v), "IJVectorCreate");
  check(HYPRE_IJVectorSetObjectType(v, HYPRE_PARCSR), "IJVectorSetObjectType");
  check(HYPRE_IJVectorInitialize(v), "IJVectorInitialize");
  if (!idx.empty())
    check(HYPRE_IJVectorSetValues(v, static_cast<HYPRE_Int>(idx.size()), idx.data(), values), "IJVectorSetValues");
  check(HYPRE_IJVectorAssemble(v), "IJVectorAssemble");
}

}  // namespace

// BoomerAMG set up on `A`, which it keeps (its finest level points at it until a solve passes another).
struct HyprePoisson::Hierarchy {
  HYPRE_Solver amg = nullptr;
  HYPRE_IJMatrix A = nullptr;
  ~Hierarchy() {
    if (amg) HYPRE_BoomerAMGDestroy(amg);
    if (A) HYPRE_IJMatrixDestroy(A);
  }
};

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
  // |b|^2 and whether any rank's row range changed since the set-up, in one all-reduce.
  std::vector<double> sums{0.0, 0.0};
  for (double v : rows.b) sums[0] += v * v;
  sums[1] = rows.range.first != first_ || rows.range.total != total_ || n != rows_ ? 1.0 : 0.0;
  comm_.sum_in_place(sums);
  const double nb2 = sums[0];
  if (nb2 == 0) {  // zero source: the solution is zero (as cg_amg)
    std::fill(p.begin(), p.end(), 0.0);
    return rep;
  }
  const bool setup = !amg_ || must_setup_ || sums[1] > 0 || solves_since_setup_ >= kMaxReuse;
  const MPI_Comm comm = comm_.comm();
  // Empty ranks own the empty range [first, first - 1].
  const HYPRE_BigInt lo = big(rows.range.first), hi = big(rows.range.first + static_cast<GlobalRow>(n)) - 1;
  std::vector<HYPRE_BigInt> idx(n), cols(rows.col.size());
  std::vector<HYPRE_Int> ncols(n);
  for (std::size_t a = 0; a < n; ++a) {
    idx[a] = lo + static_cast<HYPRE_BigInt>(a);
    ncols[a] = rows.start[a + 1] - rows.start[a];
  }
  for (std::size_t k = 0; k < cols.size(); ++k) cols[k] = big(rows.col[k]);

  IjSystem s;
  check(HYPRE_IJMatrixCreate(comm, lo, hi, lo, hi, &s.A), "IJMatrixCreate");
  check(HYPRE_IJMatrixSetObjectType(s.A, HYPRE_PARCSR), "IJMatrixSetObjectType");
  {
    std::vector<HYPRE_Int> diag(n, 0), offd(n, 0);  // preallocation: entries inside / outside the block
    for (std::size_t a = 0; a < n; ++a)
      for (int k = rows.start[a]; k < rows.start[a + 1]; ++k)
        ++((cols[static_cast<std::size_t>(k)] >= lo && cols[static_cast<std::size_t>(k)] <= hi) ? diag : offd)[a];
    if (n > 0) check(HYPRE_IJMatrixSetDiagOffdSizes(s.A, diag.data(), offd.data()), "IJMatrixSetDiagOffdSizes");
  }
  check(HYPRE_IJMatrixInitialize(s.A), "IJMatrixInitialize");
  if (n > 0)
    check(HYPRE_IJMatrixSetValues(s.A, static_cast<HYPRE_Int>(n), ncols.data(), idx.data(), cols.data(), rows.val.data()),
          "IJMatrixSetValues");
  check(HYPRE_IJMatrixAssemble(s.A), "IJMatrixAssemble");
  make_vector(comm, lo, hi, idx, rows.b.data(), s.b);
  make_vector(comm, lo, hi, idx, p.data(), s.x);
  HYPRE_ParCSRMatrix A = nullptr;
  HYPRE_ParVector b = nullptr, x = nullptr;
  check(HYPRE_IJMatrixGetObject(s.A, reinterpret_cast<void**>(&A)), "IJMatrixGetObject");
  check(HYPRE_IJVectorGetObject(s.b, reinterpret_cast<void**>(&b)), "IJVectorGetObject");
  check(HYPRE_IJVectorGetObject(s.x, reinterpret_cast<void**>(&x)), "IJVectorGetObject");

  if (setup) {  // a new hierarchy, which keeps this solve's matrix
    amg_.reset();
    auto h = std::make_unique<Hierarchy>();
    check(HYPRE_BoomerAMGCreate(&h->amg), "BoomerAMGCreate");
    HYPRE_BoomerAMGSetPrintLevel(h->amg, 0);
    HYPRE_BoomerAMGSetCoarsenType(h->amg, kCoarsenHmis);
    HYPRE_BoomerAMGSetInterpType(h->amg, kInterpExtI);
    HYPRE_BoomerAMGSetPMaxElmts(h->amg, kInterpMaxElements);
    HYPRE_BoomerAMGSetStrongThreshold(h->amg, kStrongThreshold);
    HYPRE_BoomerAMGSetRelaxType(h->amg, kRelaxChebyshev);
    HYPRE_BoomerAMGSetNumSweeps(h->amg, 1);
    HYPRE_BoomerAMGSetTol(h->amg, 0.0);  // preconditioner: exactly one V-cycle
    HYPRE_BoomerAMGSetMaxIter(h->amg, 1);
    h->A = s.A;
    s.A = nullptr;
    amg_ = std::move(h);
    first_ = rows.range.first;
    total_ = rows.range.total;
    rows_ = n;
    must_setup_ = true;  // until PCG's set-up below has built the hierarchy
    solves_since_setup_ = 0;
    baseline_ = -1;
    ++setups_;
  }
  rep.refactored_symbolic = setup;

  check(HYPRE_ParCSRPCGCreate(comm, &s.pcg), "ParCSRPCGCreate");
  const GlobalRow max_it = std::max<GlobalRow>(200, rows.range.total);  // as cg_amg
  HYPRE_PCGSetMaxIter(s.pcg, static_cast<HYPRE_Int>(std::min<GlobalRow>(max_it, std::numeric_limits<HYPRE_Int>::max())));
  HYPRE_PCGSetTol(s.pcg, tolerance_);
  HYPRE_PCGSetAbsoluteTol(s.pcg, 0.0);
  HYPRE_PCGSetTwoNorm(s.pcg, 1);  // |r|_2 / |b|_2, the one-process solvers' test
  HYPRE_PCGSetPrintLevel(s.pcg, 0);
  HYPRE_PCGSetLogging(s.pcg, 0);
  HYPRE_PCGSetPrecond(s.pcg, reinterpret_cast<HYPRE_PtrToSolverFcn>(HYPRE_BoomerAMGSolve),
                      setup ? reinterpret_cast<HYPRE_PtrToSolverFcn>(HYPRE_BoomerAMGSetup) : keep_hierarchy, amg_->amg);
  check(HYPRE_ParCSRPCGSetup(s.pcg, A, b, x), "PCG setup");
  must_setup_ = false;
  rep.setup_seconds = seconds_since(t0);
  const auto t1 = std::chrono::steady_clock::now();
  const HYPRE_Int solved = HYPRE_ParCSRPCGSolve(s.pcg, A, b, x);
  rep.solve_seconds = seconds_since(t1);
  HYPRE_Int it = 0;
  HYPRE_PCGGetNumIterations(s.pcg, &it);
  rep.iterations = it;
  ++solves_since_setup_;
  if (baseline_ < 0)
    baseline_ = rep.iterations;
  else if (rep.iterations > std::max(kGrowth * baseline_, baseline_ + 2.0))  // +2: not on noise of small counts
    must_setup_ = true;
  if (solved != 0 && !HYPRE_CheckError(solved, HYPRE_ERROR_CONV)) check(solved, "PCG solve");
  HYPRE_ClearAllErrors();
  if (n > 0) check(HYPRE_IJVectorGetValues(s.x, static_cast<HYPRE_Int>(n), idx.data(), p.data()), "IJVectorGetValues");

  // True residual |b - A p| / |b| (the recursive one drifts by round-off), as cg_amg reports it.
  make_vector(comm, lo, hi, idx, rows.b.data(), s.r);
  HYPRE_ParVector r = nullptr;
  check(HYPRE_IJVectorGetObject(s.r, reinterpret_cast<void**>(&r)), "IJVectorGetObject");
  check(HYPRE_ParCSRMatrixMatvec(-1.0, A, x, 1.0, r), "ParCSRMatrixMatvec");
  double rr = 0;
  check(HYPRE_ParVectorInnerProd(r, r, &rr), "ParVectorInnerProd");
  rep.relative_residual = std::sqrt(rr / nb2);
  return rep;
}

}  // namespace arksph::distributed_ppe
