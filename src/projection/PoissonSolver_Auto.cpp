// "auto": the Poisson solver chosen by size at the first solve. Up to kDirectMax unknowns KLU (exact,
// and a factorisation is cheap there); above, warm-started Jacobi CG, which on the SPH Laplacian
// (about 48 non-zeros a row) beats every direct and incomplete-Cholesky option measured
// (TOOLCHAIN.md §4; bench/README.md: BM_Solve at N = 2,500 ... 250,000).
#include "projection/poisson_solver.hpp"

namespace arksph {

std::unique_ptr<PoissonSolver> make_poisson_solver_klu();
std::unique_ptr<PoissonSolver> make_poisson_solver_cg(double tolerance);

class PoissonSolverAuto final : public PoissonSolver {
 public:
  static constexpr long kDirectMax = 1000;
  explicit PoissonSolverAuto(double tolerance) : tolerance_(tolerance) {}
  std::string name() const override { return "auto"; }
  SolveReport solve(const SparseMatrix& A, const std::vector<double>& b, std::vector<double>& p) override {
    if (!chosen_) chosen_ = A.rows() <= kDirectMax ? make_poisson_solver_klu() : make_poisson_solver_cg(tolerance_);
    return chosen_->solve(A, b, p);
  }

 private:
  double tolerance_;
  std::unique_ptr<PoissonSolver> chosen_;
};

std::unique_ptr<PoissonSolver> make_poisson_solver_auto(double tolerance) {
  return std::make_unique<PoissonSolverAuto>(tolerance);
}

}  // namespace arksph
