// muParser wrapper: see expression.hpp. The parser stores raw pointers to the variables, so parser and
// variables live together in one heap block (State) that a move hands over and a copy rebuilds.
#include "core/expression.hpp"

#include <muParser.h>

#include <algorithm>
#include <numbers>
#include <stdexcept>

#include "core/errors.hpp"

namespace arksph {

struct Expression::State {
  mu::Parser parser;
  double x = 0.0, y = 0.0, t = 0.0;  // bound to the parser by address
  std::vector<std::string> used;     // variables the expression reads
};

namespace {

// "x, y, t" for messages.
std::string list_names(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out.empty() ? "none" : out;
}

std::string describe(const std::string& text, const mu::ParserError& e,
                     const std::vector<std::string>& variables) {
  std::string reason;
  if (e.GetCode() == mu::ecUNASSIGNABLE_TOKEN)
    reason = "unknown name \"" + echo_value(e.GetToken(), 60) + "\" (variables: " + list_names(variables) +
             "; constant: pi)";
  else
    reason = echo_value(e.GetMsg());
  return one_line("expression \"" + echo_value(text) + "\": " + reason);
}

}  // namespace

std::unique_ptr<Expression::State> Expression::compile(const std::string& text,
                                                       const std::vector<std::string>& variables) {
  auto s = std::make_unique<Expression::State>();
  for (const auto& v : variables) {
    double* slot = v == "x" ? &s->x : v == "y" ? &s->y : v == "t" ? &s->t : nullptr;
    if (!slot) throw std::invalid_argument("Expression: unsupported variable \"" + v + "\"");
    s->parser.DefineVar(v, slot);
  }
  try {
    s->parser.DefineConst("pi", std::numbers::pi);
    s->parser.SetExpr(text);
    s->parser.Eval();  // parse now, so that errors surface when the scene is read
    if (s->parser.GetNumResults() != 1)
      throw InputError(one_line("expression \"" + echo_value(text) + "\": a single value is expected, not a "
                                "comma-separated list"));
    for (const auto& [name, ptr] : s->parser.GetUsedVar()) s->used.push_back(name);
    s->parser.Eval();  // GetUsedVar() resets the bytecode: rebuild it once here, not in eval()
  } catch (const mu::ParserError& e) {
    throw InputError(describe(text, e, variables));
  }
  return s;
}

Expression::Expression(const std::string& text, const std::vector<std::string>& variables)
    : text_(text), variables_(variables), state_(compile(text, variables)) {}

Expression::Expression(const Expression& other)
    : text_(other.text_),
      variables_(other.variables_),
      state_(other.state_ ? compile(other.text_, other.variables_) : nullptr) {}

Expression& Expression::operator=(const Expression& other) {
  if (this != &other) {
    auto fresh = other.state_ ? compile(other.text_, other.variables_) : nullptr;
    text_ = other.text_;
    variables_ = other.variables_;
    state_ = std::move(fresh);
  }
  return *this;
}

Expression::Expression(Expression&& other) noexcept = default;
Expression& Expression::operator=(Expression&& other) noexcept = default;
Expression::~Expression() = default;

double Expression::eval(double x, double y, double t) const {
  state_->x = x;
  state_->y = y;
  state_->t = t;
  return state_->parser.Eval();
}

bool Expression::is_constant() const { return state_->used.empty(); }

bool Expression::uses(const std::string& name) const {
  return std::find(state_->used.begin(), state_->used.end(), name) != state_->used.end();
}

}  // namespace arksph
