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
#include <functional>
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

// The same in two parts, for sums gathered elsewhere (a decomposed run): the indicator's numerator
// and denominator at the grid nodes, which add up over disjoint sets of nodes, and the contour.
struct IndicatorGrid {
  IndicatorGrid(double xmin, double ymin, double xmax, double ymax, double spacing);
  long nx = 0, ny = 0;
  double xmin = 0, ymin = 0, spacing = 0;
  std::vector<double> num, den;  // node (i, j) at j nx + i
};
// Adds the sums over every point of f (real and ghost; phase per real point, ghosts take their
// source's) at the nodes for which owns(x, y) holds.
void add_phase_indicator(const FluidFields& f, const std::int32_t* phase, IndicatorGrid& grid,
                         const std::function<bool(double, double)>& owns);
PhaseInterface contour_phase_indicator(const IndicatorGrid& grid);

struct PhaseDensity {
  double mean = 0, rms = 0;  // Szewc eqs. 55-56 over the particles of phase >= 1 (frame_reduction.hpp)
};

}  // namespace arksph
