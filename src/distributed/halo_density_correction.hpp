// The Pozorski-Wawrenczuk position correction (Szewc et al. 2012 eqs. 57-59) on one rank of a
// decomposed run, after each step's projection (halo_projection.hpp), as DensityCorrection does
// after one process's: when the r.m.s. fluctuation of the summation density over all particles
// exceeds method.correction_threshold, Newton steps with the exact derivative of the summation
// density (projection/correction_newton.hpp) move the rank's particles. The iteration is one
// process's, run over a CorrectionSpan: sums (means, r.m.s., BiCGSTAB's inner products) over the
// ranks, the potential p and the shifts of the rank's particles handed to their halo copies before
// a pair loop reads them, the Jacobi preconditioner's median over every rank's diagonal. Every
// rank takes the same Newton and Krylov iterations and the same accept/halve decisions.
//
// Only method.correction_solver = "newton" (the default) runs on ranks; the fixed point and KINSOL
// are refused by check_distributable.
#pragma once
#include <vector>

#include "core/scene.hpp"
#include "distributed/halo_rhs.hpp"
#include "distributed/rank_particles.hpp"
#include "parallel/communicator.hpp"
#include "projection/DensityCorrection_PozorskiWawrenczuk.hpp"
#include "projection/correction_newton.hpp"

namespace arksph::distributed {

class HaloDensityCorrection {
 public:
  HaloDensityCorrection(const Scene& scene, const parallel::Communicator& comm, HaloRhs& f,
                        const RankParticles& owned);
  // Collective. Corrects the positions of the rank's state y (time t) in place.
  void apply(double t, double* y);
  // applications, iterations and first_history are global (the same on every rank), seconds this rank's.
  const CorrectionStats& stats() const { return stats_; }

 private:
  CorrectionSpan span() const;
  const parallel::Communicator& comm_;
  HaloRhs& f_;
  const RankParticles& owned_;
  double threshold_;
  int max_iterations_;
  double spacing_;
  CorrectionStats stats_;
};

}  // namespace arksph::distributed
