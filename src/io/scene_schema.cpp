// Typed, checked access to the TOML tree of a scene: see scene_schema.hpp.
#include "io/scene_schema.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "core/errors.hpp"
#include "io/names.hpp"
#include "core/expression.hpp"

namespace arksph::scene_schema {

namespace {

std::string type_name(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::string: return "string";
    case toml::node_type::integer: return "integer";
    case toml::node_type::floating_point: return "float";
    case toml::node_type::boolean: return "boolean";
    case toml::node_type::date: return "date";
    case toml::node_type::time: return "time";
    case toml::node_type::date_time: return "date-time";
    case toml::node_type::array: return "array";
    case toml::node_type::table: return "table";
    default: return "nothing";
  }
}

// "got string \"abc\"", "got array": the type, and the value when it is short and scalar.
std::string got(const toml::node& n) {
  std::string value;
  if (auto s = n.value_exact<std::string>()) value = '"' + echo_value(*s) + '"';
  else if (auto i = n.value_exact<int64_t>()) value = std::to_string(*i);
  else if (auto d = n.value_exact<double>()) value = format_number(*d);
  else if (auto b = n.value_exact<bool>()) value = *b ? "true" : "false";
  std::string out = "got " + type_name(n);
  if (!value.empty()) out.append(1, ' ').append(value);
  return out;
}

bool starts_with_component(const std::string& longer, const std::string& prefix) {
  if (longer.size() <= prefix.size() || longer.compare(0, prefix.size(), prefix) != 0) return false;
  return longer[prefix.size()] == '.' || longer[prefix.size()] == '[';
}

// The value of a TOML number as a double; an integer that a double cannot hold exactly (beyond 2^53)
// is refused with its digits, since rounding it would change the value written.
double number_of(const toml::node& n, const Reporter& rep, const std::string& key) {
  if (auto i = n.value_exact<int64_t>()) {
    const double d = static_cast<double>(*i);
    if (std::abs(d) > 9007199254740992.0 || static_cast<int64_t>(d) != *i)
      rep.fail(key, "the integer " + std::to_string(*i) + " is not exactly representable as a number here (|n| <= 2^53)");
    return d;
  }
  return *n.value_exact<double>();
}

}  // namespace

std::string format_number(double v) {
  char buf[64];
  auto res = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, res.ptr);
}

std::string join(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out.empty() ? "(none registered)" : out;
}

// ---- Reporter ----

Reporter::Reporter(std::string source, std::vector<std::pair<std::string, std::string>> overrides,
                   std::ostream* warnings)
    : source_(std::move(source)), overrides_(std::move(overrides)), warnings_(warnings) {}

std::string Reporter::origin(const std::string& key) const {
  for (auto it = overrides_.rbegin(); it != overrides_.rend(); ++it) {
    const auto& [set_key, option] = *it;
    if (key == set_key || starts_with_component(key, set_key) || starts_with_component(set_key, key))
      return option;
  }
  return source_;
}

void Reporter::fail(const std::string& key, const std::string& reason) const {
  std::string where = origin(key);
  throw InputError(one_line(key.empty() ? where + ": " + reason : where + ": " + echo_value(key) + ": " + reason));
}

void Reporter::warn(const std::string& key, const std::string& reason) const {
  if (warnings_) *warnings_ << one_line(origin(key) + ": " + echo_value(key) + ": " + reason) << '\n';
}

// ---- Section ----

Section::Section(const Reporter& rep, const toml::node* node, std::string path,
                 std::vector<std::string> keys)
    : rep_(&rep), table_(nullptr), path_(std::move(path)) {
  if (!node) return;
  table_ = node->as_table();
  if (!table_) rep.fail(path_, "expected a table, " + got(*node));
  for (const auto& [k, v] : *table_) {
    std::string name(k.str());
    if (std::find(keys.begin(), keys.end(), name) == keys.end())
      rep.fail(key(name), "unknown key (valid keys here: " + join(keys) + ")");
  }
}

std::string Section::key(std::string_view name) const {
  return path_.empty() ? std::string(name) : path_ + "." + std::string(name);
}

bool Section::has(std::string_view name) const { return node(name) != nullptr; }

const toml::node* Section::node(std::string_view name) const {
  return table_ ? table_->get(name) : nullptr;
}

void Section::fail(std::string_view name, const std::string& reason) const {
  rep_->fail(key(name), reason);
}

const toml::node& Section::required(std::string_view name) const {
  const toml::node* n = node(name);
  if (!n) fail(name, "missing required key");
  return *n;
}

Section Section::section(std::string_view name, std::vector<std::string> keys) const {
  return Section(*rep_, node(name), key(name), std::move(keys));
}

