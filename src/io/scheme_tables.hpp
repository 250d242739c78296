// Scene keys that apply to one scheme only: the table [for_scheme.<scheme>.<table>] holds keys of the
// scene table <table> that take effect when method.scheme (after the --set options) is <scheme>,
// e.g. a case that reproduces a weakly compressible paper pins its regularisation for wcsph only:
//
//   [method]
//   scheme = "wcsph"
//   [for_scheme.wcsph.method]
//   regularisation = "none"      # the paper's scheme; another scheme keeps the "auto" default
//
// A key given by --set wins over the scheme's table; the scheme itself cannot be set there.
#pragma once
#include <toml++/toml.h>

#include <string>
#include <utility>
#include <vector>

#include "io/scene_schema.hpp"

namespace arksph {

// Checks every [for_scheme.*] table of `tree` (registered scheme names, known tables and keys: one
// InputError line otherwise), copies the keys of the table of the scene's scheme into their tables,
// except those named by `overrides` (the --set keys), and removes [for_scheme] from the tree.
// Returns (dotted key, "SOURCE (for_scheme.<scheme>)") for every key copied: where a bad value came
// from, in the form of scene_schema::Reporter's overrides.
std::vector<std::pair<std::string, std::string>> apply_scheme_tables(const scene_schema::Reporter& rep, toml::table& tree,
                         const std::vector<std::pair<std::string, std::string>>& overrides);

}  // namespace arksph
