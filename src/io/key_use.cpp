#include "io/key_use.hpp"

#include <algorithm>
#include <string>

#include "core/scheme.hpp"

namespace arksph {
namespace {

// The text value of the scene key `key` (a family selector), or "" when no such key exists.
std::string selected_part(const std::string& key, const Scene& s) {
  for (const CatalogKey& c : scene_catalog())
    if (c.param.key == key && c.param.load) {
      const ParamValue v = c.param.load(s);
      if (const auto* text = std::get_if<std::string>(&v)) return *text;
    }
  return "";
}

// A group of keys named after a scheme: "isph" holds the keys of both projection schemes.
bool scheme_group_in_use(const std::string& owner, const Scene& s) {
  if (owner == "wcsph") return scheme_traits(s.scheme).weakly_compressible;
  if (owner == "isph") return !scheme_traits(s.scheme).weakly_compressible;
  if (owner == "isph-gpps") return scheme_traits(s.scheme).grid;
  return true;
}

}  // namespace

bool key_in_use(const CatalogKey& k, const Scene& s) {
  const Param& p = k.param;
  if (!p.schemes.empty() && std::find(p.schemes.begin(), p.schemes.end(), s.scheme) == p.schemes.end())
    return false;
  if (!scheme_group_in_use(k.owner, s)) return false;
  if (const auto colon = k.owner.find(": "); colon != std::string::npos) {
    const FamilyInfo* f = find_family(k.owner.substr(0, colon));
    if (f && selected_part(f->key, s) != k.owner.substr(colon + 2)) return false;
  }
  if (!p.family.empty()) {
    const FamilyInfo* f = find_family(p.family);
    if (f && std::none_of(f->entries.begin(), f->entries.end(), [&](const FamilyInfo::Entry& e) {
          return e.name != "none" && e.traits.applies_to(s.scheme);
        }))
      return false;
  }
  return true;
}

}  // namespace arksph
