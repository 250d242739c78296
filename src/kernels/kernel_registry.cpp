// Kernels by name: one line each. Scene files use these strings.
#include <functional>
#include <stdexcept>
#include <utility>

#include "kernels/kernel_shapes.hpp"

namespace arksph {
namespace {
using ShapeFactory = std::shared_ptr<const KernelShape> (*)();
const std::vector<std::pair<std::string, ShapeFactory>>& kernel_table() {
  static const std::vector<std::pair<std::string, ShapeFactory>> table = {
      {"cubic_spline", make_cubic_spline},          // C&R eq. 5, Szewc eq. 5
      {"quartic_spline", make_quartic_spline},      // C&R eq. 6
      {"wendland_quintic", make_wendland_quintic},  // Szewc eq. 6
      {"quintic_spline", make_quintic_spline},      // Szewc eq. 7
  };
  return table;
}
}  // namespace

std::vector<std::string> kernel_names() {
  std::vector<std::string> names;
  for (const auto& [name, factory] : kernel_table()) names.push_back(name);
  return names;
}

Kernel make_kernel(const std::string& name, double h, int dimension) {
  for (const auto& [n, factory] : kernel_table())
    if (n == name) return Kernel(n, factory(), h, dimension);
  throw std::out_of_range("unknown kernel '" + name + "'");
}

}  // namespace arksph
