// The approximate pressure projection of Cummins & Rudman 1999 (projection/projection.hpp) on one
// rank of a decomposed run, applied to the rank's state after each accepted step (ERKStep's
// post-process step function: every rank takes the same steps, so the calls are collective):
//   1. fields at r* with u* over the rank's particles and its halo (HaloRhs::eval(t, y, nullptr):
//      the copies take the step end's positions and velocities u* from their owners); under a body
//      force with walls u* - dt g, and the source and the wall points' pressures take the force's
//      wall flux (projection/body_force_split.hpp, as in one process);
//   2. div(u*) of the owned particles (C&R eq. 17, or the difference form), their rows of the PPE
//      L(P) = div(u*)/dt with global row numbers (distributed_ppe/ppe_rows.hpp: the rows of the
//      one-process assemble_ppe), solved by hypre's BoomerAMG-preconditioned PCG
//      (distributed_ppe/hypre_poisson.hpp) to method.ppe_tolerance, warm-started from the last
//      solution and reusing the BoomerAMG hierarchy (set up anew by hypre_poisson's rule, and
//      after each migration) while the rank's particles stay the same;
//   3. P at the scene's level (zero mean or zero minimum over all ranks) plus the offset, sent to the
//      halo copies; the velocity correction u = u* - dt sum_b m_b (P_b/rho_b^2 + P_a/rho_a^2)
//      grad_a W_ab (C&R eq. 11) of the owned particles, wall ghosts carrying their source's P;
//   4. optionally the positions centred in time (C&R eq. 12) plus the step's regularisation
//      displacement, as in one process.
// The pressure level: one particle (one global id for the whole run) is pinned to P = 0, as one
// process pins its particle 0 (ppe_assembly.hpp). With unequal particle volumes the Neumann system
// is only approximately consistent and the pinned particle shows in the solution at the level of
// the inconsistency (docs/parallel.md); one process's particle 0 changes with its re-sorts.
//
// With method.projection_points = "stages" steps 1-3 also run on every stage (project_stage).
//   5. the Pozorski-Wawrenczuk density correction, when the scene has it (halo_density_correction.hpp).
// isph-gpps (Szewc et al. 2012 §4.2) replaces steps 2-3 by the grid solve of GridProjection: each
// rank deposits its own particles on the auxiliary grid, the cell sums are all-reduced, and every
// rank solves the whole grid problem (KLU, the same on every rank) and interpolates (1/rho) grad p
// and p at its own particles; the level (zero minimum) over all ranks. The grid is replicated: its
// memory and the all-reduce of 8 numbers a cell per step do not shrink with the rank count.
// method.projection = "constrained" solves the pressure inside f instead (constrain, after each
// evaluation; halo_constrained_pressure.hpp), and project() is not called.
// What this does not do (refused on several ranks by check_distributable): the orthogonal
// projection, the density correction's KINSOL solver, and the exact operator (C&R eq. 18).
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/scene.hpp"
#include "distributed/halo_constrained_pressure.hpp"
#include "distributed/halo_density_correction.hpp"
#include "distributed/halo_poisson.hpp"
#include "distributed/halo_rhs.hpp"
#include "distributed/rank_particles.hpp"
#include "parallel/communicator.hpp"
#include "projection/body_force_split.hpp"
#include "projection/grid/ProjectionGrid_Szewc2012.hpp"
#include "projection/projection.hpp"

namespace arksph::distributed {

class HaloProjection {
 public:
  // pinned_id: the global id of the particle whose pressure is pinned to 0 for the whole run;
  // flow_rate: U / h of the whole model (the constrained projection's rates).
  HaloProjection(const Scene& scene, const parallel::Communicator& comm, HaloRhs& f, RankParticles& owned,
                 std::int64_t pinned_id, double flow_rate);
  // method.projection = "constrained": the pressure inside f.
  bool constrained() const { return constrained_ != nullptr; }
  // Collective. After f.eval(t, y, ydot): the constrained projection's -G p added to ydot.
  void constrain(const double* y, double* ydot);
  // Collective. The constrained projection's start: the velocities of y made divergence-free.
  void project_initial(double t, double* y);
  // Remembers the rank's state at the start of the next step (for the centring of C&R eq. 12).
  void begin_step(double t, const double* y);
  // Collective. Projects the rank's state y (the end of the step, time t) in place.
  void project(double t, double* y);
  // Collective. method.projection_points = "stages": projects the velocities of a stage state at
  // t = t_n + c_i h with dt = c_i h (steps 1-3: no centring), as Projection::project_stage.
  void project_stage(double t, double* y);
  // The rank's particles changed (migration, a new deal): the rows are numbered anew and the solver
  // starts cold (no warm start, a new hierarchy).
  void particles_moved();
  // Counters as ProjectionStats: solves, iterations and residuals are global (the same on every
  // rank), times this rank's.
  const ProjectionStats& stats() const { return stats_; }
  // The pressure of the last projection and the ids of its particles (this rank's, at that time).
  const std::vector<double>& pressure() const { return pressure_; }
  const std::vector<std::int64_t>& pressure_ids() const { return pressure_ids_; }
  // Collective. The last projection's pressure of the particles `ids` (this rank's now, which may
  // have migrated since that projection), of a model of n particles: every rank's (id, P) gathered
  // into one array by id (spread_by_id).
  std::vector<double> pressure_at(const std::vector<std::int64_t>& ids, std::size_t n) const;
  // The pressure solve as summary.json names it: hypre's, or the grid's (isph-gpps).
  std::string solver_name() const { return grid_ ? "grid-klu" : "hypre-pcg-boomeramg"; }
  // The density correction after each step (null without one).
  const HaloDensityCorrection* correction() const { return correction_.get(); }

 private:
  const parallel::Communicator& comm_;
  HaloRhs& f_;
  RankParticles& owned_;
  HaloPoisson poisson_;
  void project_velocities(double dt, double t, double* y);  // steps 1-3 of the header comment
  // Steps 2-3 on the particles (hypre) or on the grid (isph-gpps), from the owned particles' div(u*).
  void project_on_particles(const FluidFields& f, std::vector<double>& div, double dt, double* u, double* v);
  void project_on_grid(const FluidFields& f, const std::vector<double>& div, double dt, double* u, double* v);
  std::unique_ptr<GridProjection> grid_;  // isph-gpps only
  std::unique_ptr<HaloConstrainedPressure> constrained_;  // method.projection = "constrained" only

  BodyForceSplit split_;  // the body force's wall flux as Neumann data (body_force_split.hpp)
  bool slip_origin_;      // the stages' wall images take the increment (t - t_n) g (not with stages projected)
  bool centre_positions_, difference_divergence_, zero_min_level_;
  double pressure_offset_;
  std::vector<double> solution_;  // hypre's solution (P_pinned = 0): the next warm start
  std::vector<double> pressure_;  // P at the level chosen, owned particles
  std::vector<std::int64_t> pressure_ids_;
  double t_prev_ = 0;
  std::vector<double> y_prev_;
  ProjectionStats stats_;
  std::unique_ptr<HaloDensityCorrection> correction_;
};

}  // namespace arksph::distributed
