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
//
// The correction acts on a ParticleDomain (projection/particle_domain.hpp): one process's, or one
// rank's particles with their halo, where sums run over every rank, p* reaches the halo copies from
// their owners before a pair loop reads it, and the fixed point's Poisson problem is the
// projection's back-end (hypre's rows with global numbers on ranks). Every rank takes the same
// iterations and the same decisions. KINSOL runs on one process only.
#pragma once
#include <memory>
#include <vector>

#include "core/registry.hpp"
#include "core/scene.hpp"
#include "projection/correction/correction_solver.hpp"
#include "projection/particle_domain.hpp"

namespace arksph {

// method.density_correction: "none" | "pozorski_wawrenczuk", with the correction's parameters.
const Registry<Selected>& density_corrections();

struct CorrectionStats {
  long applications = 0;   // steps in which it ran
  long iterations = 0;     // Poisson solves (Newton iterations)
  double seconds = 0;
  std::vector<double> first_history;  // r.m.s. relative density error before each iteration of the first application, and after the last
};

class DensityCorrection {
 public:
  DensityCorrection(const Scene& scene, ParticleDomain& domain);
  // Corrects the positions in y (the end of a step, time t) in place. Collective on ranks.
  void apply(double t, double* y);
  // applications, iterations and first_history are global (the same on every rank), seconds this rank's.
  const CorrectionStats& stats() const { return stats_; }
  // The particles re-ordered: the warm start p* follows (new index i is old index from[i]).
  void permute_particles(const std::vector<std::uint32_t>& from);
  // Drops the warm start and the solver's set-up (a restart, or the particles moved to other ranks).
  void forget_warm_start();

 private:
  ParticleDomain& domain_;
  std::unique_ptr<CorrectionSolver> solver_;  // method.correction_solver
  double threshold_;
  CorrectionStats stats_;
};

}  // namespace arksph
