// Scene reader: parse the TOML text, apply the --set overrides to the tree, then the keys of the
// scene's scheme ([for_scheme.<scheme>], io/scheme_tables.hpp), read every key of the
// scene catalog (io/scene_catalog.hpp) by its declared type, range and choices, then the box, the
// sides and the phases, and check the combinations that no single key can.
#include "io/scene_reader.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cerrno>
#include <map>
#include <optional>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>

#include "core/errors.hpp"
#include "core/expression.hpp"
#include "core/projection_method.hpp"
#include "core/scheme.hpp"
#include "diagnostics/energy_budget.hpp"
#include "io/input_file.hpp"
#include "io/scene_catalog.hpp"
#include "io/scene_defaults.hpp"
#include "io/scene_limits.hpp"
#include "io/scene_schema.hpp"
#include "io/scheme_tables.hpp"
#include "projection/correction/DensityCorrection_PozorskiWawrenczuk.hpp"
#include "projection/poisson/poisson_solver.hpp"
#include "projection/projection_options.hpp"

namespace arksph {

namespace {

using scene_schema::format_number;
using scene_schema::Reporter;
using scene_schema::Section;

const char* const kAxis[2] = {"x", "y"};

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
  const std::string option = "--set " + echo_value(set);
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
                                         "time.end, got \"" + echo_value(key) + "\""));

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
    if (!t) throw InputError(one_line(option + ": " + echo_value(walked) + ": is not a table, cannot set " + echo_value(key)));
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

// True when `where` selects a point of the initial lattice min + (i + 1/2) spacing that holds fluid
// (fluid.region).
bool selects_fluid(const Scene& s, const std::string& where) {
  const Expression region(where, {"x", "y"});
  const std::optional<Expression> fluid =
      s.fluid_region.empty() ? std::nullopt : std::optional<Expression>(Expression(s.fluid_region, {"x", "y"}));
  const long nx = std::lround((s.max[0] - s.min[0]) / s.spacing);
  const long ny = s.dimension == 2 ? std::lround((s.max[1] - s.min[1]) / s.spacing) : 1;
  for (long j = 0; j < ny; ++j) {
    const double y = s.dimension == 2 ? s.min[1] + (j + 0.5) * s.spacing : 0.0;
    for (long i = 0; i < nx; ++i) {
      const double x = s.min[0] + (i + 0.5) * s.spacing;
      if (region.eval(x, y) != 0.0 && (!fluid || fluid->eval(x, y) != 0.0)) return true;
    }
  }
  return false;
}

// Fails unless `where` selects at least one fluid particle of the initial lattice.
void check_phase_region(const Scene& s, const Section& phase, const std::string& where) {
  if (!selects_fluid(s, where))
    phase.fail("where", s.fluid_region.empty() ? "selects no particle of the initial lattice"
                                               : "selects no particle of the initial lattice inside fluid.region");
}

// One value of a key declared in the catalog, checked against its type, range and choices.
ParamValue read_value(const Section& sec, const std::string& name, const Param& p, const Scene& s) {
  switch (p.type) {
    case Param::Type::boolean:  // a key with a rule has the fallback "auto" and is read here only when set
      return sec.boolean(name, std::holds_alternative<bool>(p.fallback) ? std::get<bool>(p.fallback) : false);
    case Param::Type::integer: {
      const long v = sec.integer(name, p.required ? std::nullopt : std::optional<long>(std::get<long>(p.fallback)));
      if (!p.allowed.empty() && std::find(p.allowed.begin(), p.allowed.end(), v) == p.allowed.end()) {
        std::string list;  // "0, 100 or 1000"
        for (std::size_t i = 0; i < p.allowed.size(); ++i)
          list += (i == 0 ? "" : i + 1 == p.allowed.size() ? " or " : ", ") + std::to_string(p.allowed[i]);
        sec.fail(name, "must be " + list + ", got " + std::to_string(v));
      }
      sec.require(p.range.contains(static_cast<double>(v)), name, p.range.describe(), static_cast<double>(v));
      return v;
    }
    case Param::Type::whole: {
      const double v = sec.number(name, p.required ? std::nullopt
                                                   : std::optional<double>(static_cast<double>(std::get<long>(p.fallback))));
      sec.require(p.range.contains(v) && v == std::floor(v), name, "a whole number " + p.range.describe(), v);
      return static_cast<long>(v);
    }
    case Param::Type::number: {
      const double v = sec.number(name, p.required ? std::nullopt : std::optional<double>(std::get<double>(p.fallback)));
      sec.require(p.range.contains(v), name, p.range.describe(), v);
      return v;
    }
    case Param::Type::text:
      return sec.string(name, p.required ? std::nullopt : std::optional<std::string>(std::get<std::string>(p.fallback)));
    case Param::Type::choice: {
      const std::string& fallback = std::get<std::string>(p.fallback);
      return p.family.empty() ? sec.one_of(name, p.choices, fallback) : sec.registered(name, p.family, fallback);
    }
    case Param::Type::expressions:
      return sec.expressions(name, s.dimension, p.variables, std::vector<std::string>(s.dimension, "0"));
    case Param::Type::numbers:
    case Param::Type::table: break;
  }
  sec.fail(name, "is read by the scene reader's own code");
}