double Section::number(std::string_view name, std::optional<double> fallback) const {
  if (!has(name) && fallback) return *fallback;
  const toml::node& n = required(name);
  if (!n.is_number()) fail(name, "expected a number, " + got(n));
  double v = number_of(n, *rep_, key(name));
  if (!std::isfinite(v)) fail(name, "expected a finite number, " + got(n));
  return v;
}

long Section::integer(std::string_view name, std::optional<long> fallback) const {
  if (!has(name) && fallback) return *fallback;
  const toml::node& n = required(name);
  if (!n.is_integer()) fail(name, "expected an integer, " + got(n));
  return static_cast<long>(*n.value_exact<int64_t>());
}

bool Section::boolean(std::string_view name, bool fallback) const {
  if (!has(name)) return fallback;
  const toml::node& n = required(name);
  if (!n.is_boolean()) fail(name, "expected a boolean (true or false), " + got(n));
  return *n.value_exact<bool>();
}

std::string Section::string(std::string_view name, std::optional<std::string> fallback) const {
  if (!has(name) && fallback) return *fallback;
  const toml::node& n = required(name);
  if (!n.is_string()) fail(name, "expected a string, " + got(n));
  return *n.value_exact<std::string>();
}

std::string Section::one_of(std::string_view name, const std::vector<std::string>& allowed,
                            const std::string& fallback) const {
  std::string v = string(name, fallback);
  if (std::find(allowed.begin(), allowed.end(), v) == allowed.end())
    fail(name, "\"" + echo_value(v) + "\" is not one of: " + join(allowed));
  return v;
}

std::string Section::registered(std::string_view name, const std::string& family,
                                const std::string& fallback) const {
  std::string v = string(name, fallback);
  if (!is_registered(family, v))
    fail(name, "unknown " + family + " \"" + echo_value(v) + "\" (valid: " + join(registered_names(family)) + ")");
  return v;
}

std::vector<double> Section::numbers(std::string_view name, std::size_t count,
                                     std::optional<std::vector<double>> fallback) const {
  if (!has(name) && fallback) return *fallback;
  const toml::node& n = required(name);
  const toml::array* a = n.as_array();
  if (!a) fail(name, "expected an array of " + std::to_string(count) + " numbers, " + got(n));
  if (a->size() != count)
    fail(name, "expected " + std::to_string(count) + " numbers (one per dimension), got " +
                   std::to_string(a->size()));
  std::vector<double> out;
  for (std::size_t i = 0; i < count; ++i) {
    const toml::node& e = *a->get(i);
    std::string k = key(name) + "[" + std::to_string(i) + "]";
    if (!e.is_number()) rep_->fail(k, "expected a number, " + got(e));
    double v = number_of(e, *rep_, k);
    if (!std::isfinite(v)) rep_->fail(k, "expected a finite number, " + got(e));
    out.push_back(v);
  }
  return out;
}

std::string Section::expression_at(const toml::node& n, const std::string& k,
                                   const std::vector<std::string>& variables) const {
  std::string text;
  if (auto s = n.value_exact<std::string>()) text = *s;
  else if (n.is_integer())
    text = std::to_string(*n.value_exact<int64_t>());
  else if (n.is_number() && std::isfinite(*n.value_exact<double>()))
    text = format_number(*n.value_exact<double>());
  else rep_->fail(k, "expected an expression (string or number), " + got(n));
  try {
    Expression check(text, variables);
  } catch (const InputError& e) {
    rep_->fail(k, e.what());
  }
  return text;
}

std::string Section::expression(std::string_view name, const std::vector<std::string>& variables,
                                std::optional<std::string> fallback) const {
  if (!has(name) && fallback) return *fallback;
  return expression_at(required(name), key(name), variables);
}

std::vector<std::string> Section::expressions(std::string_view name, std::size_t count,
                                              const std::vector<std::string>& variables,
                                              const std::vector<std::string>& fallback) const {
  if (!has(name)) return fallback;
  const toml::node& n = required(name);
  const toml::array* a = n.as_array();
  if (!a) fail(name, "expected an array of " + std::to_string(count) + " expressions, " + got(n));
  if (a->size() != count)
    fail(name, "expected " + std::to_string(count) + " expressions (one per dimension), got " +
                   std::to_string(a->size()));
  std::vector<std::string> out;
  for (std::size_t i = 0; i < count; ++i)
    out.push_back(expression_at(*a->get(i), key(name) + "[" + std::to_string(i) + "]", variables));
  return out;
}

void Section::require(bool ok, std::string_view name, const std::string& what, double value) const {
  if (!ok) fail(name, "must be " + what + ", got " + format_number(value));
}

}  // namespace arksph::scene_schema
