// The P-W correction's solvers by name: one line each.
#include "projection/correction/correction_solver.hpp"

namespace arksph {

std::unique_ptr<CorrectionSolver> make_correction_fixed_point(const Scene& scene, ParticleDomain& domain);
std::unique_ptr<CorrectionSolver> make_correction_kinsol(const Scene& scene, ParticleDomain& domain);
std::unique_ptr<CorrectionSolver> make_correction_newton(const Scene& scene, ParticleDomain& domain);

namespace {
// method.correction_solver = "auto": newton. With fixed steps of Szewc's single linear solve the
// density error grows wherever a step moves particles by more than one solve removes; the exact
// Jacobian removes most of it in one iteration. Measured at t = 10 on the spin-down: CV 0.0012
// against 0.0080 (C&R's set-up), 0.00037 against 0.013 (the project's defaults). Szewc's fixed
// point stays selectable and is what the paper cases use.
std::string automatic_correction_solver(const Scene&, const SelectedParts&) { return "newton"; }
}  // namespace

const Registry<CorrectionSolverFactory>& correction_solvers() {
  static const Registry<CorrectionSolverFactory> r("correction_solver", "method.correction_solver", {
      {"fixed_point", "repeated linear solves of Szewc et al. 2012 eq. 58", make_correction_fixed_point},
      {"kinsol", "KINSOL Newton on eq. 59 with the Laplacian as frozen Jacobian (KLU)", make_correction_kinsol, {},
       {.one_process = true}},
      {"newton", "Newton with the exact Jacobian of the summation density", make_correction_newton},
  }, {}, {"newton", automatic_correction_solver});
  return r;
}

}  // namespace arksph
