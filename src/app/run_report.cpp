#include "app/run_report.hpp"

#include <cstdio>
#include <filesystem>

#include "core/errors.hpp"
#include "io/json_reader.hpp"

#ifndef ARKSPH_VERSION
#define ARKSPH_VERSION "unknown"
#endif
#ifndef ARKSPH_GIT_COMMIT
#define ARKSPH_GIT_COMMIT ""
#endif

namespace arksph {

std::string version_text() {
  const std::string commit = ARKSPH_GIT_COMMIT;
  return std::string("arksph ") + ARKSPH_VERSION + (commit.empty() ? "" : " (git " + commit + ")") + "\n";
}

void print_next_steps(const std::string& dir) {
  namespace fs = std::filesystem;
  const fs::path pvd = fs::path(dir) / "particles.pvd";
  if (fs::exists(pvd)) std::printf("  frames: %s (view: paraview %s)\n", pvd.c_str(), pvd.c_str());
  JsonValue summary;
  try {
    summary = read_json_file((fs::path(dir) / "summary.json").string());
  } catch (const InputError&) {
    return;
  }
  const JsonValue* metrics = summary.find("metrics");
  if (!metrics) return;
  static const std::pair<const char*, const char*> headline[] = {
      {"ghia_u_linf", "Ghia u L_inf"},
      {"ghia_u_rms", "Ghia u rms"},
      {"ghia_v_linf", "Ghia v L_inf"},
      {"ghia_v_rms", "Ghia v rms"},
      {"poiseuille_eps_max_tstar_0.5_2", "Poiseuille eps max (t* in [0.5, 2])"},
      {"poiseuille_rms", "Poiseuille eps"},
      {"velocity_l1_relative", "velocity L1 relative error"},
      {"peak_speed_error", "peak speed error"},
      {"amplitude_error", "amplitude error"},
      {"bubble_y", "bubble tip y"},
      {"spike_y", "spike tip y"},
      {"upper_density_mean", "upper density mean"},
      {"upper_density_rms", "upper density rms"},
      {"cv", "CV"},
  };
  std::string line;
  for (const auto& [key, label] : headline)
    if (const JsonValue* v = metrics->find(key); v && v->kind == JsonValue::Kind::number)
      line += std::string(line.empty() ? "" : ", ") + label + " " + v->text;
  if (!line.empty()) std::printf("  metrics (summary.json): %s\n", line.c_str());
}

}  // namespace arksph
