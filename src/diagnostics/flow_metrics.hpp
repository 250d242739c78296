// Whole-flow diagnostics written to timeseries.csv and summary.json.
#pragma once
#include <vector>

#include "core/particles.hpp"
#include "rhs/fluid_fields.hpp"

namespace arksph {

struct FlowMetrics {
  double kinetic_energy = 0;  // sum_a m_a |u_a|^2 / 2
  double max_speed = 0;
  double cv = 0;              // Cummins & Rudman 1999 eqs. 24-25
  double density_mean = 0;    // Szewc et al. 2012 eq. 55
  double density_rms = 0;     // Szewc et al. 2012 eq. 56
};

// Number density d_a = sum_b W_ab (C&R eq. 25), self and ghost neighbours included, so that a
// particle next to a wall has the same d_a as one in the bulk on the initial lattice.
std::vector<double> number_density(const FluidFields& f);

// fields must be fresh (RhsEvaluator::eval at the current state). d0: number density at t = 0.
FlowMetrics flow_metrics(const FluidFields& f, const std::vector<double>& d0);

}  // namespace arksph
