// The interface between two phases (Rayleigh-Taylor, Szewc et al. 2012 §7.2, Cummins & Rudman 1999
// §3.2): the 0.5 contour of a kernel-smoothed phase indicator,
//   chi(x) = sum_b V_b chi_b W(x - x_b) / sum_b V_b W(x - x_b),  chi_b = 1 for phase >= 1, else 0,
// evaluated on the nodes of a regular grid (spacing fluid.spacing, walls included; ghosts carry
// their source's phase; a node with no particle within the kernel support is a void and no contour
// crosses its cells) and contoured by marching squares. The bubble tip is the highest point of
// the contour (the light lower fluid rising), the spike tip the lowest (the heavy upper fluid
// falling). Also the density statistics of Szewc eqs. 55-56 restricted to the upper phase.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "rhs/fluid_fields.hpp"

namespace arksph {

struct PhaseInterface {
  std::vector<std::array<double, 4>> segments;  // x0, y0, x1, y1
  double bubble_y = 0, spike_y = 0;             // highest and lowest contour points
};

// f: fresh fields (real particles then ghosts); phase: per real particle.
PhaseInterface phase_interface(const FluidFields& f, const std::vector<std::int32_t>& phase, double xmin,
                               double ymin, double xmax, double ymax, double spacing);

struct PhaseDensity {
  double mean = 0, rms = 0;  // Szewc eqs. 55-56 over the particles of phase >= 1
};
PhaseDensity upper_phase_density(const FluidFields& f, const std::vector<std::int32_t>& phase,
                                 const std::vector<double>& number_density);

}  // namespace arksph
