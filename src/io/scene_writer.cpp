// Scene -> TOML text with every key, in the order of the file format (Scene::resolved_toml).
// Numbers are written in their shortest exact form, so the text reads back to the same Scene.
#include <toml++/toml.h>

#include <sstream>

#include "io/scene_reader.hpp"
#include "io/scene_schema.hpp"

namespace arksph {

namespace {

std::string quote(const std::string& s) {
  std::ostringstream os;
  os << toml::value<std::string>(s);  // TOML string syntax, escapes included
  return os.str();
}

std::string num(double v) {  // a TOML float: always with a '.' or an exponent
  std::string t = scene_schema::format_number(v);
  if (t.find_first_of(".eE") == std::string::npos) t += ".0";
  return t;
}

std::string numbers(const double* v, int n) {
  std::string out = "[";
  for (int i = 0; i < n; ++i) out += (i ? ", " : "") + num(v[i]);
  return out + "]";
}

std::string strings(const std::vector<std::string>& v) {
  std::string out = "[";
  for (std::size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + quote(v[i]);
  return out + "]";
}

std::string boolean(bool b) { return b ? "true" : "false"; }

}  // namespace

std::string scene_to_toml(const Scene& s) {
  const int dim = s.dimension;
  std::ostringstream o;
  o << "[scene]\n"
    << "name = " << quote(s.name) << "\n"
    << "dimension = " << dim << "\n\n";
  o << "[domain]\n"
    << "min = " << numbers(s.min.data(), dim) << "\n"
    << "max = " << numbers(s.max.data(), dim) << "\n\n";
  o << "[boundary]\n";
  const char* const names[4] = {"left", "right", "bottom", "top"};
  for (int i = 0; i < 2 * dim; ++i) {
    const SideSpec& side = s.sides[i];
    o << names[i] << " = { kind = ";
    if (side.kind == SideKind::periodic) {
      o << quote("periodic") << " }\n";
      continue;
    }
    o << quote("wall") << ", velocity = " << numbers(side.velocity.data(), dim)
      << ", slip = " << quote(side.slip == SlipKind::no_slip ? "no_slip" : "free_slip") << " }\n";
  }
  o << "corner_alpha = " << num(s.corner_alpha) << "\n"
    << "free_slip_divergence = " << boolean(s.free_slip_divergence) << "\n"
    << "wall_velocity = " << quote(s.wall_velocity) << "\n"
    << "wall_particles = " << boolean(s.wall_particles) << "\n\n";
  o << "[fluid]\n"
    << "spacing = " << num(s.spacing) << "\n"
    << "density = " << num(s.density) << "\n"
    << "viscosity = " << num(s.viscosity) << "\n"
    << "body_force = " << strings(s.body_force) << "\n"
    << "shuffle_initial_order = " << boolean(s.shuffle_initial_order) << "\n\n";
  o << "[initial]\n"
    << "velocity = " << strings(s.initial_velocity) << "\n"
    << "offset = " << strings(s.initial_offset) << "\n\n";
  for (const PhaseSpec& p : s.phases)
    o << "[[phase]]\n"
      << "where = " << quote(p.where) << "\n"
      << "density = " << num(p.density) << "\n\n";
  o << "[method]\n"
    << "scheme = " << quote(s.scheme) << "\n"
    << "kernel = " << quote(s.kernel) << "\n"
    << "h_over_dx = " << num(s.h_over_dx) << "\n"
    << "viscosity_model = " << quote(s.viscosity_model) << "\n"
    << "cleary_xi = " << num(s.cleary_xi) << "\n"
    << "kernel_correction = " << quote(s.kernel_correction) << "\n"
    << "pressure_reduction = " << boolean(s.pressure_reduction) << "\n"
    << "equation_of_state = " << quote(s.equation_of_state) << "\n"
    << "gas_gamma = " << num(s.gas_gamma) << "\n"
    << "sound_speed = " << num(s.sound_speed) << "\n"
    << "tait_gamma = " << num(s.tait_gamma) << "\n"
    << "background_pressure = " << num(s.background_pressure) << "\n"
    << "density_mode = " << quote(s.density_mode) << "\n"
    << "pressure_gradient = " << quote(s.pressure_gradient) << "\n"
    << "density_correction = " << quote(s.density_correction) << "\n"
    << "ppe_operator = " << quote(s.ppe_operator) << "\n"
    << "ppe_divergence = " << quote(s.ppe_divergence) << "\n"
    << "ppe_pressure_level = " << quote(s.ppe_pressure_level) << "\n"
    << "ppe_pressure_offset = " << num(s.ppe_pressure_offset) << "\n"
    << "neighbor_storage = " << quote(s.neighbor_storage) << "\n"
    << "force_sweep = " << boolean(s.force_sweep) << "\n"
    << "ppe_solver = " << quote(s.ppe_solver) << "\n"
    << "ppe_tolerance = " << num(s.ppe_tolerance) << "\n"
    << "gpps_spacing = " << num(s.gpps_spacing) << "\n"
    << "gpps_volume_relaxation = " << num(s.gpps_volume_relaxation) << "\n"
    << "centre_positions = " << boolean(s.centre_positions) << "\n"
    << "projection_points = " << quote(s.projection_points) << "\n"
    << "reorder_every = " << s.reorder_every << "\n"
    << "correction_threshold = " << num(s.correction_threshold) << "\n"
    << "correction_max_iterations = " << s.correction_max_iterations << "\n"
    << "correction_solver = " << quote(s.correction_solver) << "\n\n";
  o << "[time]\n"
    << "end = " << num(s.end) << "\n"
    << "integrator = " << quote(s.integrator) << "\n"
    << "dt = " << num(s.dt) << "\n"
    << "cfl = " << num(s.cfl) << "\n"
    << "rtol = " << num(s.rtol) << "\n"
    << "atol = " << num(s.atol) << "\n"
    << "max_steps = " << s.max_steps << "\n"
    << "imex = " << boolean(s.imex) << "\n"
    << "imex_pair = " << quote(s.imex_pair) << "\n"
    << "imex_linear = " << boolean(s.imex_linear) << "\n\n";
  o << "[output]\n"
    << "directory = " << quote(s.directory) << "\n"
    << "every = " << num(s.every) << "\n"
    << "checkpoint_every = " << num(s.checkpoint_every) << "\n\n";
  o << "[metrics]\n"
    << "ghia_re = " << s.ghia_re << "\n"
    << "poiseuille = " << boolean(s.poiseuille) << "\n"
    << "interface = " << boolean(s.interface) << "\n";
  return o.str();
}

}  // namespace arksph
