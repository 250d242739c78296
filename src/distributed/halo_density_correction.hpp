// The Pozorski-Wawrenczuk position correction (Szewc et al. 2012 eqs. 57-59) on one rank of a
// decomposed run, after each step's projection (halo_domain.hpp), as DensityCorrection does
// after one process's: when the r.m.s. fluctuation of the summation density over all particles
// exceeds method.correction_threshold, Newton steps with the exact derivative of the summation
// density (projection/correction/correction_newton.hpp) move the rank's particles. The iteration is one
// process's, run over the domain's CorrectionSpan: sums (means, r.m.s., BiCGSTAB's inner products) over the
// ranks, the potential p and the shifts of the rank's particles handed to their halo copies before
// a pair loop reads them, the Jacobi preconditioner's median over every rank's diagonal. Every
// rank takes the same Newton and Krylov iterations and the same accept/halve decisions.
//
// method.correction_solver = "fixed_point" (Szewc's scheme, eq. 58 solved as a Poisson equation,
// repeated up to method.correction_max_iterations times) assembles the equation's rows with global
// numbers and solves them with hypre, as the projection does (distributed_ppe): the approximate
// Laplacian of C&R eq. 19 with the source 1 - rho~/rho0, the equation of the projection's pinned
// particle replaced by p* = 0, the last solution the next warm start (dropped when particles
// migrate). KINSOL is refused on ranks by check_distributable.
#pragma once
#include <memory>
#include <vector>

#include "core/scene.hpp"
#include "distributed/halo_rhs.hpp"
#include "distributed/rank_particles.hpp"
#include "projection/correction/DensityCorrection_PozorskiWawrenczuk.hpp"
#include "projection/correction/correction_newton.hpp"
#include "projection/particle_domain.hpp"

namespace arksph::distributed {

class HaloDensityCorrection : public PositionCorrection {
 public:
  // domain: the rank's (halo_domain.hpp), over f and owned; the fixed point's Poisson back-end is its.
  HaloDensityCorrection(const Scene& scene, ParticleDomain& domain, HaloRhs& f, const RankParticles& owned);
  // Collective. Corrects the positions of the rank's state y (time t) in place.
  void apply(double t, double* y) override;
  // applications, iterations and first_history are global (the same on every rank), seconds this rank's.
  const CorrectionStats& stats() const override { return stats_; }
  // The rank's particles changed (migration, a new deal): no warm start, a new hierarchy.
  void forget_warm_start() override;
  void permute_particles(const std::vector<std::uint32_t>& from) override;

 private:
  // One fixed-point iteration (eq. 58 solved, eq. 57 applied) from the fields of y; s: the density
  // fluctuation of the rank's particles.
  void fixed_point_step(const std::vector<double>& s, double* y);
  ParticleDomain& domain_;
  HaloRhs& f_;
  const RankParticles& owned_;
  double threshold_;
  int max_iterations_;
  double spacing_;
  bool newton_;
  std::unique_ptr<ParticlePoisson> poisson_;  // the fixed point's
  std::vector<double> pstar_;  // the fixed point's last solution, the rank's particles
  CorrectionStats stats_;
};

}  // namespace arksph::distributed
