// Names registered by the numerical modules, grouped by family (io/scene_catalog.hpp lists the
// families), for validation and `arksph list`.
#pragma once
#include <string>
#include <vector>

namespace arksph {

std::vector<std::string> registered_names(const std::string& family);
bool is_registered(const std::string& family, const std::string& name);

}  // namespace arksph
