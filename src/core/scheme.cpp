// The registered schemes: one line each.
#include "core/scheme.hpp"

namespace arksph {

const Registry<SchemeTraits>& scheme_registry() {
  static const Registry<SchemeTraits> registry("scheme", "method.scheme", {
      {"wcsph", "weakly compressible SPH, Tait equation of state (Szewc et al. 2012 §4.1)", {.weakly_compressible = true}},
      {"isph", "incompressible SPH by pressure projection on the particles (Cummins & Rudman 1999)", {.projection = true}},
      {"isph-gpps", "incompressible SPH, Poisson equation on an auxiliary grid (Szewc et al. 2012 §4.2)", {.projection = true, .grid = true}},
  });
  return registry;
}

const SchemeTraits& scheme_traits(const std::string& name) { return scheme_registry().at(name).make; }

}  // namespace arksph
