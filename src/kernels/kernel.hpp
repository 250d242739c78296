// Smoothing kernels W(r, h) = sigma_d / h^d * f(q), q = r / h, with compact support q < q_max.
// Each shape lives in its own header (the file names cite the source) and is registered by one
// entry in kernels/kernel_shapes.hpp. Kernel dispatches on the shape's index in that list once per
// call (with_shape), so that the shape's polynomial is inlined in the loops.
#pragma once
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "kernels/kernel_shapes.hpp"

namespace arksph {

// Calls f.template operator()<Shape>() for the shape at `index` of the list.
template <class... Shapes, class F>
inline void with_shape(ShapeList<Shapes...>, int index, F&& f) {
  int k = 0;
  (void)((k++ == index ? (f.template operator()<Shapes>(), true) : false) || ...);
}
// A shape bound to a smoothing length and a dimension: the object the right-hand side uses.
class Kernel {
 public:
  // `shape`: the index of the shape in KernelShapes.
  Kernel(std::string name, int shape, double h, int dimension);
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
    with_shape(KernelShapes{}, shape_, [&]<class S>() { d2 = S::d2(q); });
    return norm_ * inv_h_ * inv_h_ * d2;
  }
  // Both at once: w = W(r), f = (dW/dr) / r, so that grad_a W_ab = f * r_ab (f = 0 at r = 0).
  // With q = r / h: (dW/dr) / r = norm / h^2 * f'(q) / q.
  void eval(double r, double& w, double& f_over_r) const {
    double fq, dfq_over_q;
    shape_over_q(r * inv_h_, fq, dfq_over_q);
    w = norm_ * fq;
    f_over_r = r > 0 ? norm_inv_h2_ * dfq_over_q : 0.0;
  }

 private:
  void shape(double q, double& f, double& df) const {
    f = df = 0.0;  // for the compiler: with_shape always calls one shape
    with_shape(KernelShapes{}, shape_, [&]<class S>() { S::eval(q, f, df); });
  }
  // f(q) and f'(q) / q (without a division where the shape provides eval_over_q).
  void shape_over_q(double q, double& f, double& df_over_q) const {
    f = df_over_q = 0.0;  // for the compiler: with_shape always calls one shape
    with_shape(KernelShapes{}, shape_, [&]<class S>() { over_q<S>(q, f, df_over_q); });
  }

 public:
  // W and (dW/dr)/r for n squared distances (r2[i] -> w[i], f[i]; f may alias r2), the shape chosen
  // once outside the loop so that the loop body is one inlined polynomial (the pair-list hot path).
  // Same values as eval(sqrt(r2[i]), ...).
  // One squared distance, bit-identical to eval_many (the lean pair storage relies on it).
  void eval_r2(double r2, double& w, double& f) const { eval_many(1, &r2, &w, &f); }
  // The same from separations (rx[i], ry[i]) -> r2 = rx^2 + ry^2; w null: (dW/dr)/r only.
  void eval_many_xy(std::size_t n, const double* rx, const double* ry, double* w, double* f) const {
    if (w)
      eval_many_xy_with<true>(n, rx, ry, w, f);
    else
      eval_many_xy_with<false>(n, rx, ry, w, f);
  }
  void eval_many(std::size_t n, const double* r2, double* w, double* f) const {
    with_shape(KernelShapes{}, shape_, [&]<class S>() { eval_many_as<S>(n, r2, w, f); });
  }

 private:
  template <class Shape>
  static void over_q(double q, double& fq, double& g) {
    if constexpr (requires { Shape::eval_over_q(q, fq, g); }) {
      Shape::eval_over_q(q, fq, g);
    } else {
      double df;
      Shape::eval(q, fq, df);
      g = q > 0 ? df / q : 0.0;
    }
  }
  template <class Shape, bool with_w>
  void eval_many_xy_as(std::size_t n, const double* rx, const double* ry, double* w, double* f) const {
    const double inv_h = inv_h_, norm = norm_, norm_inv_h2 = norm_inv_h2_;
    // As eval_many_as, with r2 = rx^2 + ry^2 computed here (the operations of every pair loop).
#pragma omp simd
    for (std::size_t i = 0; i < n; ++i) {
      const double rr = rx[i] * rx[i] + ry[i] * ry[i];
      double fq, g;
      over_q<Shape>(std::sqrt(rr) * inv_h, fq, g);
      if constexpr (with_w) w[i] = norm * fq;
      f[i] = rr > 0 ? norm_inv_h2 * g : 0.0;
    }
  }
  template <bool with_w>
  void eval_many_xy_with(std::size_t n, const double* rx, const double* ry, double* w, double* f) const {
    with_shape(KernelShapes{}, shape_, [&]<class S>() { eval_many_xy_as<S, with_w>(n, rx, ry, w, f); });
  }
  template <class Shape>
  void eval_many_as(std::size_t n, const double* r2, double* w, double* f) const {
    const double inv_h = inv_h_, norm = norm_, norm_inv_h2 = norm_inv_h2_;
    // Element-wise (f may alias r2 only index for index): vectorised, sqrt included; the
    // arithmetic of each element is that of the scalar loop, so the values are the same.
#pragma omp simd
    for (std::size_t i = 0; i < n; ++i) {
      const double rr = r2[i];
      double fq, g;
      over_q<Shape>(std::sqrt(rr) * inv_h, fq, g);
      w[i] = norm * fq;
      f[i] = rr > 0 ? norm_inv_h2 * g : 0.0;
    }
  }
  std::string name_;
  int shape_;
  double h_, inv_h_, norm_, radius_, norm_inv_h2_;
  int dim_;
};

// Registry: names in registration order, and construction by name (throws std::out_of_range).
std::vector<std::string> kernel_names();
// One line per shape: "name: summary" (arksph list).
std::vector<std::pair<std::string, std::string>> kernel_summaries();
Kernel make_kernel(const std::string& name, double h, int dimension);

}  // namespace arksph
