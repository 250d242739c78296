// The approximate pressure projection of Cummins & Rudman 1999 (§2.2-2.5), applied to the state
// after each accepted ARKODE step (post-process step function):
//   1. fields at the new positions r* (ghosts, neighbours) with the unconstrained velocity u*;
//   2. the PPE L(P) = div(u*)/dt (eqs. 10, 17, 19; see ppe_assembly.hpp), solved by a registered solver;
//   3. velocity correction u = u* - dt sum_b m_b (P_b/rho_b^2 + P_a/rho_a^2) grad_a W_ab (eq. 11),
//      ghosts carrying their source's pressure (plus the hydrostatic step under a body force:
//      body_force_split.hpp, where also the source and the PPE take the body force's wall flux);
//   4. optionally, positions centred in time: r = r_n + dt (u + u_n)/2 (eq. 12).
// With ARKSPH_FORWARD_EULER_1_1 this is C&R's scheme (eqs. 8-12), except that ARKODE evaluates the
// viscous term at r_n where eq. 9 reads chi^n(r*): a difference of O(dt^2) per step.
// Scheme isph-gpps replaces steps 2-3 by the grid-projected Poisson solver of Szewc et al. 2012 §4.2
// (ProjectionGrid_Szewc2012.hpp): same source, Poisson equation on a regular grid, u = u* - dt a_grid.
//
// The projection acts on a ParticleDomain (particle_domain.hpp): one process's model
// (local_domain.hpp), or one rank's particles with its halo (distributed/halo_domain.hpp), where the
// PPE's rows carry global numbers and hypre solves them, the level is taken over every rank, P
// reaches the halo copies from their owners, and the grid's cell sums are all-reduced (every rank
// then solves the whole grid problem: the grid is replicated).
#pragma once
#include "core/parameter.hpp"
#include <memory>
#include <string>
#include <vector>

#include "core/scene.hpp"
#include "projection/ConstrainedPressure.hpp"
#include "projection/correction/DensityCorrection_PozorskiWawrenczuk.hpp"
#include "projection/grid/ProjectionGrid_Szewc2012.hpp"
#include "projection/body_force_split.hpp"
#include "projection/particle_domain.hpp"
#include "projection/projection_options.hpp"
#include "projection/velocity_correction.hpp"
#include "rhs/pressure_gravity.hpp"

