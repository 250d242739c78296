// Names registered by the numerical modules, grouped by family, for validation and `arksph list`.
// Families: "kernel", "scheme", "viscosity_model", "density_mode", "pressure_gradient",
// "density_correction", "erk_table".
#pragma once
#include <string>
#include <vector>

namespace arksph {

std::vector<std::string> registered_names(const std::string& family);
bool is_registered(const std::string& family, const std::string& name);

}  // namespace arksph