void read_domain(const Section& domain, Scene& s) {
  const std::size_t dim = s.dimension;
  const auto lo = domain.numbers("min", dim, std::nullopt);
  const auto hi = domain.numbers("max", dim, std::nullopt);
  for (std::size_t d = 0; d < dim; ++d)
    if (!(hi[d] > lo[d]))
      domain.fail("max", "must exceed domain.min in every component (max[" + std::to_string(d) +
                             "] = " + format_number(hi[d]) + ", min[" + std::to_string(d) + "] = " +
                             format_number(lo[d]) + ")");
  s.min = {lo[0], dim == 2 ? lo[1] : 0.0};
  s.max = {hi[0], dim == 2 ? hi[1] : 0.0};
}

void read_sides(const Section& b, Scene& s) {
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
  bool any_wall = false;
  for (std::size_t i = 0; i < 2 * dim; ++i) any_wall |= s.sides[i].kind == SideKind::wall;
  if (s.free_slip_divergence && !any_wall)
    b.fail("free_slip_divergence", "needs at least one wall, but every side is periodic");
}

void check_fluid(const Section& f, const Scene& s) {
  const std::size_t dim = s.dimension;
  for (std::size_t d = 0; d < dim; ++d) check_lattice(f, s.spacing, s.max[d] - s.min[d], d);
  // A count no machine holds must be a message, not std::bad_alloc (or an endless phase check).
  double particles = 1;
  for (std::size_t d = 0; d < dim; ++d) particles *= std::round((s.max[d] - s.min[d]) / s.spacing);
  if (!(particles <= 2e8))
    f.fail("spacing", format_number(particles) + " particles exceed the limit of 2e8");
  if (s.fluid_region.empty()) return;
  try {
    Expression(s.fluid_region, {"x", "y"});
  } catch (const InputError& e) {
    f.fail("region", e.what());
  }
  if (!selects_fluid(s, s.fluid_region))
    f.fail("region", "\"" + echo_value(s.fluid_region) + "\" selects no point of the initial lattice in the domain [" +
                         format_number(s.min[0]) + ", " + format_number(s.max[0]) + "]" +
                         (s.dimension == 2 ? " x [" + format_number(s.min[1]) + ", " + format_number(s.max[1]) + "]" : "") +
                         ": the domain would hold no fluid");
  const SchemeTraits& scheme = scheme_traits(s.scheme);
  if (scheme.grid)  // Szewc et al. 2012 §4.2: the grid's Poisson equation fills the box
    f.fail("region", "a free surface needs the pressure on the particles: isph-gpps solves it on a grid over the "
                     "whole box (Szewc et al. 2012), which has no free surface; use wcsph");
  // ISPH: C&R's projection and the constrained one take the surface's rows
  // (projection/free_surface.hpp); the orthogonal projection's coarse pressure space has none.
  if (!scheme.weakly_compressible && s.projection == ProjectionMethod::orthogonal)
    f.fail("region", "a free surface under method.projection = \"orthogonal\": its coarse pressure space has no rows "
                     "for the surface (docs/methods/free-surface.md); use \"constrained\" or \"cummins_rudman\"");
  // The P-W correction moves the particles until their summation density is rho0 (Szewc et al.
  // 2012 eqs. 57-58), which the cut supports at a surface cannot reach: there it solves for nothing
  // (the a/20 dam break: 8 % r.m.s. density error at every step, no iteration taken).
  if (density_corrections().at(s.density_correction).traits.corrects_density)
    f.fail("region", "a free surface with method.density_correction = \"" + s.density_correction +
                         "\": the correction drives the summation density to the reference density, which the cut "
                         "kernel supports at a surface cannot reach (docs/methods/free-surface.md); use "
                         "method.density_correction = \"none\"");
}

