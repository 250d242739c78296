// The schemes a scene selects with method.scheme, registered by name with the traits the rest of the
// code asks instead of comparing names.
#pragma once
#include <string>

#include "core/registry.hpp"

namespace arksph {

// For a scheme the registered "factory" is the description of its structure.
struct SchemeTraits {
  bool weakly_compressible = false;  // pressure from an equation of state; density may be in the state
  bool projection = false;           // a pressure Poisson equation projects the velocity
  bool grid = false;                 // the Poisson equation is solved on an auxiliary grid
  // The Poisson equation is assembled on the particles (one matrix entry per neighbour pair).
  bool particle_poisson() const { return projection && !grid; }
};

const Registry<SchemeTraits>& scheme_registry();
// The traits of a registered scheme (std::out_of_range otherwise).
const SchemeTraits& scheme_traits(const std::string& name);

}  // namespace arksph
