// Scene reader: parse the TOML text, apply the --set overrides to the tree, then validate section by
// section into a Scene (see scene_reader.hpp; keys are documented in default_scene.cpp).
#include "io/scene_reader.hpp"

#include <toml++/toml.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>

#include "core/errors.hpp"
#include "core/names.hpp"
#include "io/expression.hpp"
#include "io/scene_schema.hpp"

namespace arksph {

namespace {

using scene_schema::format_number;
using scene_schema::Reporter;
using scene_schema::Section;

const char* const kSideNames[4] = {"left", "right", "bottom", "top"};
const char* const kAxis[2] = {"x", "y"};

std::string one_line(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  return s;
}

std::string trim(const std::string& s) {
  auto b = s.find_first_not_of(" \t");
  auto e = s.find_last_not_of(" \t");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

toml::table parse_document(const std::string& text, const std::string& source) {
  try {
    return toml::parse(std::string_view(text), std::string_view(source));
  } catch (const toml::parse_error& e) {
    const auto& at = e.source().begin;
    throw InputError(one_line(source + ":" + std::to_string(at.line) + ":" +
                              std::to_string(at.column) + ": syntax error: " +
                              std::string(e.description())));
  }
}

// Applies "KEY=VALUE" to the tree; returns (KEY, "--set KEY=VALUE") for the error messages.
std::pair<std::string, std::string> apply_override(toml::table& root, const std::string& set) {
  const std::string option = "--set " + set;
  auto eq = set.find('=');
  if (eq == std::string::npos)
    throw InputError(one_line(option + ": expected KEY=VALUE, e.g. --set time.end=2"));
  const std::string key = trim(set.substr(0, eq));
  const std::string text = set.substr(eq + 1);
  std::vector<std::string> parts;
  for (std::size_t start = 0;;) {
    auto dot = key.find('.', start);
    parts.push_back(key.substr(start, dot - start));
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  for (const auto& p : parts)
    if (p.empty())
      throw InputError(one_line(option + ": expected KEY=VALUE with KEY a dotted path such as "
                                         "time.end, got \"" + key + "\""));

  // VALUE as a TOML value (number, boolean, string, array, inline table), else a bare string.
  toml::table holder;
  try {
    holder = toml::parse("v = " + text);
  } catch (const toml::parse_error&) {
    holder = toml::table{};
  }
  if (holder.size() != 1 || !holder.get("v")) {
    holder = toml::table{};
    holder.insert("v", trim(text));
  }

  toml::table* t = &root;
  std::string walked;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    walked += (walked.empty() ? "" : ".") + parts[i];
    if (!t->get(parts[i])) t->insert(parts[i], toml::table{});
    t = t->get(parts[i])->as_table();
    if (!t) throw InputError(one_line(option + ": " + walked + ": is not a table, cannot set " + key));
  }
  holder.get("v")->visit([&](auto&& value) { t->insert_or_assign(parts.back(), std::move(value)); });
  return {key, option};
}

// Fails unless `length` holds a whole number (>= 2) of particles of size `spacing`.
void check_lattice(const Section& fluid, double spacing, double length, int axis) {
  const double n = length / spacing;
  const double count = std::round(n);
  if (std::abs(n - count) > 1e-6 * std::max(count, 1.0))
    fluid.fail("spacing", "does not divide the domain length " + format_number(length) + " along " +
                              kAxis[axis] + " into a whole number of particles (length/spacing = " +
                              format_number(n) + ")");
  if (count < 2)
    fluid.fail("spacing", "gives " + format_number(count) + " particle(s) along " + kAxis[axis] +
                              "; at least 2 are needed");
}

// Fails unless `where` selects at least one point of the initial lattice min + (i + 1/2) spacing.
void check_phase_region(const Scene& s, const Section& phase, const std::string& where) {
  const Expression region(where, {"x", "y"});
  const long nx = std::lround((s.max[0] - s.min[0]) / s.spacing);
  const long ny = s.dimension == 2 ? std::lround((s.max[1] - s.min[1]) / s.spacing) : 1;
  for (long j = 0; j < ny; ++j) {
    const double y = s.dimension == 2 ? s.min[1] + (j + 0.5) * s.spacing : 0.0;
    for (long i = 0; i < nx; ++i)
      if (region.eval(s.min[0] + (i + 0.5) * s.spacing, y) != 0.0) return;
  }
  phase.fail("where", "selects no particle of the initial lattice");
}

void read_scene_domain(const Section& root, Scene& s) {
  const Section scene = root.section("scene", {"name", "dimension"});
  s.name = scene.string("name", s.name);  // label: messages, summary.json, default output directory
  if (s.name.empty()) scene.fail("name", "must not be empty");
  s.dimension = static_cast<int>(scene.integer("dimension", 2));  // 1 or 2
  if (s.dimension != 1 && s.dimension != 2)
    scene.fail("dimension", "must be 1 or 2, got " + std::to_string(s.dimension));
  const std::size_t dim = s.dimension;

  const Section domain = root.section("domain", {"min", "max"});
  const auto lo = domain.numbers("min", dim, std::nullopt);  // lower corner of the fluid box
  const auto hi = domain.numbers("max", dim, std::nullopt);  // upper corner
  for (std::size_t d = 0; d < dim; ++d)
    if (!(hi[d] > lo[d]))
      domain.fail("max", "must exceed domain.min in every component (max[" + std::to_string(d) +
                             "] = " + format_number(hi[d]) + ", min[" + std::to_string(d) + "] = " +
                             format_number(lo[d]) + ")");
  s.min = {lo[0], dim == 2 ? lo[1] : 0.0};
  s.max = {hi[0], dim == 2 ? hi[1] : 0.0};
}

void read_boundary(const Section& root, Scene& s) {
  const Section b = root.section(
      "boundary", {"left", "right", "bottom", "top", "corner_alpha", "free_slip_divergence", "wall_velocity",
                                            "wall_particles"});
  const std::size_t dim = s.dimension;
  for (int i = 0; i < 4; ++i) {
    if (i >= 2 && dim == 1) {
      if (b.has(kSideNames[i])) b.fail(kSideNames[i], "not allowed when scene.dimension = 1");
      s.sides[i] = SideSpec{};  // unused in 1D
      continue;
    }
    const Section side = b.section(kSideNames[i], {"kind", "velocity", "slip"});
    SideSpec& spec = s.sides[i];
    // kind: "wall" (mirror ghost particles) | "periodic" (the opposite side must be periodic too)
    spec.kind = side.one_of("kind", {"wall", "periodic"}, "wall") == "wall" ? SideKind::wall
                                                                            : SideKind::periodic;
    if (spec.kind == SideKind::periodic)
      for (const char* wall_only : {"velocity", "slip"})
        if (side.has(wall_only)) side.fail(wall_only, "only a wall takes this key, the side is periodic");
    // velocity: wall velocity (a moving lid), one number per dimension
    const auto w = side.numbers("velocity", dim, std::vector<double>(dim, 0.0));
    spec.velocity = {w[0], dim == 2 ? w[1] : 0.0};
    // slip: "no_slip" (ghosts mirror the velocity about w) | "free_slip" (tangential copied)
    spec.slip = side.one_of("slip", {"no_slip", "free_slip"}, "no_slip") == "no_slip"
                    ? SlipKind::no_slip
                    : SlipKind::free_slip;
  }
  for (int i = 0; i < 2 * static_cast<int>(dim); i += 2)
    if ((s.sides[i].kind == SideKind::periodic) != (s.sides[i + 1].kind == SideKind::periodic)) {
      const int p = s.sides[i].kind == SideKind::periodic ? i : i + 1;
      b.fail(kSideNames[p], std::string("periodic requires boundary.") + kSideNames[p ^ 1] +
                                " to be periodic too");
    }
  s.corner_alpha = b.number("corner_alpha", s.corner_alpha);  // Szewc 2012 eq. 46
  b.require(s.corner_alpha >= -1 && s.corner_alpha <= 1, "corner_alpha", "in [-1, 1]", s.corner_alpha);
  s.free_slip_divergence = b.boolean("free_slip_divergence", s.free_slip_divergence);
  // wall_velocity: tangential velocity of no-slip ghosts (Basa et al. 2008 §6.1.2): "mirror" (2w - u of
  // the source) | "linear" (the wall shear of the nearest fluid particle extrapolated into the wall) |
  // "quadratic" (through the two nearest fluid rows); the list is registered_names("wall_velocity")
  s.wall_velocity = b.one_of("wall_velocity", registered_names("wall_velocity"), s.wall_velocity);
  // wall_particles: add particles on the no-slip walls carrying the wall velocity, one per fluid
  // particle closer than dx (Basa et al. 2008 §6.1.2), with any wall_velocity rule; 2D
  s.wall_particles = b.boolean("wall_particles", s.wall_particles);
  bool any_wall = false;
  for (std::size_t i = 0; i < 2 * dim; ++i) any_wall |= s.sides[i].kind == SideKind::wall;
  if (s.free_slip_divergence && !any_wall)
    b.fail("free_slip_divergence", "needs at least one wall, but every side is periodic");
}

void read_fluid(const Section& root, Scene& s) {
  const std::size_t dim = s.dimension;
  const std::vector<std::string> zeros(dim, "0");
  const Section f = root.section("fluid", {"spacing", "density", "viscosity", "body_force", "shuffle_initial_order"});
  s.spacing = f.number("spacing", std::nullopt);  // initial lattice spacing dx
  f.require(s.spacing > 0, "spacing", "> 0", s.spacing);
  for (std::size_t d = 0; d < dim; ++d) check_lattice(f, s.spacing, s.max[d] - s.min[d], d);
  // A count no machine holds must be a message, not std::bad_alloc (or an endless phase check).
  double particles = 1;
  for (std::size_t d = 0; d < dim; ++d) particles *= std::round((s.max[d] - s.min[d]) / s.spacing);
  if (!(particles <= 2e8))
    f.fail("spacing", format_number(particles) + " particles exceed the limit of 2e8");
  s.density = f.number("density", s.density);  // reference density rho0
  f.require(s.density > 0, "density", "> 0", s.density);
  s.viscosity = f.number("viscosity", s.viscosity);  // kinematic viscosity nu
  f.require(s.viscosity >= 0, "viscosity", ">= 0", s.viscosity);
  s.body_force = f.expressions("body_force", dim, {"x", "y", "t"}, zeros);  // acceleration g(x, y, t)
  // Particles stored in a fixed pseudo-random order (ids kept): the memory order of a long mixed run
  s.shuffle_initial_order = f.boolean("shuffle_initial_order", s.shuffle_initial_order);

  const Section init = root.section("initial", {"velocity", "offset"});
  s.initial_velocity = init.expressions("velocity", dim, {"x", "y"}, zeros);  // u(x, y, 0)
  s.initial_offset = init.expressions("offset", dim, {"x", "y"}, zeros);  // displacement of the lattice point (x, y)

  s.phases.clear();
  if (const toml::node* node = root.node("phase")) {
    const toml::array* list = node->as_array();
    if (!list || (!list->empty() && !list->is_array_of_tables()))
      root.fail("phase", "expected an array of tables ([[phase]] sections)");
    for (std::size_t i = 0; i < list->size(); ++i) {
      const Section p(root.reporter(), list->get(i), "phase[" + std::to_string(i) + "]",
                      {"where", "density"});
      PhaseSpec phase;
      phase.where = p.expression("where", {"x", "y"}, std::nullopt);  // region: non-zero selects
      phase.density = p.number("density", std::nullopt);             // reference density of the phase
      p.require(phase.density > 0, "density", "> 0", phase.density);
      check_phase_region(s, p, phase.where);
      s.phases.push_back(phase);
    }
  }
}

void read_method(const Section& root, Scene& s) {
  const Section m = root.section("method", {"scheme", "kernel", "h_over_dx", "viscosity_model",
                                            "sound_speed", "tait_gamma", "background_pressure", "density_mode",
                                            "pressure_gradient", "density_correction", "ppe_solver",
                                            "ppe_operator", "ppe_divergence", "ppe_pressure_level", "ppe_pressure_offset", "neighbor_storage", "force_sweep", "ppe_tolerance", "gpps_spacing", "gpps_volume_relaxation", "centre_positions", "projection_points", "correction_threshold",
                                            "correction_max_iterations", "correction_solver", "reorder_every",
                                            "cleary_xi", "kernel_correction", "pressure_reduction",
                                            "equation_of_state", "gas_gamma"});
  s.scheme = m.registered("scheme", "scheme", s.scheme);
  s.kernel = m.registered("kernel", "kernel", s.kernel);
  s.h_over_dx = m.number("h_over_dx", s.h_over_dx);  // smoothing length h / dx
  m.require(s.h_over_dx >= 0.5 && s.h_over_dx <= 4, "h_over_dx", "in [0.5, 4]", s.h_over_dx);
  s.viscosity_model = m.registered("viscosity_model", "viscosity_model", s.viscosity_model);
  s.cleary_xi = m.number("cleary_xi", s.cleary_xi);  // model D constant (Basa eq. 34)
  m.require(s.cleary_xi > 0, "cleary_xi", "> 0", s.cleary_xi);
  // Basa §4 kernel consistency correction of the pressure and viscous terms
  s.kernel_correction = m.registered("kernel_correction", "kernel_correction", s.kernel_correction);
  s.pressure_reduction = m.boolean("pressure_reduction", s.pressure_reduction);  // Basa eq. 20
  // Basa eq. 13 (Tait) or eq. 12 (ideal gas, with the energy equation 14 in the ODE state)
  s.equation_of_state = m.registered("equation_of_state", "equation_of_state", s.equation_of_state);
  s.gas_gamma = m.number("gas_gamma", s.gas_gamma);  // ideal-gas ratio of specific heats
  m.require(s.gas_gamma > 1, "gas_gamma", "> 1", s.gas_gamma);
  if (s.equation_of_state != "tait" && s.scheme != "wcsph")
    m.fail("equation_of_state", "\"" + s.equation_of_state + "\" needs scheme \"wcsph\"");
  s.sound_speed = m.number("sound_speed", s.sound_speed);  // WCSPH c0; 0: default
  m.require(s.sound_speed >= 0, "sound_speed", ">= 0", s.sound_speed);
  s.tait_gamma = m.number("tait_gamma", s.tait_gamma);  // Tait exponent (C&R eq. 7)
  m.require(s.tait_gamma >= 1, "tait_gamma", ">= 1", s.tait_gamma);
  s.background_pressure = m.number("background_pressure", s.background_pressure);  // added to Tait p
  m.require(s.background_pressure >= 0, "background_pressure", ">= 0", s.background_pressure);
  s.density_mode = m.registered("density_mode", "density_mode", s.density_mode);
  s.pressure_gradient = m.registered("pressure_gradient", "pressure_gradient", s.pressure_gradient);
  s.density_correction = m.registered("density_correction", "density_correction", s.density_correction);
  if (s.density_correction != "none" && s.scheme == "wcsph")
    m.fail("density_correction", "\"" + s.density_correction +
                                     "\" needs a projection scheme; scheme \"wcsph\" takes only \"none\"");
  if (s.sound_speed != 0 && s.scheme != "wcsph")
    m.reporter().warn(m.key("sound_speed"), "unused by scheme " + s.scheme);
  // Projection schemes: the Poisson solver ("klu" | "cg"), the CG tolerance, and the centring of
  // positions in time (Cummins & Rudman eq. 12).
  s.ppe_solver = m.registered("ppe_solver", "ppe_solver", s.ppe_solver);
  // "approximate" (C&R eq. 19) | "exact" (C&R eq. 18, the 1D decoupling demonstration; KLU only)
  s.ppe_operator = m.one_of("ppe_operator", {"approximate", "exact"}, s.ppe_operator);
  // Source of the PPE: "cummins_rudman" (C&R eq. 17, ghosts left out) | "difference" (Szewc eq. 19 / rho, ghosts in)
  s.ppe_divergence = m.one_of("ppe_divergence", {"cummins_rudman", "difference"}, s.ppe_divergence);
  // The free level of P (Neumann problem): "zero_mean" | "zero_min" (all P >= 0: eq. 11 then repels)
  s.ppe_pressure_level = m.one_of("ppe_pressure_level", {"zero_mean", "zero_min"}, s.ppe_pressure_level);
  // "pairs": W and F stored per pair (fast); "candidates": only the Verlet candidates are stored and
  // every term evaluates the kernel again (about 1 KB per particle less than 2, slower)
  s.neighbor_storage = m.one_of("neighbor_storage", {"pairs", "candidates"}, s.neighbor_storage);
  // true (wcsph): the force terms that sum over one particle's neighbours run in one sweep, each
  // particle's neighbours and kernel values gathered once into a small buffer (no per-pair storage);
  // false: each term walks the stored pair list on its own. Same results bit for bit.
  s.force_sweep = m.boolean("force_sweep", s.force_sweep);
  // A constant added to P after the level is fixed (a background pressure: with eq. 11's symmetric
  // pairs it pushes disordered particles apart in proportion to their disorder)
  s.ppe_pressure_offset = m.number("ppe_pressure_offset", s.ppe_pressure_offset);
  m.require(s.ppe_pressure_offset >= 0, "ppe_pressure_offset", ">= 0", s.ppe_pressure_offset);
  if (s.ppe_operator == "exact" && s.ppe_solver == "auto") s.ppe_solver = "klu";  // the only one for it
  if (s.ppe_operator == "exact" && s.ppe_solver != "klu")
    m.fail("ppe_operator", "the exact operator is not symmetric: it needs method.ppe_solver = \"klu\"");
  s.ppe_tolerance = m.number("ppe_tolerance", s.ppe_tolerance);
  m.require(s.ppe_tolerance > 0 && s.ppe_tolerance < 1, "ppe_tolerance", "in (0, 1)", s.ppe_tolerance);
  // isph-gpps: cell size of the auxiliary Poisson grid (Szewc §4.2); 0 takes fluid.spacing
  s.gpps_spacing = m.number("gpps_spacing", s.gpps_spacing);
  m.require(s.gpps_spacing >= 0, "gpps_spacing", ">= 0", s.gpps_spacing);
  if (s.gpps_spacing != 0 && s.scheme != "isph-gpps")
    m.reporter().warn(m.key("gpps_spacing"), "unused by scheme " + s.scheme);
  // isph-gpps: relaxation of the deposited particle volume per cell towards the cell volume (0: off)
  s.gpps_volume_relaxation = m.number("gpps_volume_relaxation", s.gpps_volume_relaxation);
  m.require(s.gpps_volume_relaxation >= 0 && s.gpps_volume_relaxation <= 1, "gpps_volume_relaxation", "in [0, 1]",
            s.gpps_volume_relaxation);
  s.centre_positions = m.boolean("centre_positions", s.centre_positions);
  // "step": project after each accepted step (C&R); "stages": also every ERK stage z_i, i >= 2
  s.projection_points = m.one_of("projection_points", {"step", "stages"}, s.projection_points);
  // Re-sort the particles by cell (kernel-support grid, row-major) every this many steps; 0: never
  s.reorder_every = m.integer("reorder_every", s.reorder_every);
  m.require(s.reorder_every >= 0, "reorder_every", ">= 0", static_cast<double>(s.reorder_every));
  // Pozorski-Wawrenczuk correction (Szewc §9): trigger threshold and iterations per step.
  s.correction_threshold = m.number("correction_threshold", s.correction_threshold);
  m.require(s.correction_threshold >= 0, "correction_threshold", ">= 0", s.correction_threshold);
  const double iters = m.number("correction_max_iterations", s.correction_max_iterations);
  m.require(iters >= 1 && iters <= 1000 && iters == std::floor(iters), "correction_max_iterations",
            "a whole number in [1, 1000]", iters);
  s.correction_max_iterations = static_cast<int>(iters);
  // "fixed_point": repeated linear solves of eq. 58; "kinsol": KINSOL Newton on eq. 59 with the
  // Laplacian as frozen Jacobian (KLU)
  s.correction_solver = m.one_of("correction_solver", {"fixed_point", "kinsol", "newton"}, s.correction_solver);
}

void read_time_output(const Section& root, Scene& s) {
  const Section t = root.section("time", {"end", "integrator", "dt", "cfl", "rtol", "atol", "max_steps", "imex",
                                            "imex_pair", "imex_linear"});
  s.end = t.number("end", std::nullopt);  // final simulated time
  t.require(s.end > 0, "end", "> 0", s.end);
  s.integrator = t.registered("integrator", "erk_table", s.integrator);  // ARKODE table name
  s.dt = t.number("dt", s.dt);  // 0: adaptive; > 0: fixed step
  t.require(s.dt >= 0, "dt", ">= 0", s.dt);
  s.cfl = t.number("cfl", s.cfl);
  t.require(s.cfl > 0 && s.cfl <= 1, "cfl", "in (0, 1]", s.cfl);
  s.rtol = t.number("rtol", s.rtol);
  t.require(s.rtol > 0, "rtol", "> 0", s.rtol);
  s.atol = t.number("atol", s.atol);
  t.require(s.atol > 0, "atol", "> 0", s.atol);
  s.max_steps = t.integer("max_steps", s.max_steps);
  t.require(s.max_steps >= 1, "max_steps", ">= 1", static_cast<double>(s.max_steps));
  // IMEX: ARKStep with the viscous term implicit (app README "Stiff viscosity"); time.integrator is
  // then unused, the pair names both tables
  s.imex = t.boolean("imex", s.imex);
  s.imex_pair = t.registered("imex_pair", "imex_pair", s.imex_pair);
  s.imex_linear = t.boolean("imex_linear", s.imex_linear);
  if (s.imex && s.scheme != "wcsph") t.fail("imex", "needs method.scheme = \"wcsph\" (got \"" + s.scheme + "\")");

  const Section o = root.section("output", {"directory", "every", "checkpoint_every"});
  s.directory = o.string("directory", "runs/" + s.name);
  if (s.directory.empty()) o.fail("directory", "must not be empty");
  s.every = o.number("every", s.every);  // simulated time between frames; 0: first and last only
  o.require(s.every >= 0, "every", ">= 0", s.every);
  s.checkpoint_every = o.number("checkpoint_every", s.checkpoint_every);  // time between checkpoints; 0: end only
  o.require(s.checkpoint_every >= 0, "checkpoint_every", ">= 0", s.checkpoint_every);

  const Section mt = root.section("metrics", {"ghia_re", "poiseuille", "interface"});
  s.ghia_re = static_cast<int>(mt.integer("ghia_re", s.ghia_re));
  if (s.ghia_re != 0 && s.ghia_re != 100 && s.ghia_re != 1000)
    mt.fail("ghia_re", "must be 0 (off), 100 or 1000, got " + std::to_string(s.ghia_re));
  s.poiseuille = mt.boolean("poiseuille", s.poiseuille);
  // Phase interface (Rayleigh-Taylor): contour CSV per output time, bubble and spike tips
  s.interface = mt.boolean("interface", s.interface);
  if (s.interface && (s.phases.empty() || s.dimension != 2))
    mt.fail("interface", "needs a 2D scene with at least one [[phase]]");
}

}  // namespace

Scene read_scene_text(const std::string& toml_text, const std::string& source_name,
                      const std::vector<std::string>& sets, std::ostream& warnings) {
  toml::table tree = parse_document(toml_text, source_name);
  std::vector<std::pair<std::string, std::string>> overrides;
  for (const auto& set : sets) overrides.push_back(apply_override(tree, set));
  const Reporter rep(source_name, overrides, &warnings);
  const Section root(rep, &tree, "",
                     {"scene", "domain", "boundary", "fluid", "initial", "phase", "method", "time",
                      "output", "metrics"});
  Scene s;
  s.source = source_name;
  read_scene_domain(root, s);
  read_boundary(root, s);
  read_fluid(root, s);
  read_method(root, s);
  read_time_output(root, s);
  s.resolved_toml = scene_to_toml(s);
  return s;
}

Scene read_scene_text(const std::string& toml_text, const std::string& source_name,
                      const std::vector<std::string>& sets) {
  return read_scene_text(toml_text, source_name, sets, std::cerr);
}

Scene read_scene_file(const std::string& path, const std::vector<std::string>& sets) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(one_line(path + ": cannot open scene file: " + std::strerror(errno)));
  std::ostringstream text;
  text << in.rdbuf();
  return read_scene_text(text.str(), path, sets);
}

}  // namespace arksph
