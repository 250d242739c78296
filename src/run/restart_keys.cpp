#include "run/restart_keys.hpp"

#include <array>
#include <vector>

#include "core/errors.hpp"
#include "io/scene_schema.hpp"

namespace arksph {

namespace {

using scene_schema::format_number;

std::string text(double v) { return format_number(v); }
std::string text(bool v) { return v ? "true" : "false"; }
std::string text(int v) { return std::to_string(v); }
std::string text(const std::string& v) { return "\"" + v + "\""; }
std::string text(SideKind k) { return k == SideKind::wall ? "\"wall\"" : "\"periodic\""; }
std::string text(SlipKind k) { return k == SlipKind::no_slip ? "\"no_slip\"" : "\"free_slip\""; }
std::string text(const std::array<double, 2>& a, int dim) {
  return dim == 1 ? "[" + text(a[0]) + "]" : "[" + text(a[0]) + ", " + text(a[1]) + "]";
}
std::string text(const std::vector<std::string>& a, int dim) {
  std::string s = "[";
  for (int k = 0; k < dim && k < static_cast<int>(a.size()); ++k) s += (k ? ", \"" : "\"") + a[k] + "\"";
  return s + "]";
}

[[noreturn]] void refuse(const std::string& source, const std::string& key, const std::string& was,
                         const std::string& now) {
  throw InputError(source + ": " + key + ": " + echo_value(now) + " differs from " + echo_value(was) +
                   " in the checkpoint; a restart may not change the keys that shape the particle set or the walls");
}

}  // namespace

void check_restart_keys(const Scene& a, const Scene& b, const std::string& source) {
  const auto same = [&](const std::string& key, const std::string& was, const std::string& now) {
    if (was != now) refuse(source, key, was, now);
  };
  same("scene.dimension", text(a.dimension), text(b.dimension));
  const int dim = a.dimension;
  same("domain.min", text(a.min, dim), text(b.min, dim));
  same("domain.max", text(a.max, dim), text(b.max, dim));
  same("fluid.spacing", text(a.spacing), text(b.spacing));
  same("fluid.density", text(a.density), text(b.density));
  same("fluid.region", text(a.fluid_region), text(b.fluid_region));
  same("fluid.shuffle_initial_order", text(a.shuffle_initial_order), text(b.shuffle_initial_order));
  same("initial.offset", text(a.initial_offset, dim), text(b.initial_offset, dim));
  for (int s = 0; s < (dim == 1 ? 2 : 4); ++s) {
    const std::string key = std::string("boundary.") + kSideNames[s];
    same(key + ".kind", text(a.sides[s].kind), text(b.sides[s].kind));
    same(key + ".slip", text(a.sides[s].slip), text(b.sides[s].slip));
  }
  same("boundary.wall_particles", text(a.wall_particles), text(b.wall_particles));
  same("phase", std::to_string(a.phases.size()) + " [[phase]] tables", std::to_string(b.phases.size()) + " [[phase]] tables");
  for (std::size_t i = 0; i < a.phases.size(); ++i) {
    const std::string key = "phase[" + std::to_string(i) + "]";
    same(key + ".where", text(a.phases[i].where), text(b.phases[i].where));
    same(key + ".density", text(a.phases[i].density), text(b.phases[i].density));
  }
}

}  // namespace arksph
