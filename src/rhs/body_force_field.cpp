#include "rhs/body_force_field.hpp"

namespace arksph {

BodyForceField::BodyForceField(const std::vector<std::string>& expr, int dim) : dim_(dim) {
  for (int k = 0; k < dim_; ++k) {
    expr_.emplace_back(expr.at(static_cast<std::size_t>(k)), std::vector<std::string>{"x", "y", "t"});
    const Expression& e = expr_.back();
    constant_.push_back(e.is_constant());
    value_.push_back(constant_.back() ? e.eval(0, 0, 0) : 0.0);
    if (!constant_.back() || value_.back() != 0.0) zero_ = false;
    if (e.uses("x") || e.uses("y")) uniform_ = false;
  }
}

BodyForceField::BodyForceField(const std::vector<std::string>& expr, const Scene& scene)
    : BodyForceField(expr, scene.dimension) {
  for (int k = 0; k < 2; ++k) walled_[k] = k < scene.dimension && scene.sides[2 * k].kind == SideKind::wall;
}

void BodyForceField::at(double x, double y, double t, double g[2]) const {
  g[1] = 0.0;
  for (int k = 0; k < dim_; ++k) g[k] = constant_[k] ? value_[k] : expr_[k].eval(x, y, t);
}

}  // namespace arksph
