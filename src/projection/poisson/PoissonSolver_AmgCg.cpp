// "cg_amg": conjugate gradients (Hestenes & Stiefel 1952; preconditioned form: Saad 2003, Algorithm
// 9.1) preconditioned by one symmetric V-cycle of aggregation AMG (amg_hierarchy.hpp), warm-started
// from the caller's pressure.
//
// Reuse across steps: the particle count is fixed and particles move a fraction of a spacing per
// step, so the hierarchy of one step serves the next ones. Each solve re-points the finest level
// (smoother) at the new matrix; aggregates, prolongators and coarse operators stay those of the last
// setup (a fixed SPD preconditioner, so CG stays valid). The hierarchy is rebuilt when a solve needs
// more than kGrowth times the iterations of the first solve after the last rebuild, after kMaxReuse
// solves, or when the size changes. Measured on the Re = 1000 cavity, N = 14,400, 150 steps
// (bench/RESULTS.md): never rebuilding, the count climbs to 34 a solve on average; rebuilding every
// solve gives 8.6 but costs a setup (~5 solves' worth) each time; keeping the aggregates and redoing
// the Galerkin products every solve gives 10.3 at nearly the cost of a setup; the growth trigger
// (1.25) gives 9.5 with 15 setups in 150 solves, the cheapest. A kept hierarchy that no longer
// preconditions the moved particles' matrix (CG far past the count after the last rebuild, or a
// non-positive r.z) is given up within the solve: a new one is built and the solve done again from
// the same start, where it would otherwise run to the iteration limit max(200, n).
//
// The V-cycle runs on a sparsified copy of the matrix (amg_hierarchy.hpp, sparsify): the hierarchy
// is set up on it and its finest level re-pointed at each solve's copy, while CG multiplies by the
// matrix itself, so the solution and the stopping test are the matrix's. On the N = 57,600 cavity
// (C&R, 52 steps) it took 547 iterations instead of 485 and 3.2 s of solves instead of 4.4-4.9
// (bench/RESULTS.md).
#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/errors.hpp"
#include "core/seconds_since.hpp"
#include "projection/poisson/amg_hierarchy.hpp"
#include "projection/poisson/poisson_solver.hpp"

namespace arksph {

namespace {

constexpr double kGrowth = 1.25;  // rebuild when iterations exceed this x the count after the last rebuild
constexpr int kMaxReuse = 25;     // ... or after this many solves
// A solve on a kept hierarchy is given up after kGiveUpAfter x the count after the last rebuild plus
// kGiveUpSlack iterations (or at a non-positive r.z), and done again on a new hierarchy.
constexpr double kGiveUpAfter = 3.0;
constexpr int kGiveUpSlack = 10;

class PoissonSolverAmgCg final : public PoissonSolver {
 public:
  explicit PoissonSolverAmgCg(double tolerance) : tolerance_(tolerance) {}
  std::string name() const override { return "cg_amg"; }

  // rep.refactored_symbolic: the hierarchy was (re)built for this solve.
  SolveReport solve(const SparseMatrix& A, const std::vector<double>& b, std::vector<double>& p) override {
    const CsrRef view = csr_view(A);
    const int n = view.n;
    if (p.size() != b.size()) p.assign(b.size(), 0.0);
    const bool rebuild = !amg_.ready() || amg_.size(0) != n || must_rebuild_ || solves_since_setup_ >= kMaxReuse;
    const auto t0 = std::chrono::steady_clock::now();
    sparsify(view, kPreconditionerDropBelow, sparse_);
    const CsrRef pre = sparse_.ref();
    SolveReport rep;
    if (!rebuild) {  // the kept hierarchy, given up on if it no longer preconditions this matrix
      amg_.rebind_finest(pre);
      start_.assign(p.begin(), p.end());
      rep.setup_seconds = seconds_since(t0);
      const int limit = static_cast<int>(kGiveUpAfter * baseline_) + kGiveUpSlack;
      if (pcg(view, b.data(), p.data(), rep.relative_residual, limit, rep.iterations)) {
        record(rep.iterations);
        return rep;
      }
      std::copy(start_.begin(), start_.end(), p.begin());
    }
    const auto t1 = rebuild ? t0 : std::chrono::steady_clock::now();
    amg_.setup(pre);
    solves_since_setup_ = 0;
    baseline_ = -1;
    must_rebuild_ = false;
    rep.setup_seconds += seconds_since(t1);
    rep.refactored_symbolic = true;
    int it = 0;
    pcg(view, b.data(), p.data(), rep.relative_residual, -1, it);
    rep.iterations += it;
    record(it);
    return rep;
  }

