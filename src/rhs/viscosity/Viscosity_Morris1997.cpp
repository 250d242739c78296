#include "rhs/viscosity/Viscosity_Morris1997.hpp"

#include "rhs/term_registry.hpp"
#include "rhs/terms.hpp"

namespace arksph {

Part<TermFactory> viscosity_morris() {
  return {"morris", "model E of Basa et al. 2008 (eq. 35), the viscosity of Morris et al. 1997",
          [](const Scene&) -> std::unique_ptr<Term> { return std::make_unique<ViscosityMorris>(); }, {},
          {.can_be_implicit = true}};
}

}  // namespace arksph
