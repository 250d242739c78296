#include "core/errors.hpp"

#include <cmath>
#include <cstdio>
#include <utility>

namespace arksph {

namespace {
std::string& current_activity() {
  static std::string a = "starting";
  return a;
}
}  // namespace

std::string message_number(double v) {
  if (std::isnan(v)) return "NaN";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

void set_activity(std::string what) { current_activity() = std::move(what); }

const std::string& activity() { return current_activity(); }

}  // namespace arksph
