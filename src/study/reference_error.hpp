// Velocity errors of a particle state against a reference, shared by the studies:
//   - an analytic velocity field u(x, y, t), v(x, y, t) given as two expressions (e.g. the
//     Taylor-Green vortex), evaluated at each particle's position;
//   - a reference run (a finer lattice): its velocities interpolated onto each particle with its
//     own kernel and h, Shepard-normalised (Cummins & Rudman 1999 §3.4, the interpolation of the
//     finer lattice onto the coarser one):  u_ref(r) = sum_b V_b u_b W(r - r_b) / sum_b V_b W(r - r_b),
//     V_b = m_b / rho0_b.
// Per particle e_a = |u_a - u_ref(r_a)| (vector magnitude); L1 = mean e_a, L2 = sqrt(mean e_a^2),
// Linf = max e_a over the particles of the run; all three are NaN when some e_a is (a velocity or a
// reference value that is not finite).
#pragma once
#include <array>
#include <string>
#include <vector>

#include "core/particles.hpp"
#include "core/expression.hpp"

namespace arksph {

struct VelocityErrors {
  double l1 = 0, l2 = 0, linf = 0;
};

// The velocity components of a state vector laid out by L, with their positions (2D).
struct ParticleVelocities {
  std::vector<double> x, y, u, v, volume;  // volume m / rho0 (used by the interpolation)
};
ParticleVelocities velocities_of(const StateLayout& L, const double* state, const std::vector<double>& mass,
                                 const std::vector<double>& rho0);

// Analytic velocity field: two expressions of x, y, t. Throws InputError (one line) on a bad expression.
class AnalyticVelocity {
 public:
  AnalyticVelocity(const std::string& u, const std::string& v);
  void eval(double x, double y, double t, double& u, double& v) const;
  const std::string& u_text() const { return u_.text(); }
  const std::string& v_text() const { return v_.text(); }

 private:
  Expression u_, v_;
};

VelocityErrors errors_against_analytic(const ParticleVelocities& run, const AnalyticVelocity& exact, double t);

// Interpolation of `ref` (kernel `kernel`, smoothing length h) onto the particles of `run`. A particle
// with no reference neighbour within the support counts with e_a = |u_a|.
VelocityErrors errors_against_reference(const ParticleVelocities& run, const ParticleVelocities& ref,
                                        const std::string& kernel, double h);

}  // namespace arksph
