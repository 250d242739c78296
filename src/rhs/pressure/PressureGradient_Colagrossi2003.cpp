#include "rhs/pressure/PressureGradient_Colagrossi2003.hpp"

#include "rhs/term_registry.hpp"
#include "rhs/terms.hpp"

namespace arksph {

Part<TermFactory> pressure_gradient_colagrossi() {
  return {"colagrossi", "(p_a + p_b) form of Colagrossi & Landrini 2003 (Szewc et al. 2012 eq. 23)",
          [](const Scene&) -> std::unique_ptr<Term> { return std::make_unique<PressureGradientColagrossi>(); }};
}

}  // namespace arksph