namespace arksph {

// The keys of the projection schemes (isph, isph-gpps), in the order of the scene file.
const std::vector<Param>& projection_params();
const std::vector<Param>& projection_time_params();

struct ProjectionStats {
  long solves = 0;
  double seconds = 0;           // right-hand side at r* + assembly + solve + correction
  double solve_seconds = 0;     // the linear solve alone
  double assembly_seconds = 0;  // divergence, source and matrix of the particle PPE
  double setup_seconds = 0;     // of solve_seconds, the solver's set-up (SolveReport::setup_seconds)
  double last_residual = 0, max_residual = 0;
  long iterations = 0, symbolic_analyses = 0;  // isph-gpps: symbolic_analyses counts grid factorisations
  // One solve's counts: its iterations, whether it set up its factorisation or hierarchy anew, and
  // its relative residual.
  void record_solve(long solve_iterations, bool set_up, double residual) {
    ++solves;
    iterations += solve_iterations;
    symbolic_analyses += set_up ? 1 : 0;
    last_residual = residual;
    max_residual = residual > max_residual ? residual : max_residual;
  }
};

class Projection {
 public:
  // flow_rate: U / h of the whole model (ConstrainedPressure.hpp: flow_rate), read by the constrained
  // projection only.
  Projection(const Scene& scene, std::unique_ptr<ParticleDomain> domain, double flow_rate);
  // method.projection = "constrained": the pressure is part of f(t, y) (constrain), nothing is done
  // after a step or stage, and the initial velocity is projected once (project_initial).
  bool constrained() const { return constrained_ != nullptr; }
  const ConstrainedPressure* constraint() const { return constrained_.get(); }
  // After rhs.eval(t, y, ydot): the pressure acceleration added to ydot (au, av: an acceleration
  // the constraint must also see, IMEX's implicit partition, or null).
  void constrain(const double* y, double* ydot, const double* au = nullptr, const double* av = nullptr);
  // The start of a constrained run: u <- P u, so that D u = 0 at t = 0.
  void project_initial(double t, double* y);
  // Remembers the state at the start of the next step (for the centring of eq. 12).
  void begin_step(double t, const double* y);
  // Projects y (the end-of-step state at time t) in place.
  void project(double t, double* y);
  // The "after each stage" variant: projects the velocities of a stage state z_i at t = t_n + c_i h
  // with dt = c_i h (steps 1-3 only: no centring, no density correction, which act on the step).
  void project_stage(double t, double* y);
  // The pressure of the last projection (or constrained evaluation) at the own particles; with
  // gravity in the pressure (rhs/pressure_gravity.hpp) its hydrostatic part added.
  const std::vector<double>& pressure() const {
    return gravity_.active ? reported_ : constrained_ ? constrained_->pressure() : pressure_;
  }
  const ProjectionStats& stats() const { return stats_; }
  std::string solver_name() const { return grid_ ? "grid-klu" : constrained_ ? constrained_->solver_name() : poisson_->name(); }
  const DensityCorrection* correction() const { return correction_.get(); }
  // Drops what the solvers carry from one step to the next (CG's initial guess, KLU's
  // factorisation), so that a run restarted from a checkpoint continues bit for bit.
  void forget_warm_start();
  // The particles re-ordered (RhsEvaluator::permute_particles): the warm starts and the last
  // pressure follow (new index i is old index from[i]).
  void permute_particles(const std::vector<std::uint32_t>& from);
  // The particles moved to other ranks (a migration, a new deal): the solvers start cold; the
  // pressure of the last projection stays (for the frame, by particle id).
  void particles_moved();

 private:
  void project_velocities(double dt, double t, double* y);  // steps 1-3 of the header comment
  void project_on_particles(const FluidFields& f, const std::vector<double>& div, double dt, double* y);
  void project_on_grid(const FluidFields& f, const std::vector<double>& div, double dt, double* y);
  // reported_ = P + rho0 (g . r - min g . r) at the fields' positions (gravity in the pressure).
  void report(const std::vector<double>& p);

  std::unique_ptr<ParticleDomain> domain_;
  BodyForceSplit split_;           // the body force's wall flux as Neumann data (body_force_split.hpp)
  bool slip_origin_ = false;       // the stages' wall images take the increment (t - t_n) g
  std::unique_ptr<ParticlePoisson> poisson_;
  bool centre_positions_;
  bool exact_operator_;
  bool difference_divergence_;
  bool zero_min_level_;
  // fluid.region: p = 0 on the surface particles, found anew at each solve (free_surface.hpp); the
  // pressure's level is then fixed by them. The threshold of div r: Lind et al. 2012's 1.5 in 2D,
  // three quarters of the bulk value d. The velocity correction and the Laplacian's defect there:
  // free_surface.hpp.
  bool free_surface_;
  double surface_threshold_;
  double surface_depth_;                 // the surface's distance beyond its particles: half a spacing
  std::vector<RenormalisedGradient> last_gradient_;  // of the last projection's P (free surface)
  double pressure_offset_;
  double t_prev_ = 0;
  std::vector<double> y_prev_;
  std::vector<double> pressure_;  // P at the level chosen (zero mean or zero minimum)
  std::vector<double> solution_;  // the Poisson solver's solution (one P pinned to 0): the next warm start
  std::unique_ptr<GridProjection> grid_;  // only with scheme isph-gpps
  std::unique_ptr<DensityCorrection> correction_;  // only with density_correction = pozorski_wawrenczuk
  std::unique_ptr<ConstrainedPressure> constrained_;  // only with projection = constrained
  ProjectionStats stats_;
  PressureGravity gravity_;        // the body force the pressure takes
  std::vector<double> reported_;  // the pressure with its hydrostatic part (gravity_.active)
};

}  // namespace arksph