 private:
  void record(int iterations) {
    ++solves_since_setup_;
    if (baseline_ < 0) baseline_ = iterations;
    else if (iterations > std::max(kGrowth * baseline_, baseline_ + 2.0)) must_rebuild_ = true;  // +2: not on noise of small counts
  }

  // Preconditioned CG on A x = b from the guess in x, its iterations in `it`; returns whether it
  // converged. give_up >= 0: returns false (x then undefined) after that many iterations, or when
  // the preconditioner is found not positive; give_up < 0: throws on either (NumericalFailure).
  bool pcg(const CsrRef& A, const double* b, double* x, double& rel_residual, int give_up, int& it) {
    const int n = A.n;
    r_.resize(n);
    z_.resize(n);
    d_.resize(n);
    q_.resize(n);
    double* r = r_.data();
    double* z = z_.data();
    double* d = d_.data();
    double* q = q_.data();
    csr_residual(A, b, x, r);
    double nb2 = 0, rr = 0;
#pragma omp parallel for schedule(static) reduction(+ : nb2, rr) if (n > kSolverParallelMin)
    for (int i = 0; i < n; ++i) {
      nb2 += b[i] * b[i];
      rr += r[i] * r[i];
    }
    if (nb2 == 0) {  // zero source: the solution is zero (as Eigen's CG returns)
      std::fill(x, x + n, 0.0);
      rel_residual = 0;
      it = 0;
      return true;
    }
    const double target2 = tolerance_ * tolerance_ * nb2;
    const int max_it = give_up >= 0 ? give_up : std::max(200, n);
    it = 0;
    double rz = 0;
    while (rr > target2 && it < max_it) {
      amg_.vcycle(r, z);
      double rz_new = 0;
#pragma omp parallel for schedule(static) reduction(+ : rz_new) if (n > kSolverParallelMin)
      for (int i = 0; i < n; ++i) rz_new += r[i] * z[i];
      if (!(rz_new > 0)) {
        if (give_up >= 0) return false;
        throw NumericalFailure("cg_amg: preconditioner not positive definite");
      }
      const double beta = it == 0 ? 0.0 : rz_new / rz;
      rz = rz_new;
#pragma omp parallel for schedule(static) if (n > kSolverParallelMin)
      for (int i = 0; i < n; ++i) d[i] = z[i] + beta * d[i];
      csr_multiply(A, d, q);
      double dq = 0;
#pragma omp parallel for schedule(static) reduction(+ : dq) if (n > kSolverParallelMin)
      for (int i = 0; i < n; ++i) dq += d[i] * q[i];
      if (!(dq > 0)) throw NumericalFailure("cg_amg: matrix or preconditioner not positive definite");
      const double alpha = rz / dq;
      rr = 0;
#pragma omp parallel for schedule(static) reduction(+ : rr) if (n > kSolverParallelMin)
      for (int i = 0; i < n; ++i) {
        x[i] += alpha * d[i];
        r[i] -= alpha * q[i];
        rr += r[i] * r[i];
      }
      ++it;
    }
    // True residual (the recursive one drifts by round-off).
    csr_residual(A, b, x, q);
    double res = 0;
#pragma omp parallel for schedule(static) reduction(+ : res) if (n > kSolverParallelMin)
    for (int i = 0; i < n; ++i) res += q[i] * q[i];
    rel_residual = std::sqrt(res / nb2);
    if (rr > target2) {
      if (give_up >= 0) return false;
      SolveReport rep;
      rep.iterations = it;
      rep.relative_residual = rel_residual;
      throw_not_converged("cg_amg", tolerance_, rep);
    }
    return true;
  }

  double tolerance_;
  AmgHierarchy amg_;
  CsrOwned sparse_;  // the V-cycle's finest matrix (sparsify)
  int solves_since_setup_ = 0;
  int baseline_ = -1;
  bool must_rebuild_ = false;
  std::vector<double> r_, z_, d_, q_;
  std::vector<double> start_;  // the warm start of a solve on a kept hierarchy, for a second attempt
};

}  // namespace

std::unique_ptr<PoissonSolver> make_poisson_solver_cg_amg(double tolerance) {
  return std::make_unique<PoissonSolverAmgCg>(tolerance);
}

}  // namespace arksph
