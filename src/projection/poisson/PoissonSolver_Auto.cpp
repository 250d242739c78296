// "auto": the Poisson solver chosen by size at the first solve. Up to kDirectMax unknowns KLU (exact;
// at that size the AMG hierarchy of cg_amg would be a single dense Cholesky level anyway, and both
// take well under 10 ms a step); above, CG preconditioned by aggregation AMG ("cg_amg"), which on
// the running Re = 1000 cavity beats KLU from N = 400 up and Jacobi CG at every size measured
// (N = 900: 2.1 ms a solve against 26 ms KLU and 8.4 ms Jacobi CG; N = 3,600: 9 iterations against
// 160; bench/RESULTS.md).
#include "projection/poisson/poisson_solver.hpp"

namespace arksph {

std::unique_ptr<PoissonSolver> make_poisson_solver_klu();
std::unique_ptr<PoissonSolver> make_poisson_solver_cg_amg(double tolerance);

class PoissonSolverAuto final : public PoissonSolver {
 public:
  static constexpr long kDirectMax = 400;
  explicit PoissonSolverAuto(double tolerance) : tolerance_(tolerance) {}
  std::string name() const override { return "auto"; }
  SolveReport solve(const SparseMatrix& A, const std::vector<double>& b, std::vector<double>& p) override {
    if (!chosen_) chosen_ = A.rows() <= kDirectMax ? make_poisson_solver_klu() : make_poisson_solver_cg_amg(tolerance_);
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
