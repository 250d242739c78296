// Fields at all points seen by the right-hand-side terms: real particles [0, n_real) followed by
// ghosts [n_real, n_all). Terms read these and write the time derivatives of real particles.
#pragma once
#include <cstdint>
#include <vector>

#include "neighbors/cell_list.hpp"

namespace arksph {

class Kernel;

struct FluidFields {
  int dim = 2;
  std::size_t n_real = 0, n_all = 0;
  double t = 0;
  const Kernel* kernel = nullptr;
  PairList pairs;

  // All points (real then ghosts).
  std::vector<double> x, y;    // positions
  std::vector<double> u, v;    // velocity for the momentum terms
  std::vector<double> ud, vd;  // velocity for the divergence (free-slip images near walls, Szewc §6)
  std::vector<double> rho, p, m;
  std::vector<double> nu;      // kinematic viscosity per point
  std::vector<std::uint32_t> src;  // the real particle each point stands for (itself when real)

  // Real particles only.
  std::vector<double> rho0;               // reference density of the phase
  std::vector<double> dudt, dvdt, drhodt; // outputs
};

}  // namespace arksph
