// Smoothing kernels W(r, h) = sigma_d / h^d * f(q), q = r / h, with compact support q < q_max.
// Each shape lives in its own header (the file names cite the source) and is registered by name in
// kernel_registry.cpp. Kernel::eval dispatches on the shape with a switch that the compiler hoists
// out of pair loops, so the shape's polynomial is inlined.
#pragma once
#include <string>
#include <vector>

#include "kernels/CubicSpline_Monaghan.hpp"
#include "kernels/QuarticSpline_CumminsRudman1999.hpp"
#include "kernels/QuinticSpline_Morris1997.hpp"
#include "kernels/WendlandQuintic_Wendland1995.hpp"

namespace arksph {

enum class KernelShapeId { cubic_spline, quartic_spline, wendland_quintic, quintic_spline };

// A shape bound to a smoothing length and a dimension: the object the right-hand side uses.
class Kernel {
 public:
  Kernel(std::string name, KernelShapeId shape, double h, int dimension);
  const std::string& name() const { return name_; }
  double h() const { return h_; }
  int dimension() const { return dim_; }
  double radius() const { return radius_; }  // support radius q_max * h
  double W(double r) const {
    double w, f;
    eval(r, w, f);
    return w;
  }
  double dWdr(double r) const {
    double fq, dfq;
    shape(r * inv_h_, fq, dfq);
    return norm_ * inv_h_ * dfq;
  }
  // d2W/dr2 (Basa et al. 2008 eq. 28 needs it for the direct second derivatives of model A).
  double d2Wdr2(double r) const {
    const double q = r * inv_h_;
    double d2 = 0.0;
    switch (shape_) {
      case KernelShapeId::cubic_spline: d2 = CubicSpline::d2(q); break;
      case KernelShapeId::quartic_spline: d2 = QuarticSpline::d2(q); break;
      case KernelShapeId::wendland_quintic: d2 = WendlandQuintic::d2(q); break;
      case KernelShapeId::quintic_spline: d2 = QuinticSpline::d2(q); break;
    }
    return norm_ * inv_h_ * inv_h_ * d2;
  }
  // Both at once: w = W(r), f = (dW/dr) / r, so that grad_a W_ab = f * r_ab (f = 0 at r = 0).
  void eval(double r, double& w, double& f_over_r) const {
    double fq, dfq;
    shape(r * inv_h_, fq, dfq);
    w = norm_ * fq;
    f_over_r = r > 0 ? norm_ * inv_h_ * dfq / r : 0.0;
  }

 private:
  void shape(double q, double& f, double& df) const {
    switch (shape_) {
      case KernelShapeId::cubic_spline: return CubicSpline::eval(q, f, df);
      case KernelShapeId::quartic_spline: return QuarticSpline::eval(q, f, df);
      case KernelShapeId::wendland_quintic: return WendlandQuintic::eval(q, f, df);
      case KernelShapeId::quintic_spline: return QuinticSpline::eval(q, f, df);
    }
    f = df = 0.0;
  }
  std::string name_;
  KernelShapeId shape_;
  double h_, inv_h_, norm_, radius_;
  int dim_;
};

// Registry: names in registration order, and construction by name (throws std::out_of_range).
std::vector<std::string> kernel_names();
Kernel make_kernel(const std::string& name, double h, int dimension);

}  // namespace arksph
