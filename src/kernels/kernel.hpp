// Smoothing kernels W(r, h) = sigma_d / h^d * f(q), q = r / h, with compact support q <= q_max.
// Each kernel shape lives in its own file and is registered by name in kernel_registry.cpp.
#pragma once
#include <memory>
#include <string>
#include <vector>

namespace arksph {

// The dimensionless shape f(q) and its derivative df/dq, before normalisation.
struct KernelShape {
  virtual ~KernelShape() = default;
  virtual double support() const = 0;        // q_max: f(q) = 0 for q >= q_max
  virtual double sigma(int dimension) const = 0;  // normalisation so that the integral of W is 1
  virtual void eval(double q, double& f, double& dfdq) const = 0;
};

// A shape bound to a smoothing length and a dimension: the object the right-hand side uses.
class Kernel {
 public:
  Kernel(std::string name, std::shared_ptr<const KernelShape> shape, double h, int dimension);
  const std::string& name() const { return name_; }
  double h() const { return h_; }
  int dimension() const { return dim_; }
  double radius() const { return radius_; }  // support radius q_max * h
  double W(double r) const;
  double dWdr(double r) const;
  // Both at once: w = W(r), f = (dW/dr) / r, so that grad_a W_ab = f * r_ab (f = 0 at r = 0).
  void eval(double r, double& w, double& f_over_r) const {
    double fq, dfq;
    shape_->eval(r * inv_h_, fq, dfq);
    w = norm_ * fq;
    f_over_r = r > 0 ? norm_ * inv_h_ * dfq / r : 0.0;
  }

 private:
  std::string name_;
  std::shared_ptr<const KernelShape> shape_;
  double h_, inv_h_, norm_, radius_;
  int dim_;
};

// Registry: names in registration order, and construction by name (throws std::out_of_range).
std::vector<std::string> kernel_names();
Kernel make_kernel(const std::string& name, double h, int dimension);

}  // namespace arksph
