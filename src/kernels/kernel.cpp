#include "kernels/kernel.hpp"

#include <cmath>
#include <stdexcept>

namespace arksph {

Kernel::Kernel(std::string name, int shape, double h, int dimension)
    : name_(std::move(name)), shape_(shape), h_(h), inv_h_(1.0 / h), dim_(dimension) {
  double sigma = 0, support = 0;
  with_shape(KernelShapes{}, shape, [&]<class S>() {
    sigma = S::sigma(dimension);
    support = S::support();
  });
  norm_ = sigma / std::pow(h, dimension);
  norm_inv_h2_ = norm_ * inv_h_ * inv_h_;
  radius_ = support * h;
}

std::vector<std::string> kernel_names() {
  std::vector<std::string> names;
  for (const auto& [name, summary] : kernel_summaries()) names.push_back(name);
  return names;
}

std::vector<std::pair<std::string, std::string>> kernel_summaries() {
  std::vector<std::pair<std::string, std::string>> out;
  for (int i = 0; i < KernelShapes::size; ++i)
    with_shape(KernelShapes{}, i, [&]<class S>() { out.emplace_back(S::name, S::summary); });
  return out;
}

Kernel make_kernel(const std::string& name, double h, int dimension) {
  const auto names = kernel_names();
  for (int i = 0; i < static_cast<int>(names.size()); ++i)
    if (names[i] == name) return Kernel(name, i, h, dimension);
  throw std::out_of_range("unknown kernel '" + name + "'");
}

}  // namespace arksph
