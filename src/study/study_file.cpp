#include "study/study_file.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>

#include "core/errors.hpp"
#include "io/input_file.hpp"
#include "study/reference_error.hpp"

namespace arksph {

std::string read_text_file(const std::string& path) { return read_input_file(path, "scene"); }

toml::table read_study_toml(const std::string& path) {
  const std::string text = read_input_file(path, "study");
  try {
    return toml::parse(std::string_view(text), std::string_view(path));
  } catch (const toml::parse_error& e) {
    throw InputError(path + ":" + std::to_string(e.source().begin.line) + ":" + std::to_string(e.source().begin.column) +
                     ": syntax error");
  }
}

void check_analytic_velocity(const std::string& path, const std::vector<std::string>& uv) {
  const std::string key = path + ": study.analytic_velocity: ";
  if (uv.size() != 2) throw InputError(key + "expected two expressions [u, v] of x, y, t");
  try {
    AnalyticVelocity check(uv[0], uv[1]);
  } catch (const InputError& e) {
    throw InputError(key + e.what());
  }
}

}  // namespace arksph
