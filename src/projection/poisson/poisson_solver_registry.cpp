// Poisson solvers by name: one line each.
#include <cstdio>

#include "core/errors.hpp"
#include "core/param_builder.hpp"
#include "projection/poisson/poisson_solver.hpp"

namespace arksph {

std::unique_ptr<PoissonSolver> make_poisson_solver_klu();
std::unique_ptr<PoissonSolver> make_poisson_solver_cg(double tolerance);
std::unique_ptr<PoissonSolver> make_poisson_solver_cg_ic(double tolerance);
std::unique_ptr<PoissonSolver> make_poisson_solver_cg_amg(double tolerance);
std::unique_ptr<PoissonSolver> make_poisson_solver_auto(double tolerance);

const Registry<PoissonSolverFactory>& poisson_solvers() {
  static const Registry<PoissonSolverFactory> r("ppe_solver", "method.ppe_solver", {
      {"klu", "SuiteSparse KLU, AMD ordering: the exact direct solve", [](double) { return make_poisson_solver_klu(); }},
      {"cg", "conjugate gradients with a Jacobi preconditioner, warm-started", make_poisson_solver_cg},
      {"cg_ic", "conjugate gradients with an incomplete-Cholesky preconditioner, warm-started", make_poisson_solver_cg_ic},
      {"cg_amg", "conjugate gradients preconditioned by one V-cycle of smoothed-aggregation AMG", make_poisson_solver_cg_amg},
      {"auto", "KLU up to 400 unknowns, cg_amg above (KLU for the exact operator)", make_poisson_solver_auto},
  }, {number("method.ppe_tolerance", 1e-10).in(between(1e-15, 1, false, true))
          .doc("relative residual at which the iterative Poisson solvers stop (not reached within their "
               "iteration limit: exit 3); below 1e-15 it is under the round-off of the residual").to(&Scene::ppe_tolerance)});
  return r;
}

void throw_not_converged(const std::string& solver, double tolerance, const SolveReport& reached) {
  char text[256];
  std::snprintf(text, sizeof text,
                "%s: the pressure Poisson equation did not reach method.ppe_tolerance = %.3g in %d iterations "
                "(relative residual %.3g); raise method.ppe_tolerance or use method.ppe_solver = \"klu\"",
                solver.c_str(), tolerance, reached.iterations, reached.relative_residual);
  throw NumericalFailure(text);
}

std::string exact_operator_solver(const std::string& requested) {
  if (requested == "auto") return "klu";
  return requested == "klu" ? requested : std::string();
}

std::vector<std::string> poisson_solver_names() { return poisson_solvers().names(); }

std::unique_ptr<PoissonSolver> make_poisson_solver(const std::string& name, double tolerance) {
  return poisson_solvers().at(name).make(tolerance);
}

}  // namespace arksph
