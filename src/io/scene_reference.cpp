// docs/scene-reference.md, generated from the scene catalog (`arksph scene-reference`).
#include <sstream>

#include "io/scene_catalog.hpp"
#include "io/scene_reader.hpp"
#include "io/scene_schema.hpp"

namespace arksph {

namespace {

const char* type_name(const Param& p) {
  switch (p.type) {
    case Param::Type::boolean: return "boolean";
    case Param::Type::integer: return "integer";
    case Param::Type::whole: return "whole number";
    case Param::Type::number: return "number";
    case Param::Type::text: return "string";
    case Param::Type::choice: return "name";
    case Param::Type::numbers: return "numbers (one per dimension)";
    case Param::Type::expressions: return "expressions (one per dimension)";
    case Param::Type::table: return "table";
  }
  return "";
}

std::string cell(std::string s) {  // Markdown table cell: no bar, no newline
  for (char& c : s)
    if (c == '\n') c = ' ';
  std::string out;
  for (char c : s) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

std::string default_text(const Param& p) {
  if (p.required) return "required";
  if (p.custom) return "";
  struct Text {
    std::string operator()(bool b) const { return b ? "true" : "false"; }
    std::string operator()(long i) const { return std::to_string(i); }
    std::string operator()(double d) const { return scene_schema::format_number(d); }
    std::string operator()(const std::string& s) const { return "\"" + s + "\""; }
    std::string operator()(const std::vector<double>&) const { return ""; }
    std::string operator()(const std::vector<std::string>& v) const {
      std::string out;
      for (const auto& e : v) out += (out.empty() ? "\"" : ", \"") + e + "\"";
      return "[" + out + "]";
    }
  };
  return std::visit(Text{}, p.fallback);
}

std::string admissible(const Param& p) {
  if (p.type == Param::Type::boolean && p.automatic) return "true, false, or auto (see the description)";
  if (p.type == Param::Type::choice) {
    const std::string automatic = p.automatic ? ", or auto (see the description)" : "";
    if (!p.family.empty()) return "a registered " + p.family + " (below)" + automatic;
    std::string list;
    for (const auto& c : p.choices) list += (list.empty() ? "" : ", ") + c;
    return list + automatic;
  }
  if (!p.allowed.empty()) {
    std::string list;
    for (long a : p.allowed) list += (list.empty() ? "" : ", ") + std::to_string(a);
    return list;
  }
  if (p.type == Param::Type::expressions) {
    std::string vars;
    for (const auto& v : p.variables) vars += (vars.empty() ? "" : ", ") + v;
    return "in " + vars;
  }
  return p.range.describe();
}

}  // namespace

std::string scene_reference_markdown() {
  std::ostringstream o;
  o << "# Scene reference\n\n"
    << "Every key of a scene file, generated from the parameters that the code declares "
       "(`arksph scene-reference` prints this page; a test fails when the committed copy is stale).\n"
    << "Keys are dotted paths: `[method]` + `kernel = ...` is `method.kernel`, which `--set method.kernel=...` "
       "overrides. \"Declared by\" names the family or part that reads the key.\n"
    << "A key of any table but `[scene]` and `[[phase]]` may also sit in `[for_scheme.<scheme>.<table>]`, where it takes effect "
       "only when `method.scheme` is `<scheme>` ([user-guide.md](user-guide.md), \"Keys for one scheme\").\n";
  for (const std::string& table : scene_tables()) {
    o << "\n## [" << (table == "phase" ? "[phase]" : table) << "]\n\n"
      << "| key | type | default | admissible | unit | description | declared by |\n"
      << "|---|---|---|---|---|---|---|\n";
    for (const CatalogKey& k : scene_catalog()) {
      const Param& p = k.param;
      if (p.key.compare(0, table.size() + 1, table + ".") != 0) continue;
      o << "| `" << p.key << "` | " << type_name(p) << " | " << cell(default_text(p)) << " | "
        << cell(admissible(p)) << " | " << cell(p.unit) << " | " << cell(p.doc) << " | " << cell(k.owner) << " |\n";
    }
  }
  o << "\n## Registered parts\n";
  for (const FamilyInfo& f : scene_families()) {
    o << "\n### " << f.family << " (`" << f.key << "`)\n\n| name | description |\n|---|---|\n";
    for (const auto& e : f.entries) {
      std::string notes = e.summary;
      std::vector<std::string> traits;
      if (!e.traits.schemes.empty()) traits.push_back("schemes: " + scene_schema::join(e.traits.schemes));
      if (e.traits.can_be_implicit) traits.push_back("may be implicit (time.imex)");
      if (e.traits.stencil_depth > 1) traits.push_back("stencil depth " + std::to_string(e.traits.stencil_depth));
      if (!e.traits.state.empty()) traits.push_back("adds to the state: " + scene_schema::join(e.traits.state));
      std::string list;
      for (const auto& x : traits) list += (list.empty() ? "" : "; ") + x;
      if (!list.empty()) notes += " (" + list + ")";
      o << "| `" << e.name << "` | " << cell(notes) << " |\n";
    }
  }
  return o.str();
}

}  // namespace arksph
