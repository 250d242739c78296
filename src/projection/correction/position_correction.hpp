// A position correction applied after a step's projection (method.density_correction): one process's
// (DensityCorrection_PozorskiWawrenczuk.hpp) or one rank's (distributed/halo_density_correction.hpp).
#pragma once
#include <cstdint>
#include <vector>

namespace arksph {

struct CorrectionStats {
  long applications = 0;   // steps in which it ran
  long iterations = 0;     // Poisson solves
  double seconds = 0;
  std::vector<double> first_history;  // r.m.s. relative density error before each iteration of the first application, and after the last
};

class PositionCorrection {
 public:
  virtual ~PositionCorrection() = default;
  // Corrects the positions in y (the end of a step, time t) in place.
  virtual void apply(double t, double* y) = 0;
  virtual const CorrectionStats& stats() const = 0;
  // Drops the warm start and the solver's set-up (a restart, or the particles moved to other ranks).
  virtual void forget_warm_start() = 0;
  // The particles re-ordered: the warm start follows (new index i is old index from[i]).
  virtual void permute_particles(const std::vector<std::uint32_t>& from) = 0;
};

}  // namespace arksph
