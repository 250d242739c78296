// Pozorski-Wawrenczuk position correction, Szewc et al. 2012 §9 (eqs. 57-59).
//
// After the projection, the summation density (Szewc eq. 21) rho~_a = m_a sum_b W_ab drifts from
// rho0. Positions are shifted by r_a <- r_a - grad p*_a / rho0 (eq. 57), with p* from
//   (1/rho0) div((rho^n/rho0) grad p*) = 1 - rho~_a/rho0                          (eq. 58).
// Discretised with the approximate Laplacian of C&R eq. 19 at rho^n = rho0 (so the left side is
// L(p*) of ppe_assembly.hpp), the mean of the source removed (a closed box cannot change its mean
// density by moving particles), ghosts carrying their source's p* (Neumann walls), and the
// gradient in difference form sum_b V_b (p*_b - p*_a) grad_a W_ab, which vanishes for constant p*.
// Applied when the r.m.s. relative density error exceeds a threshold, up to a number of iterations
// per step (Szewc apply it once per step).
#pragma once
#include <memory>
#include <vector>

#include "core/registry.hpp"
#include "core/scene.hpp"
#include "projection/correction/position_correction.hpp"
#include "projection/poisson/poisson_solver.hpp"
#include "rhs/evaluator.hpp"

namespace arksph {

// method.density_correction: "none" | "pozorski_wawrenczuk", with the correction's parameters.
const Registry<Selected>& density_corrections();
// method.correction_solver: how the correction's Poisson problem is solved.
const Registry<Selected>& correction_solvers();

class DensityCorrection : public PositionCorrection {
 public:
  DensityCorrection(const Scene& scene, RhsEvaluator& rhs);
  void apply(double t, double* y) override;
  const CorrectionStats& stats() const override { return stats_; }
  void permute_particles(const std::vector<std::uint32_t>& from) override;
  void forget_warm_start() override {
    pstar_.clear();
    solver_ = make_poisson_solver(solver_->name(), tolerance_);
  }

 private:
  double density_error(double t, const double* y);  // refreshes fields; r.m.s. of rho~/rho0 about its mean
  RhsEvaluator& rhs_;
  std::unique_ptr<PoissonSolver> solver_;
  double tolerance_;
  double threshold_;
  int max_iterations_;
  bool use_kinsol_;
  bool use_newton_;
  double spacing_;
  std::vector<double> pstar_;
  CorrectionStats stats_;
};

}  // namespace arksph
