// Kernels by name: one line each. Scene files use these strings.
#include <stdexcept>
#include <utility>

#include "kernels/kernel.hpp"

namespace arksph {
namespace {
const std::vector<std::pair<std::string, KernelShapeId>>& kernel_table() {
  static const std::vector<std::pair<std::string, KernelShapeId>> table = {
      {"cubic_spline", KernelShapeId::cubic_spline},          // C&R eq. 5, Szewc eq. 5
      {"quartic_spline", KernelShapeId::quartic_spline},      // C&R eq. 6
      {"wendland_quintic", KernelShapeId::wendland_quintic},  // Szewc eq. 6
      {"quintic_spline", KernelShapeId::quintic_spline},      // Szewc eq. 7
  };
  return table;
}
}  // namespace

std::vector<std::string> kernel_names() {
  std::vector<std::string> names;
  for (const auto& entry : kernel_table()) names.push_back(entry.first);
  return names;
}

Kernel make_kernel(const std::string& name, double h, int dimension) {
  for (const auto& [n, id] : kernel_table())
    if (n == name) return Kernel(n, id, h, dimension);
  throw std::out_of_range("unknown kernel '" + name + "'");
}

}  // namespace arksph
