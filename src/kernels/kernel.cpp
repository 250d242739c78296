#include "kernels/kernel.hpp"

#include <cmath>

namespace arksph {

Kernel::Kernel(std::string name, std::shared_ptr<const KernelShape> shape, double h, int dimension)
    : name_(std::move(name)), shape_(std::move(shape)), h_(h), inv_h_(1.0 / h), dim_(dimension) {
  norm_ = shape_->sigma(dimension) / std::pow(h, dimension);
  radius_ = shape_->support() * h;
}

double Kernel::W(double r) const {
  double f, df;
  shape_->eval(r * inv_h_, f, df);
  return norm_ * f;
}

double Kernel::dWdr(double r) const {
  double f, df;
  shape_->eval(r * inv_h_, f, df);
  return norm_ * inv_h_ * df;
}

}  // namespace arksph
