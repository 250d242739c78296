// Where a projection's particles live, and how their pressure Poisson equation is solved: the two
// things that differ between one process and one rank of a decomposed run. The projection after a
// step (projection.hpp), the constrained projection (ConstrainedPressure.hpp), the grid projection
// and the P-W correction (correction/DensityCorrection_PozorskiWawrenczuk.hpp) are written once
// against these interfaces:
//   - ParticleDomain: the state's particles (the rank's own ones, first among the evaluator's real
//     points, then its halo copies), the evaluator's fields, and the collectives over every
//     particle (the pressure's level, the halo copies' values from their owners, the grid's cell
//     sums, the correction's span);
//   - ParticlePoisson: C&R eq. 19 over the domain's particles, one back-end per user (its own warm
//     start and set-up). One process: the matrix of ppe_assembly.hpp and a registered solver (KLU,
//     CG, AMG; poisson/poisson_solver.hpp). Ranks: rows with global numbers and hypre's
//     BoomerAMG-preconditioned PCG (distributed/halo_domain.hpp).
// One process's domain is local_domain.hpp. Every method is collective on ranks.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/particles.hpp"
#include "core/scene.hpp"
#include "projection/correction/correction_newton.hpp"
#include "projection/grid/ProjectionGrid_Szewc2012.hpp"
#include "projection/poisson/poisson_solver.hpp"
#include "projection/ppe_assembly.hpp"
#include "rhs/fluid_fields.hpp"

namespace arksph {

class ParticlePoisson {
 public:
  virtual ~ParticlePoisson() = default;
  // Solves L P = source / dt at the fields f of the domain's last refresh or evaluation for its
  // particles (source: one value each, or one per real point of f: the first ones are read). p: the
  // warm start in (zeros when its size is not the particle count), the solution out, with one
  // particle's P pinned to 0.
  virtual SolveReport solve(const FluidFields& f, const std::vector<double>& source, double dt,
                            std::vector<double>& p) = 0;
  // What summary.json calls the solver.
  virtual std::string name() const = 0;
  // The rows of given P (a free surface: ppe_assembly.hpp) of the next solves; empty: none. Where
  // the domain has no such rows (ranks), a non-empty set is a logic error.
  virtual void set_given(DirichletRows given) = 0;
  // Drops the stored set-up (factorisation, hierarchy, numbering): the particles were re-ordered,
  // moved to other ranks, or a run restarts.
  virtual void reset() = 0;
  // Time spent assembling the equation so far.
  virtual double assembly_seconds() const = 0;
};

class ParticleDomain {
 public:
  virtual ~ParticleDomain() = default;
  // The layout of the state y the projection is handed (its own particles).
  virtual StateLayout layout() const = 0;
  // The fields (ghosts, neighbours, density) at the state y, without derivatives. A failure on one
  // rank is a NumericalFailure on every rank.
  virtual void refresh(double t, const double* y) = 0;
  // The fields of the last refresh or evaluation of f: the own particles first among the real points.
  virtual const FluidFields& fields() const = 0;
  // Velocity component k at every real point of the fields, for the state y of the last evaluation
  // (the halo copies' from their owners).
  virtual const double* point_velocity(const double* y, int k) const = 0;
  // The evaluator's wall images carry the increment (t - t0) g of a step's body force (on), or not.
  virtual void set_slip_origin(bool on, double t0) = 0;
  // The level that makes p (the own particles' values) zero-minimum or zero-mean over every particle.
  virtual double level(const std::vector<double>& p, bool zero_min) const = 0;
  // The largest of x over every rank (one process: x).
  virtual double largest(double x) const = 0;
  // v summed element-wise over every rank, in place (one process: unchanged).
  virtual void sum_in_place(std::vector<double>& v) const = 0;
  // The own particles' values followed by their halo copies': one value per real point of the fields.
  virtual std::vector<double> with_halo(const std::vector<double>& own) const = 0;
  // The same for two fields at once (the components of a vector).
  virtual std::pair<std::vector<double>, std::vector<double>> with_halo(const std::vector<double>& a,
                                                                        const std::vector<double>& b) const = 0;
  // The grid projection's cell sums and maxima over every rank (empty: nothing to combine).
  virtual CellCombine cell_combine() const = 0;
  // The P-W correction's particles and reductions (correction_newton.hpp).
  virtual CorrectionSpan correction_span() const = 0;
  // A Poisson back-end of its own (exact_operator: C&R eq. 18 in place of eq. 19, one process only).
  virtual std::unique_ptr<ParticlePoisson> poisson(const Scene& scene, bool exact_operator) = 0;
};

}  // namespace arksph
