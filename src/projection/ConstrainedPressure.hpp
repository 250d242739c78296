// The constrained projection (method.projection = "constrained"): the pressure is solved inside
// f(t, y), so that ARKODE integrates one ODE whose every stage carries its own pressure, and the
// table's order holds for the velocity and the pressure alike.
//
// With D the difference-form divergence (projection/divergence_operator.hpp), L the approximate
// Laplacian of Cummins & Rudman eq. 19 (projection/ppe_assembly.hpp), G their symmetric pressure
// gradient (C&R eq. 11) and a* the acceleration of every other term (viscosity, body force; under
// IMEX both partitions), f returns
//
//   dr/dt = u,   du/dt = a* - G p,   L p = D (a* + alpha u) - Q,
//
// where Q is exactly the part of d(D u)/dt that the particles' motion makes
// (divergence_rate_of_motion: d(D u)/dt = D du/dt - Q along dr/dt = u). Along the ODE therefore
//
//   d(D u)/dt = -alpha D u + (L - D G) p :
//
// where L = D G (smooth pressure modes, to the approximation of eq. 19) a divergence-free start
// stays divergence-free, and what the time integration and L's approximation leave decays at the
// rate alpha (alpha = beta U/h, beta = method.constraint_relaxation; Baumgarte's stabilisation of an index-reduced
// constraint). The pressure is the discrete counterpart of div(grad p / rho) = div(a*) -
// tr(grad u grad u) of an incompressible flow.
//
// This is the route of Matsunaga (2025): the pressure equation written along the particle
// trajectories, so that explicit Runge-Kutta applies to the whole system; with C&R's compact L it
// is the projection of the velocity increment that Almgren, Bell & Crutchfield (2000) recommend for
// approximate projections, applied at every stage. p is a smooth function of the state between the
// changes of the particle its level is taken at (method.ppe_pressure_level: zero_min, P >= 0, so
// that the pair force of C&R eq. 11 never attracts), and it converges at the velocity's order
// (cases/isph_order).
//
// Under a body force g with walls, the source takes D(a* - g) + div g and the flux of g is the
// Neumann data of L and G (wall points at P_src + rho g . d; projection/body_force_split.hpp): D's
// wall images reflect a*, which for a uniform g leaves a layer of sources along the walls that
// C&R's mirrored P in G cannot balance.
//
// With method.density_correction = "pozorski_wawrenczuk" the correction is a velocity in dr/dt as well
// (projection/correction/density_relaxation.hpp), so positions stay inside the ODE.
//
// The exact orthogonal projection I - G (D G)^-1 D with G = -M^-1 D^T V (DivergenceOperator) is
// idempotent, but D G decouples odd and even particles: on a perturbed lattice it has near-null
// modes, and a constraint imposed through it moves the velocity by O(|u|) (docs/methods/isph.md).
//
// method.projection = "orthogonal" takes that exact pair on a coarse pressure space instead
// (projection/poisson/coarse_pressure_space.hpp): p = Pi q, cubic B-splines on a grid of spacing
// method.orthogonal_spacing x dx, G the adjoint gradient -M^-1 D^T V, and
//
//   du/dt = a* - G Pi q,   K_c q = -(Pi^T V D (a* + alpha u - C) + E),   K_c = Pi^T K Pi,
//
// where C = (u . grad) u is the convective acceleration (convective_acceleration), whose divergence
// stands for Q, and E = sum_a (grad Pi_a . u_a) V_a (D u)_a is the change of Pi^T V D u from the
// particles moving across the fixed grid. D C takes the motion term through the same smoothing as
// K = V D M^-1 D^T V (two kernel sums): with Q, computed from the kernel's Hessian in one sum, the
// pressure of the Taylor-Green vortex came out 2-3 times too large and the 32^2 vortex blew up. Along the ODE d(D_c u)/dt = -alpha D_c u with D_c = Pi^T V D (up to the
// change of the volumes V), and the velocity change of each stage is the orthogonal projection
// P = I - M^-1 D_c^T K_c^-1 D_c of a* + alpha u: idempotent to round-off.
//
// The class acts on a ParticleDomain (particle_domain.hpp): on one rank of a decomposed run the
// source w = a* + alpha u reaches the halo copies from their owners before D reads it (the
// evaluator computes no derivatives for the copies), the PPE's rows carry global numbers and hypre
// solves them, the level is taken over every rank and p reaches the copies before G reads it. The
// orthogonal projection is one process's (refused on ranks).
#pragma once
#include <memory>
#include <vector>

