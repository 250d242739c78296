#include "study/study_file.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>

#include "core/errors.hpp"
#include "study/reference_error.hpp"

namespace arksph {

std::string read_text_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

toml::table read_study_toml(const std::string& path) {
  const std::string text = read_text_file(path);
  if (text.empty() && !std::filesystem::exists(path)) throw InputError(path + ": cannot read the study file");
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
