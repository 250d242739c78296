// Poisson solvers by name: one line each.
#include <stdexcept>

#include "projection/poisson_solver.hpp"

namespace arksph {

std::unique_ptr<PoissonSolver> make_poisson_solver_klu();
std::unique_ptr<PoissonSolver> make_poisson_solver_cg(double tolerance);
std::unique_ptr<PoissonSolver> make_poisson_solver_cg_ic(double tolerance);
std::unique_ptr<PoissonSolver> make_poisson_solver_cg_amg(double tolerance);
std::unique_ptr<PoissonSolver> make_poisson_solver_auto(double tolerance);

std::vector<std::string> poisson_solver_names() { return {"klu", "cg", "cg_ic", "cg_amg", "auto"}; }

std::unique_ptr<PoissonSolver> make_poisson_solver(const std::string& name, double tolerance) {
  if (name == "klu") return make_poisson_solver_klu();
  if (name == "cg") return make_poisson_solver_cg(tolerance);
  if (name == "cg_ic") return make_poisson_solver_cg_ic(tolerance);
  if (name == "cg_amg") return make_poisson_solver_cg_amg(tolerance);
  if (name == "auto") return make_poisson_solver_auto(tolerance);  // by size: KLU up to 400 unknowns, else cg_amg
  throw std::out_of_range("unknown Poisson solver '" + name + "'");
}

}  // namespace arksph