void read_phases(const Section& root, Scene& s) {
  s.phases.clear();
  const toml::node* node = root.node("phase");
  if (!node) return;
  const toml::array* list = node->as_array();
  if (!list || (!list->empty() && !list->is_array_of_tables()))
    root.fail("phase", "expected an array of tables ([[phase]] sections)");
  for (std::size_t i = 0; i < list->size(); ++i) {
    const Section p(root.reporter(), list->get(i), "phase[" + std::to_string(i) + "]", keys_of_table("phase"));
    PhaseSpec phase;
    phase.where = p.expression("where", {"x", "y"}, std::nullopt);  // region: non-zero selects
    phase.density = p.number("density", std::nullopt);             // reference density of the phase
    p.require(phase.density > 0, "density", "> 0", phase.density);
    check_phase_region(s, p, phase.where);
    s.phases.push_back(phase);
  }
}

// Selected parts must apply to the scheme; keys of other schemes give a warning when set.
void check_schemes(const std::map<std::string, Section>& sections, const Scene& s,
                   const std::vector<const CatalogKey*>& automatic) {
  for (const CatalogKey& k : scene_catalog()) {
    const Param& p = k.param;
    if (p.custom || std::find(automatic.begin(), automatic.end(), &k) != automatic.end()) continue;
    const auto dot = p.key.find('.');
    const Section& sec = sections.at(p.key.substr(0, dot));
    const std::string name = p.key.substr(dot + 1);
    if (!p.family.empty()) {
      const FamilyInfo* f = find_family(p.family);
      const std::string chosen = std::get<std::string>(p.load(s));
      for (const auto& e : f->entries)
        if (e.name == chosen && !e.traits.applies_to(s.scheme))
          sec.fail(name, "\"" + chosen + "\" needs scheme " + scene_schema::join(e.traits.schemes) + " (got \"" +
                             s.scheme + "\")");
    }
    if (!p.schemes.empty() && std::find(p.schemes.begin(), p.schemes.end(), s.scheme) == p.schemes.end() &&
        p.load(s) != p.fallback)
      sec.reporter().warn(sec.key(name), "unused by scheme " + s.scheme);
  }
}

// A key with a rule (Param::automatic) left out, or set to "auto": its value is chosen once the
// whole scene is read (resolve_automatic).
bool left_automatic(const Section& sec, const std::string& name, const Param& p) {
  if (!p.automatic) return false;
  if (!sec.has(name)) return true;
  const toml::node* n = sec.node(name);
  return n->is_string() && *n->value_exact<std::string>() == "auto";
}

void check_method(const Section& m, Scene& s) {
  // What the constrained projection (pressure inside f) does not combine with: one line naming both keys.
  if (s.pressure_in_f()) {
    const std::string value = "\"" + projection_methods().name(s.projection) + "\"";
    if (scheme_traits(s.scheme).grid)
      m.fail("projection", value + " needs the particle Poisson equation: method.scheme = \"isph\" (got \"" +
                               s.scheme + "\")");
    if (s.projection_points != ProjectionPoints::step)
      m.fail("projection", value + " projects inside f: method.projection_points = \"" +
                               projection_options().projection_points.name(s.projection_points) +
                               "\" does not apply");
    if (s.ppe_operator != PpeOperator::approximate)
      m.fail("projection", value + " builds its own operator: method.ppe_operator = \"" +
                               projection_options().ppe_operator.name(s.ppe_operator) +
                               "\" does not apply");
  }
  if (s.projection == ProjectionMethod::orthogonal && s.dimension != 2)
    m.fail("projection", "\"orthogonal\" needs a 2D scene (scene.dimension = " + std::to_string(s.dimension) + ")");
  if (s.ppe_operator == PpeOperator::exact) {
    s.ppe_solver = exact_operator_solver(s.ppe_solver);
    if (s.ppe_solver.empty())
      m.fail("ppe_operator", "the exact operator is not symmetric: it needs method.ppe_solver = \"klu\"");
  }
}

