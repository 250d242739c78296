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
  // Whether the force terms may take the plain pair loops where these fields allow them
  // (rhs/particle_term.hpp); false: the general loops always (the same bits, which tests compare).
  bool allow_plain_pairs = true;

  // All points (real then ghosts).
  std::vector<double> x, y;    // positions
  std::vector<double> u, v;    // velocity for the momentum terms
  std::vector<double> ud, vd;  // velocity for the divergence (free-slip images near walls, Szewc §6)
  std::vector<double> rho, p, m;
  std::vector<double> vol;     // V = m / rho, refreshed on entering the force stage (no division per pair)
  double nu = 0;               // kinematic viscosity (one value for all points)
  std::vector<double> mu;      // dynamic viscosity rho nu, refreshed with vol (one load per pair, not two)
  std::vector<std::uint32_t> src;  // the real particle each point stands for (itself when real)
  std::vector<double> flip_x, flip_y;  // +1, or -1 where a point is a reflection of its source
  // A wall image (mirrored across a wall, possibly also shifted periodically), as opposed to a real
  // particle or a pure periodic image, which is a real neighbour in every respect.
  bool is_wall_image(std::size_t i) const {
    return (!flip_x.empty() && flip_x[i] < 0) || (!flip_y.empty() && flip_y[i] < 0);
  }
  // Under a body force g, the hydrostatic pressure step per unit density from each point's source
  // to the point, g(r_src, t) . d with d the displacement across the walls only (a mirror image's
  // reflected axes, a wall particle's normal; periodic shifts carry none): 0 for real particles.
  // A wall point's pressure is p_src + rho_src ghost_dp (Adami et al. 2012 eq. 27 with resting
  // walls), the Neumann condition dp/dn = rho g . n. Empty when the scene has no body force.
  std::vector<double> ghost_dp;
  // The pressure of point b from the real particles' pressures p (sized n_real): its source's,
  // plus the hydrostatic step above.
  double point_pressure(const std::vector<double>& p, std::size_t b) const {
    return ghost_dp.empty() ? p[src[b]] : p[src[b]] + rho[b] * ghost_dp[b];
  }

  // Kernel consistency correction (Basa et al. 2008 §4), filled by the kernel_correction term for
  // all points (ghosts take their source's values, reflected): see rhs/KernelCorrection_Basa2008.hpp.
  enum class Correction { none, shepard, bonet_lok };
  Correction correction = Correction::none;
  std::vector<double> one;             // <1> = sum_b V_b W_ab, self included (Basa eq. 21)
  std::vector<double> grad1x, grad1y;  // <grad 1> (Basa eq. 22)
  std::vector<double> lmat;            // Bonet-Lok L (Basa eq. 26), 4 per point, row-major
  // Local average pressure of Basa eq. 20 (real particles; empty when pressure reduction is off).
  std::vector<double> p_avg;
  // Specific internal energy (ideal-gas equation of state, Basa eqs. 12, 14); empty otherwise.
  std::vector<double> e, dedt;

  // Regularisation velocity du_s of the particle regularisation parts: the particles move with
  // dr/dt = u + du_s (rhs/regularisation/Shifting_Lind2012.cpp, rhs/regularisation/TransportVelocity_Adami2013.cpp). Sized to the
  // real particles and zeroed at every f when such a part is on (a part may extend it to the
  // ghosts); empty otherwise.
  std::vector<double> shift_u, shift_v;

  // Real particles only.
  std::vector<double> rho0;               // reference density of the phase
  std::vector<double> dudt, dvdt, drhodt; // outputs
};

}  // namespace arksph
