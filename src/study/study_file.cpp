#include "study/study_file.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>

#include "core/errors.hpp"
#include "core/particles.hpp"
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

void check_analytic_velocity_finite(const std::string& path, const std::vector<std::string>& uv, const Scene& scene,
                                    const std::string& run) {
  const AnalyticVelocity exact(uv[0], uv[1]);
  const ParticleSet particles = make_lattice(scene);
  for (const double t : {0.0, scene.end})
    for (std::size_t a = 0; a < particles.n; ++a) {
      const double x = particles.init_pos[0][a], y = particles.dim > 1 ? particles.init_pos[1][a] : 0.0;
      double u = 0, v = 0;
      exact.eval(x, y, t, u, v);
      if (std::isfinite(u) && std::isfinite(v)) continue;
      throw InputError(path + ": study.analytic_velocity: not finite at the particle (" + message_number(x) + ", " +
                       message_number(y) + "), t = " + message_number(t) + " (u = " + message_number(u) + ", v = " +
                       message_number(v) + (run.empty() ? "" : ", " + run) +
                       "): the reference is not finite, so no error could be measured against it");
    }
}

}  // namespace arksph
