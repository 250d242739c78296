// Registered names by family, from the scene catalog's families.
#include "io/names.hpp"

#include <algorithm>

#include "io/scene_catalog.hpp"

namespace arksph {

std::vector<std::string> registered_names(const std::string& family) {
  std::vector<std::string> names;
  if (const FamilyInfo* f = find_family(family))
    for (const auto& e : f->entries) names.push_back(e.name);
  return names;
}

bool is_registered(const std::string& family, const std::string& name) {
  const auto names = registered_names(family);
  return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace arksph
