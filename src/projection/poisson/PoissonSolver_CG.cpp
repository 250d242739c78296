// Iterative solve of the pressure Poisson equation: Eigen conjugate gradients, warm-started from the
// previous pressure (the caller's p), with a Jacobi ("cg") or incomplete-Cholesky ("cg_ic")
// preconditioner. On SPH Laplacians of a few thousand unknowns the Jacobi version is the fastest:
// the incomplete factorisation costs more than the iterations it saves.
#include <Eigen/IterativeLinearSolvers>

#include <stdexcept>

#include "core/errors.hpp"
#include "projection/poisson/poisson_solver.hpp"

namespace arksph {

template <class Preconditioner>
class PoissonSolverCg final : public PoissonSolver {
 public:
  PoissonSolverCg(std::string name, double tolerance) : name_(std::move(name)), tolerance_(tolerance) {}
  std::string name() const override { return name_; }

  SolveReport solve(const SparseMatrix& A, const std::vector<double>& b, std::vector<double>& p) override {
    using Vec = Eigen::Map<Eigen::VectorXd>;
    Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper, Preconditioner> cg;
    cg.setTolerance(tolerance_);
    cg.setMaxIterations(std::max<long>(200, 4 * A.rows()));
    cg.compute(A);
    if (cg.info() != Eigen::Success) throw NumericalFailure(name_ + ": preconditioner failed");
    const Eigen::Map<const Eigen::VectorXd> bb(b.data(), static_cast<long>(b.size()));
    if (p.size() != b.size()) p.assign(b.size(), 0.0);
    Vec pp(p.data(), static_cast<long>(p.size()));
    const Eigen::VectorXd guess = pp;
    pp = cg.solveWithGuess(bb, guess);
    SolveReport rep;
    rep.iterations = static_cast<int>(cg.iterations());
    const double nb = bb.norm();
    rep.relative_residual = nb > 0 ? (A * pp - bb).norm() / nb : 0.0;
    if (cg.info() != Eigen::Success) throw_not_converged(name_, tolerance_, rep);
    return rep;
  }

 private:
  std::string name_;
  double tolerance_;
};

std::unique_ptr<PoissonSolver> make_poisson_solver_cg(double tolerance) {
  return std::make_unique<PoissonSolverCg<Eigen::DiagonalPreconditioner<double>>>("cg", tolerance);
}

std::unique_ptr<PoissonSolver> make_poisson_solver_cg_ic(double tolerance) {
  return std::make_unique<PoissonSolverCg<Eigen::IncompleteCholesky<double>>>("cg_ic", tolerance);
}

}  // namespace arksph
