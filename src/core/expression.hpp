// A user expression of x, y, t from a scene file (body force, initial velocity, phase region),
// compiled once by muParser and evaluated cheaply many times.
//
// Names: the variables chosen at construction (a subset of x, y, t), the constant `pi`, and muParser's
// built-in functions and operators (sin, exp, sqrt, abs, min, max, ^, <, &&, ?:, ...). A comparison
// yields 1 or 0, so a region such as "y > 0.5 && x < 0.25" is true where it evaluates to non-zero.
#pragma once
#include <memory>
#include <string>
#include <vector>

namespace arksph {

class Expression {
 public:
  // Compiles `text`; `variables` is a subset of {"x", "y", "t"}. Throws InputError, one line naming
  // the expression, on a syntax error or an unknown name; std::invalid_argument on another variable.
  explicit Expression(const std::string& text,
                      const std::vector<std::string>& variables = {"x", "y", "t"});
  Expression(const Expression& other);             // recompiles: the copy binds its own variables
  Expression& operator=(const Expression& other);
  Expression(Expression&& other) noexcept;         // moves the heap state: bound addresses stay valid
  Expression& operator=(Expression&& other) noexcept;
  ~Expression();

  // The value at (x, y, t); variables not declared at construction are ignored. Not thread-safe on
  // one object (muParser keeps a working stack): give each thread its own copy.
  double eval(double x, double y = 0.0, double t = 0.0) const;

  // True when the expression uses no variable (e.g. "0", "-9.81", "2*pi"): callers may skip it.
  bool is_constant() const;

  // True when the expression uses the variable `name` ("x", "y" or "t").
  bool uses(const std::string& name) const;

  const std::string& text() const { return text_; }
  const std::vector<std::string>& variables() const { return variables_; }

 private:
  struct State;  // muParser parser together with the variable storage it points to
  static std::unique_ptr<State> compile(const std::string& text,
                                        const std::vector<std::string>& variables);
  std::string text_;
  std::vector<std::string> variables_;
  std::unique_ptr<State> state_;
};

}  // namespace arksph
