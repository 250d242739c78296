#include "rhs/density/Continuity_Szewc2012.hpp"

#include "rhs/term_registry.hpp"
#include "rhs/terms.hpp"

namespace arksph {

std::unique_ptr<Term> make_continuity() { return std::make_unique<ContinuitySzewc>(); }

Part<TermFactory> density_continuity() {
  return {"continuity", "density from the continuity equation in the ODE state (Szewc et al. 2012 eq. 19)",
          [](const Scene&) { return make_continuity(); }, {}, {.state = {"density"}}};
}

}  // namespace arksph
