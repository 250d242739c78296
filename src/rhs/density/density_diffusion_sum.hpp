// What another force term needs to add delta-SPH (rhs/density/DensityDiffusion_Antuono2010.cpp) in its own
// pair loop over the same neighbours (Term::take_over): without a hydrostatic part, delta-SPH adds
//   drho_a/dt += coeff sum_b -F_ab V_b (rho_b - rho_a),   coeff = 2 delta h c,
// and a term that already visits V_b (rho_b - rho_a) for every neighbour adds it for two more
// operations per pair instead of a loop of its own.
#pragma once
#include <optional>

namespace arksph {

class DensityDiffusionSum {
 public:
  virtual ~DensityDiffusionSum() = default;
  // coeff, or nothing when the term leaves out a hydrostatic part (a per-pair correction that only
  // the term itself adds).
  virtual std::optional<double> plain_coefficient() const = 0;
};

}  // namespace arksph
