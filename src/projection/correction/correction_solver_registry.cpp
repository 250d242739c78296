// The P-W correction's solvers by name: one line each.
#include "projection/correction/correction_solver.hpp"

namespace arksph {

std::unique_ptr<CorrectionSolver> make_correction_fixed_point(const Scene& scene, ParticleDomain& domain);
std::unique_ptr<CorrectionSolver> make_correction_kinsol(const Scene& scene, ParticleDomain& domain);
std::unique_ptr<CorrectionSolver> make_correction_newton(const Scene& scene, ParticleDomain& domain);

const Registry<CorrectionSolverFactory>& correction_solvers() {
  static const Registry<CorrectionSolverFactory> r("correction_solver", "method.correction_solver", {
      {"fixed_point", "repeated linear solves of Szewc et al. 2012 eq. 58", make_correction_fixed_point},
      {"kinsol", "KINSOL Newton on eq. 59 with the Laplacian as frozen Jacobian (KLU)", make_correction_kinsol, {},
       {.one_process = true}},
      {"newton", "Newton with the exact Jacobian of the summation density", make_correction_newton},
  });
  return r;
}

}  // namespace arksph
