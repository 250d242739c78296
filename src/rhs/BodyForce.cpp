// Body force per unit mass f(x, y, t) from the scene's expressions (N-S eq. 14 of Szewc et al. 2012).
// Constant expressions are evaluated once; others at every particle and call.
#include <memory>

#include "core/expression.hpp"
#include "rhs/terms.hpp"

namespace arksph {

class BodyForce final : public Term {
 public:
  explicit BodyForce(const std::vector<std::string>& expr) {
    for (const auto& e : expr) {
      expr_.emplace_back(e, std::vector<std::string>{"x", "y", "t"});
      constant_.push_back(expr_.back().is_constant());  // asked once: muParser re-parses to answer
      value_.push_back(constant_.back() ? expr_.back().eval(0, 0, 0) : 0.0);
    }
  }
  std::string name() const override { return "body_force"; }
  Stage stage() const override { return Stage::force; }
  bool uses_neighbors() const override { return false; }
  void apply(FluidFields& f) const override {
    double* out[2] = {f.dudt.data(), f.dvdt.data()};
    for (int k = 0; k < f.dim; ++k) {
      const Expression& e = expr_[k];
      if (constant_[k]) {
        const double g = value_[k];
        for (std::size_t a = 0; a < f.n_real; ++a) out[k][a] += g;
      } else {
        for (std::size_t a = 0; a < f.n_real; ++a)
          out[k][a] += e.eval(f.x[a], f.dim == 2 ? f.y[a] : 0.0, f.t);
      }
    }
  }

 private:
  std::vector<Expression> expr_;
  std::vector<bool> constant_;
  std::vector<double> value_;
};

std::unique_ptr<Term> make_body_force(const std::vector<std::string>& expr) {
  return std::make_unique<BodyForce>(expr);
}

}  // namespace arksph
