// Every scene key, in the order of the scene file, gathered from the parts that declare them, and
// every family of named parts. The scene reader, the scene writer, `arksph default-scene`,
// `arksph list` and docs/scene-reference.md are generated from these two lists.
#pragma once
#include <string>
#include <vector>

#include "core/parameter.hpp"
#include "core/registry.hpp"

namespace arksph {

struct CatalogKey {
  Param param;
  std::string owner;  // "" for a general key, else "family: part" or "family" that declares it
};

// All keys in file order. A key that selects a part of a family is followed by the family's own
// keys and then by the keys of each of its parts.
const std::vector<CatalogKey>& scene_catalog();

// The families selectable by a scene key, in the order `arksph list` shows them.
const std::vector<FamilyInfo>& scene_families();
// The family named `family`, or nullptr.
const FamilyInfo* find_family(const std::string& family);

// The TOML tables of the scene file in order ("scene", "domain", ..., "phase" for [[phase]]).
std::vector<std::string> scene_tables();
// The keys of table `table` (the part of the dotted key after "table.").
std::vector<std::string> keys_of_table(const std::string& table);

}  // namespace arksph
