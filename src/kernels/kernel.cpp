#include "kernels/kernel.hpp"

#include <cmath>

namespace arksph {

namespace {
template <class Shape>
void shape_constants(int dimension, double& sigma, double& support) {
  sigma = Shape::sigma(dimension);
  support = Shape::support();
}
}  // namespace

Kernel::Kernel(std::string name, KernelShapeId shape, double h, int dimension)
    : name_(std::move(name)), shape_(shape), h_(h), inv_h_(1.0 / h), dim_(dimension) {
  double sigma = 0, support = 0;
  switch (shape) {
    case KernelShapeId::cubic_spline: shape_constants<CubicSpline>(dimension, sigma, support); break;
    case KernelShapeId::quartic_spline: shape_constants<QuarticSpline>(dimension, sigma, support); break;
    case KernelShapeId::wendland_quintic: shape_constants<WendlandQuintic>(dimension, sigma, support); break;
    case KernelShapeId::quintic_spline: shape_constants<QuinticSpline>(dimension, sigma, support); break;
  }
  norm_ = sigma / std::pow(h, dimension);
  norm_inv_h2_ = norm_ * inv_h_ * inv_h_;
  radius_ = support * h;
}

}  // namespace arksph
