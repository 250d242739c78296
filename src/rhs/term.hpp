// One physical term of the right-hand side. Each term lives in its own file, named after the term
// and its source, and is constructed only when the scene needs it (rhs/terms_from_scene.cpp).
#pragma once
#include <string>

#include "rhs/fluid_fields.hpp"

namespace arksph {

class Term {
 public:
  // Terms run in stage order: density (fills rho of real particles), pressure (fills p),
  // force (adds to dudt, dvdt, drhodt). Ghost copies of rho and p are refreshed between stages.
  enum class Stage { density, pressure, force };
  virtual ~Term() = default;
  virtual std::string name() const = 0;  // "kind:model", listed in summary.json "terms"
  virtual Stage stage() const = 0;
  virtual void apply(FluidFields& f) const = 0;
};

}  // namespace arksph
