#include "io/scheme_tables.hpp"

#include <algorithm>

#include "io/names.hpp"
#include "io/scene_catalog.hpp"

namespace arksph {
namespace {

constexpr const char* kTable = "for_scheme";

// The scene tables a scheme's table may hold: all but the scene's name and the [[phase]] regions.
std::vector<std::string> scheme_dependent_tables() {
  std::vector<std::string> tables;
  for (const std::string& t : scene_tables())
    if (t != "scene" && t != "phase") tables.push_back(t);
  return tables;
}

// The scheme the scene runs: method.scheme of the tree (the --set options applied), or its default.
// Empty when the tree's value is not a string: the scene reader reports that.
std::string scene_scheme(const toml::table& tree) {
  if (const toml::node* v = tree.at_path("method.scheme").node()) return v->value_or(std::string());
  for (const CatalogKey& k : scene_catalog())
    if (k.param.key == "method.scheme") return std::get<std::string>(k.param.fallback);
  return {};
}

bool overridden(const std::vector<std::pair<std::string, std::string>>& overrides, const std::string& key) {
  return std::any_of(overrides.begin(), overrides.end(), [&](const auto& o) {
    const std::string& set = o.first;
    return set == key || key.rfind(set + ".", 0) == 0 || set.rfind(key + ".", 0) == 0;
  });
}

}  // namespace

std::vector<std::pair<std::string, std::string>> apply_scheme_tables(
    const scene_schema::Reporter& rep, toml::table& tree,
    const std::vector<std::pair<std::string, std::string>>& overrides) {
  std::vector<std::pair<std::string, std::string>> copied;
  const toml::node* node = tree.get(kTable);
  if (!node) return copied;
  // Every scheme's table is checked, not only the one that runs: a misspelt key must not wait for
  // the day its scheme is chosen. Values are checked when their scheme runs.
  const scene_schema::Section all(rep, node, kTable, registered_names("scheme"));
  const std::vector<std::string> tables = scheme_dependent_tables();
  for (const auto& [scheme, table] : *node->as_table()) {
    const scene_schema::Section per = all.section(scheme.str(), tables);
    for (const std::string& t : tables) {
      const scene_schema::Section keys = per.section(t, keys_of_table(t));
      if (t == "method" && keys.has("scheme")) keys.fail("scheme", "the scheme cannot depend on the scheme");
    }
  }
  const std::string scheme = scene_scheme(tree);
  toml::table chosen;
  if (const toml::table* own = node->as_table()->get_as<toml::table>(scheme)) chosen = *own;
  tree.erase(kTable);
  for (const auto& [name, sub] : chosen) {
    const std::string t(name.str());
    if (!tree.get(t)) tree.insert(t, toml::table{});
    toml::table* target = tree.get_as<toml::table>(t);
    if (!target) continue;  // [t] is not a table: the scene reader reports it
    for (const auto& [key, value] : *sub.as_table()) {
      const std::string dotted = t + "." + std::string(key.str());
      if (overridden(overrides, dotted)) continue;
      value.visit([&](const auto& v) { target->insert_or_assign(key.str(), v); });
      copied.emplace_back(dotted, rep.source() + " (" + kTable + "." + scheme + ")");
    }
  }
  return copied;
}

}  // namespace arksph
