// The iteration of one application of the Pozorski-Wawrenczuk correction (method.correction_solver),
// a registered part: Szewc's fixed point (correction_fixed_point.cpp), Newton with the exact
// derivative of the summation density (correction_newton.hpp) or KINSOL with the Laplacian as
// frozen Jacobian (correction_kinsol.hpp, one process only: trait one_process). Each acts on the
// ParticleDomain of the projection (projection/particle_domain.hpp), so that it runs on one process
// and over ranks alike. DensityCorrection (DensityCorrection_PozorskiWawrenczuk.hpp) decides when to
// apply it and keeps the counts.
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "core/registry.hpp"
#include "core/scene.hpp"
#include "projection/particle_domain.hpp"

namespace arksph {

// What one application did.
struct CorrectionOutcome {
  double error = 0;     // r.m.s. relative density fluctuation after it
  long iterations = 0;  // its solves (Newton iterations)
};

class CorrectionSolver {
 public:
  virtual ~CorrectionSolver() = default;
  // Moves the positions of y (time t), starting from the domain's fields at y, where the density
  // fluctuation of the own particles is s with r.m.s. `error` above the threshold. history (null
  // but for the first application) takes the error before each iteration after the first.
  virtual CorrectionOutcome correct(double t, double* y, std::vector<double>& s, double error,
                                    std::vector<double>* history) = 0;
  // Drops the warm start and the solver's set-up (a restart, or the particles moved to other ranks).
  virtual void forget_warm_start() {}
  // The particles re-ordered: a warm start follows (new index i is old index from[i]).
  virtual void permute_particles(const std::vector<std::uint32_t>&) {}
};

using CorrectionSolverFactory = std::unique_ptr<CorrectionSolver> (*)(const Scene& scene, ParticleDomain& domain);

// method.correction_solver
const Registry<CorrectionSolverFactory>& correction_solvers();

}  // namespace arksph