// metrics.energy_budget: the potential energy -m g . r needs g constant, and a force along a
// periodic axis has none (the positions wrap around; the force does work without end).
void check_energy_budget(const Section& metrics, const Scene& s) {
  if (!constant_body_force(s))
    metrics.fail("energy_budget", "needs a constant fluid.body_force (no x, y or t): a varying force has no potential energy -m g . r");
  for (int k = 0; k < s.dimension; ++k) {
    const double g = Expression(s.body_force.at(static_cast<std::size_t>(k)), {"x", "y", "t"}).eval(0, 0, 0);
    if (g != 0 && s.sides[static_cast<std::size_t>(2 * k)].kind == SideKind::periodic)
      metrics.fail("energy_budget", std::string("fluid.body_force has a component along the periodic ") +
                                        (k == 0 ? "x" : "y") + " axis, which has no potential energy -m g . r");
  }
}

void check_time_output(const std::map<std::string, Section>& sections, Scene& s) {
  if (s.imex && !scheme_traits(s.scheme).weakly_compressible && !s.pressure_in_f())
    sections.at("time").fail("imex", "needs method.scheme = \"wcsph\", or \"isph\" with method.projection = \"constrained\" or \"orthogonal\" (got scheme \"" +
                                         s.scheme + "\", projection \"" + projection_methods().name(s.projection) + "\")");
  const Section& o = sections.at("output");
  if (!o.has("directory")) s.directory = default_output_directory(s);
  if (s.directory.empty()) o.fail("directory", "must not be empty");
  if (s.interface && (s.phases.empty() || s.dimension != 2))
    sections.at("metrics").fail("interface", "needs a 2D scene with at least one [[phase]]");
  if (s.energy_budget) check_energy_budget(sections.at("metrics"), s);
}

}  // namespace

Scene read_scene_text(const std::string& toml_text, const std::string& source_name,
                      const std::vector<std::string>& sets, std::ostream& warnings) {
  toml::table tree = parse_document(toml_text, source_name);
  std::vector<std::pair<std::string, std::string>> overrides;
  for (const auto& set : sets) overrides.push_back(apply_override(tree, set));
  // A problem with a key names where it came from: --set options last (they win), then the table
  // of the scene's scheme, else the file.
  std::vector<std::pair<std::string, std::string>> origins =
      apply_scheme_tables(Reporter(source_name, overrides, &warnings), tree, overrides);
  origins.insert(origins.end(), overrides.begin(), overrides.end());
  const Reporter rep(source_name, origins, &warnings);
  std::vector<std::string> top = scene_tables();
  top.push_back("for_scheme");  // gone from the tree by now; named in the message for an unknown table
  const Section root(rep, &tree, "", top);
  std::map<std::string, Section> sections;  // every table but [[phase]], unknown keys rejected here
  for (const std::string& table : scene_tables())
    if (table != "phase") sections.emplace(table, root.section(table, keys_of_table(table)));
  Scene s = scene_defaults();  // every key below is stored again: the file's value or the default
  s.source = source_name;
  std::vector<const CatalogKey*> automatic;  // keys left at "auto", in catalog order
  for (const CatalogKey& k : scene_catalog()) {
    if (k.param.key == "domain.max") read_domain(sections.at("domain"), s);  // the box before the rest
    if (k.param.custom) continue;
    const auto dot = k.param.key.find('.');
    const Section& sec = sections.at(k.param.key.substr(0, dot));
    const std::string name = k.param.key.substr(dot + 1);
    if (left_automatic(sec, name, k.param)) automatic.push_back(&k);
    else k.param.store(s, read_value(sec, name, k.param, s));
  }
  if (s.name.empty()) sections.at("scene").fail("name", "must not be empty");
  read_sides(sections.at("boundary"), s);
  check_fluid(sections.at("fluid"), s);
  read_phases(root, s);
  check_schemes(sections, s, automatic);
  resolve_automatic(s, automatic);
  check_method(sections.at("method"), s);
  check_time_output(sections, s);
  check_scene_limits(sections, s);
  s.resolved_toml = scene_to_toml(s);
  return s;
}

Scene read_scene_text(const std::string& toml_text, const std::string& source_name,
                      const std::vector<std::string>& sets) {
  return read_scene_text(toml_text, source_name, sets, std::cerr);
}

Scene read_scene_file(const std::string& path, const std::vector<std::string>& sets) {
  return read_scene_text(read_input_file(path, "scene"), path, sets);
}

}  // namespace arksph