#include "core/scene.hpp"
#include "projection/anderson_acceleration.hpp"
#include "projection/body_force_split.hpp"
#include "projection/poisson/coarse_pressure_space.hpp"
#include "projection/divergence_operator.hpp"
#include "projection/correction/density_relaxation.hpp"
#include "projection/particle_domain.hpp"
#include "projection/ppe_assembly.hpp"
#include "projection/velocity_correction.hpp"
#include "rhs/evaluator.hpp"

namespace arksph {

// U / h, U the largest initial or wall speed (h / time.end for a fluid at rest between still walls).
double flow_rate(const Scene& scene, const RhsEvaluator& rhs);
// At a free surface under a body force g: 4 sqrt(|g| / h), the inverse of the body-force step of
// Szewc et al. 2012 eq. 37 (dt <= 0.25 sqrt(h / |g|)); 0 otherwise.
double surface_gravity_rate(const Scene& scene);
// alpha = beta U / h, beta = method.constraint_relaxation (method.orthogonal_relaxation for the
// orthogonal projection); at a free surface under a body force at least surface_gravity_rate
// (beta = 0 switches the relaxation off altogether).
double relaxation_rate(const Scene& scene, double flow_rate);

class ConstrainedPressure {
 public:
  // flow_rate: U / h of the whole model (flow_rate above).
  ConstrainedPressure(const Scene& scene, ParticleDomain& domain, double flow_rate);
  // After f(t, y, ydot): adds -G p to the velocity block of ydot. (au, av): an acceleration
  // not in ydot that the constraint must see (IMEX: the implicit partition), or null.
  SolveReport constrain(const double* y, double* ydot, const double* au, const double* av);
  // u <- u - G phi with L phi = D u (one approximate projection of the start), fields refreshed here.
  SolveReport project_velocity(double t, double* y);
  const std::vector<double>& pressure() const { return p_; }
  // method.projection = "orthogonal": u <- P u for real velocities (u, v) at the fields of the last
  // evaluation (the projection itself, for its idempotence test).
  void project_orthogonal(double* u, double* v);
  double relaxation() const { return relaxation_; }
  // At a free surface: the evaluations that iterated the surface's terms, the Poisson solves of those
  // iterations, and the evaluations that stopped at the iteration limit short of the fixed point
  // (summary.json ppe.surface_*).
  struct SurfaceStats {
    long evaluations = 0, solves = 0, unconverged = 0;
  };
  bool free_surface() const { return free_surface_; }
  const SurfaceStats& surface_stats() const { return surface_stats_; }
  // The P-W correction as a velocity inside f (method.density_correction), or null.
  const DensityRelaxation* density_relaxation() const { return density_.get(); }
  std::string solver_name() const { return poisson_->name(); }
  void forget_warm_start();
  void permute_particles(const std::vector<std::uint32_t>& from);
  // The particles moved to other ranks: no warm start, the solver set up anew (p_ stays, for the frame).
  void particles_moved();

 private:
  // p_ from L p = source, at the fields of the last eval, into solution (warm start in); returns
  // the solver's report.
  SolveReport solve_pressure(const std::vector<double>& source, std::vector<double>& solution);
  // At a free surface: p_ with the surface's rows and the Laplacian's defect at their fixed point;
  // `given` the rows of the last solve.
  SolveReport solve_at_surface(const std::vector<double>& source, DirichletRows& given);
  // The orthogonal projection's pressure and gradient (gx_, gy_) for the source div_ of the last
  // evaluation, (u, v) the velocities that move the particles across the grid.
  void coarse_pressure(const double* u, const double* v);

  ParticleDomain& domain_;
  BodyForceSplit split_;
  double relaxation_;
  bool zero_min_level_;
  std::unique_ptr<ParticlePoisson> poisson_;
  std::unique_ptr<DensityRelaxation> density_;
  std::unique_ptr<CoarsePressureSpace> coarse_;  // method.projection = "orthogonal"
  DivergenceOperator operator_;
  // At a free surface (fluid.region): the surface rows and the Laplacian defect of
  // projection/free_surface.hpp, iterated to their fixed point (solve_at_surface); the renormalised
  // gradients of the last p.
  bool free_surface_;
  double surface_threshold_, surface_depth_;
  AndersonAcceleration anderson_;  // of that fixed-point iteration
  SurfaceStats surface_stats_;
  std::vector<RenormalisedGradient> last_gradient_;
  std::vector<double> p_, solution_, div_, udiv_, cx_, cy_, gx_, gy_, wx_, wy_, bx_, by_;
};

}  // namespace arksph
