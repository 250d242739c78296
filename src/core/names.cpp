// Registered names by family, gathered from the modules that own them.
#include "core/names.hpp"

#include <algorithm>

#include "integrate/erk_integrator.hpp"
#include "integrate/imex_integrator.hpp"
#include "kernels/kernel.hpp"
#include "projection/poisson_solver.hpp"
#include "rhs/terms.hpp"

namespace arksph {

std::vector<std::string> registered_names(const std::string& family) {
  if (family == "kernel") return kernel_names();
  if (family == "scheme") return {"wcsph", "isph", "isph-gpps"};
  if (family == "ppe_solver") return poisson_solver_names();
  if (family == "viscosity_model") return viscosity_model_names();
  if (family == "density_mode") return {"continuity", "summation"};
  // boundary.wall_velocity: the tangential velocity of no-slip ghosts (boundary/ghosts.hpp: mirror;
  // boundary/WallVelocity_Linear_Basa2008.hpp, boundary/WallVelocity_Quadratic_Basa2008.hpp)
  if (family == "wall_velocity") return {"mirror", "linear", "quadratic"};
  if (family == "pressure_gradient") return pressure_gradient_names();
  if (family == "equation_of_state") return {"tait", "ideal_gas"};
  if (family == "kernel_correction") return kernel_correction_names();
  if (family == "density_correction") return {"none", "pozorski_wawrenczuk"};
  if (family == "erk_table") return erk_table_names();
  if (family == "imex_pair") return imex_pair_names();
  return {};
}

bool is_registered(const std::string& family, const std::string& name) {
  const auto names = registered_names(family);
  return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace arksph
