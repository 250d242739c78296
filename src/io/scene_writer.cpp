// Scene -> TOML text with every key of the scene catalog, in its order (Scene::resolved_toml), and
// the same text with each key's description as a comment (`arksph default-scene`). Numbers are
// written in their shortest exact form, so the text reads back to the same Scene.
#include <toml++/toml.h>

#include <sstream>

#include "io/scene_catalog.hpp"
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

std::string value_text(const ParamValue& v) {
  struct Text {
    std::string operator()(bool b) const { return b ? "true" : "false"; }
    std::string operator()(long i) const { return std::to_string(i); }
    std::string operator()(double d) const { return num(d); }
    std::string operator()(const std::string& s) const { return quote(s); }
    std::string operator()(const std::vector<double>& v) const { return numbers(v.data(), static_cast<int>(v.size())); }
    std::string operator()(const std::vector<std::string>& v) const { return strings(v); }
  };
  return std::visit(Text{}, v);
}

// The comment of a key: its description, admissible values and unit.
std::string comment(const Param& p) {
  std::string c = p.doc;
  if (p.type == Param::Type::choice) {
    std::vector<std::string> values = p.choices;
    if (!p.family.empty())
      if (const FamilyInfo* f = find_family(p.family))
        for (const auto& e : f->entries) values.push_back(e.name);
    if (p.automatic) values.push_back("auto");
    std::string list;
    for (const auto& v : values) list += (list.empty() ? "" : " | ") + quote(v);
    if (values.size() <= 8) c += ": " + list;
    else c += " (arksph list: " + p.family + ")";
  }
  if (p.type == Param::Type::boolean && p.automatic) c += ": true | false | \"auto\"";
  const std::string range = p.range.describe();
  if (!range.empty() && p.type != Param::Type::choice) c += "; " + range;
  if (!p.unit.empty()) c += " [" + p.unit + "]";
  return c;
}


std::string side_text(const Scene& s, int i) {
  const SideSpec& side = s.sides[i];
  if (side.kind == SideKind::periodic) return "{ kind = " + quote("periodic") + " }";
  return "{ kind = " + quote("wall") + ", velocity = " + numbers(side.velocity.data(), s.dimension) +
         ", slip = " + quote(side.slip == SlipKind::no_slip ? "no_slip" : "free_slip") + " }";
}

// The value of a key the reader handles with its own code; empty when it is not written.
std::string custom_text(const Scene& s, const std::string& key) {
  if (key == "domain.min") return numbers(s.min.data(), s.dimension);
  if (key == "domain.max") return numbers(s.max.data(), s.dimension);
  for (int i = 0; i < 2 * s.dimension; ++i)
    if (key == std::string("boundary.") + kSideNames[i]) return side_text(s, i);
  return "";
}

// The value the rule of `key` chose when the scene had "auto" there; empty otherwise.
std::string automatic_value(const Scene& s, const std::string& key) {
  for (const auto& [k, v] : s.automatic)
    if (k == key) return v;
  return "";
}

std::string write(const Scene& s, bool comments) {
  std::ostringstream o;
  bool first = true;
  for (const std::string& table : scene_tables()) {
    if (table == "phase") {  // [[phase]] blocks, or a commented template without any
      for (const PhaseSpec& p : s.phases)
        o << "\n[[phase]]\nwhere = " << quote(p.where) << "\ndensity = " << num(p.density) << "\n";
      if (comments && s.phases.empty()) {
        o << "\n# Further phases, by region:\n# [[phase]]\n";
        for (const auto& k : scene_catalog())
          if (k.param.key.rfind("phase.", 0) == 0) o << "# " << k.param.key.substr(6) << " = ...   # " << comment(k.param) << "\n";
      }
      continue;
    }
    o << (first ? "" : "\n") << "[" << table << "]\n";
    first = false;
    for (const CatalogKey& k : scene_catalog()) {
      const Param& p = k.param;
      if (p.key.compare(0, table.size() + 1, table + ".") != 0) continue;
      std::string text = p.custom ? custom_text(s, p.key) : value_text(p.load(s));
      if (text.empty()) continue;
      // The commented form shows "auto" where the scene had it, and what it gave; the plain form
      // (Scene::resolved_toml) holds the value, so that it reads back to the same run.
      const std::string chosen = comments ? automatic_value(s, p.key) : "";
      if (!chosen.empty()) text = quote("auto");
      o << p.key.substr(table.size() + 1) << " = " << text;
      if (comments) o << "   # " << comment(p) << (chosen.empty() ? "" : "; auto gives " + quote(chosen) + " here");
      o << "\n";
    }
  }
  if (comments)
    o << "\n# Keys for one scheme only (docs/user-guide.md, 'Keys for one scheme'): they take effect when method.scheme is that\n"
         "# scheme, and --set still wins, e.g.\n"
         "# [for_scheme.wcsph.method]\n"
         "# regularisation = 'none'\n";
  return o.str();
}

}  // namespace

std::string toml_string(const std::string& text) { return quote(text); }

std::string scene_to_toml(const Scene& s) { return write(s, false); }

std::string scene_to_commented_toml(const Scene& s) { return write(s, true); }

}  // namespace arksph
