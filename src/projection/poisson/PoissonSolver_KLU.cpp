// Direct solve of the pressure Poisson equation by SuiteSparse KLU (AMD ordering, no BTF).
#include <klu.h>

#include <chrono>
#include <cmath>
#include <stdexcept>

#include "core/errors.hpp"
#include "core/seconds_since.hpp"
#include "projection/poisson/poisson_solver.hpp"

namespace arksph {

class PoissonSolverKlu final : public PoissonSolver {
 public:
  PoissonSolverKlu() {
    klu_defaults(&common_);
    common_.ordering = 0;  // AMD: faster than COLAMD on SPH Laplacians (less fill)
    common_.btf = 0;
  }
  ~PoissonSolverKlu() override { release(); }
  std::string name() const override { return "klu"; }

  SolveReport solve(const SparseMatrix& A, const std::vector<double>& b, std::vector<double>& p) override {
    SolveReport rep;
    const auto t0 = std::chrono::steady_clock::now();
    const int n = static_cast<int>(A.rows());
    const bool same_pattern = symbolic_ && n == n_ && pattern_equal(A);
    if (!same_pattern) {
      release();
      col_.assign(A.outerIndexPtr(), A.outerIndexPtr() + n + 1);
      row_.assign(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
      n_ = n;
      symbolic_ = klu_analyze(n, col_.data(), row_.data(), &common_);
      if (!symbolic_) throw std::runtime_error("KLU analyze failed (status " + std::to_string(common_.status) + ")");
      rep.refactored_symbolic = true;
    }
    double* values = const_cast<double*>(A.valuePtr());
    if (numeric_ && same_pattern) {
      if (!klu_refactor(col_.data(), row_.data(), values, symbolic_, numeric_, &common_))
        throw NumericalFailure("KLU refactor failed (singular pressure matrix?) (status " + std::to_string(common_.status) + ")");
    } else {
      if (numeric_) klu_free_numeric(&numeric_, &common_);
      numeric_ = klu_factor(col_.data(), row_.data(), values, symbolic_, &common_);
      if (!numeric_) throw NumericalFailure("KLU factor failed (singular pressure matrix?) (status " + std::to_string(common_.status) + ")");
    }
    rep.setup_seconds = seconds_since(t0);
    p = b;
    if (!klu_solve(symbolic_, numeric_, n, 1, p.data(), &common_))
      throw NumericalFailure("KLU solve failed (status " + std::to_string(common_.status) + ")");
    rep.iterations = 1;
    rep.relative_residual = residual(A, b, p);
    return rep;
  }

 private:
  static double residual(const SparseMatrix& A, const std::vector<double>& b, const std::vector<double>& p) {
    const Eigen::Map<const Eigen::VectorXd> bb(b.data(), static_cast<long>(b.size()));
    const Eigen::Map<const Eigen::VectorXd> pp(p.data(), static_cast<long>(p.size()));
    const double nb = bb.norm();
    return nb > 0 ? (A * pp - bb).norm() / nb : (A * pp).norm();
  }
  bool pattern_equal(const SparseMatrix& A) const {
    if (static_cast<std::size_t>(A.nonZeros()) != row_.size()) return false;
    for (int j = 0; j <= n_; ++j)
      if (A.outerIndexPtr()[j] != col_[j]) return false;
    for (std::size_t k = 0; k < row_.size(); ++k)
      if (A.innerIndexPtr()[k] != row_[k]) return false;
    return true;
  }
  void release() {
    if (numeric_) klu_free_numeric(&numeric_, &common_);
    if (symbolic_) klu_free_symbolic(&symbolic_, &common_);
    numeric_ = nullptr;
    symbolic_ = nullptr;
  }
  klu_common common_{};
  klu_symbolic* symbolic_ = nullptr;
  klu_numeric* numeric_ = nullptr;
  std::vector<int> col_, row_;
  int n_ = 0;
};

std::unique_ptr<PoissonSolver> make_poisson_solver_klu() { return std::make_unique<PoissonSolverKlu>(); }

}  // namespace arksph
