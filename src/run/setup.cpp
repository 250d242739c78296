#include "run/setup.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "boundary/wall_velocity_rules.hpp"
#include "core/errors.hpp"
#include "core/expression.hpp"
#include "core/particle_order.hpp"
#include "core/scheme.hpp"
#include "integrate/time_params.hpp"
#include "projection/local_domain.hpp"
#include "rhs/density/initial_density.hpp"
#include "rhs/reference_speed.hpp"
#include "rhs/term_registry.hpp"
#include "rhs/terms.hpp"
#include "run/interrupt.hpp"
#include "run/memory_estimate.hpp"

namespace arksph {

namespace {
// The body force at t = 0 at every particle: NaN or infinity there is bad input (the key and one
// particle), not a numerical failure of the first step.
void check_initial_body_force(const Scene& scene, const ParticleSet& p) {
  for (int k = 0; k < scene.dimension; ++k) {
    const Expression force(scene.body_force.at(k), {"x", "y", "t"});
    for (std::size_t a = 0; a < p.n; ++a) {
      const double x = p.init_pos[0][a], y = scene.dimension == 2 ? p.init_pos[1][a] : 0.0;
      const double g = force.eval(x, y, 0.0);
      if (!std::isfinite(g))
        throw InputError(scene.source + ": fluid.body_force: component " + std::to_string(k) + " (\"" +
                         scene.body_force[k] + "\") is " + message_number(g) + " at t = 0 at the particle at (" +
                         message_number(x) + ", " + message_number(y) + ")");
    }
  }
}
}  // namespace

Model build_model(const Scene& scene) {
  Model model;
  check_run_memory(scene);  // before anything large is allocated
  const long long particles = std::llround(estimate_run_memory(scene).particles);
  set_activity("building the lattice of " + std::to_string(particles) + " particles");
  model.particles = make_lattice(scene, poll_setup_interrupt);
  poll_setup_interrupt();
  check_initial_body_force(scene, model.particles);
  poll_setup_interrupt();
  if (scene.shuffle_initial_order) permute(model.particles, shuffled_order(model.particles.n, 0x5eed));
  model.h = scene.h_over_dx * scene.spacing;
  Kernel kernel = make_kernel(scene.kernel, model.h, scene.dimension);
  for (int k = 0; k < scene.dimension; ++k) {
    const double length = scene.max[k] - scene.min[k];
    if (kernel.radius() >= length)
      throw InputError(scene.source + ": method.h_over_dx: kernel support " + arksph::message_number(kernel.radius()) +
                       " is not smaller than the box length " + arksph::message_number(length));
  }
  double u0max = 0;
  for (std::size_t a = 0; a < model.particles.n; ++a) {
    double s2 = 0;
    for (int k = 0; k < scene.dimension; ++k) s2 += model.particles.init_vel[k][a] * model.particles.init_vel[k][a];
    u0max = std::max(u0max, std::sqrt(s2));
  }
  const SchemeTraits& scheme = scheme_traits(scene.scheme);
  if (scheme.weakly_compressible) model.sound_speed = resolve_sound_speed(scene, u0max);
  apply_initial_density(scene, model.sound_speed, model.particles);
  // Ideal gas (Basa eq. 12): p = (gamma - 1) rho e; e(0) gives the sound speed sqrt(gamma p / rho) = c.
  if (equations_of_state().at(scene.equation_of_state).traits.adds_state("energy"))
    model.particles.init_energy = model.sound_speed * model.sound_speed / (scene.gas_gamma * (scene.gas_gamma - 1.0));
  auto terms = terms_from_scene(scene, model.sound_speed);
  for (const auto& t : terms)
    if (t->moves_particles()) model.reference_speed = flow_speed(scene);
  for (const auto& t : terms) model.terms.push_back(t->name());
  bool walls = false, periodic = false;
  for (int s = 0; s < 2 * scene.dimension; ++s) {
    if (scene.sides[s].kind == SideKind::wall) walls = true;
    if (scene.sides[s].kind == SideKind::periodic) periodic = true;
  }
  if (walls) model.terms.push_back(scene.free_slip_divergence ? "walls:ghost+free_slip_divergence" : "walls:ghost");
  if (walls && scene.dimension == 2 && wall_velocity_rules().at(scene.wall_velocity).make)
    model.terms.push_back("walls:" + scene.wall_velocity + "_velocity");
  if (walls && scene.wall_particles && scene.dimension == 2) model.terms.push_back("walls:wall_particles");
  if (periodic) model.terms.push_back("periodic:images");
  model.terms.push_back("kernel:" + scene.kernel);
  if (scene.imex) {  // the viscous term implicit: ARKStep IMEX, Newton with KLU on M = I - gamma J
    model.terms.push_back("integrator:arkstep_imex:" + scene.imex_pair);
    model.terms.push_back(scene.imex_linear ? "imex:viscosity_implicit+klu+linear" : "imex:viscosity_implicit+klu");
  } else {
    model.terms.push_back("integrator:erkstep:" + scene.integrator);
  }
  set_activity("setting up the right-hand side of " + std::to_string(model.particles.n) + " particles");
  model.rhs = std::make_unique<RhsEvaluator>(scene, model.particles, std::move(kernel), std::move(terms));
  poll_setup_interrupt();
  if (scheme.projection) {
    set_activity("setting up the projection of " + std::to_string(model.particles.n) + " particles");
    const double rate = scene.pressure_in_f() ? flow_rate(scene, *model.rhs) : 0.0;
    model.projection = std::make_unique<Projection>(scene, std::make_unique<LocalDomain>(scene, *model.rhs), rate);
    if (scheme.grid) {
      const GridSpec g = gpps_grid(scene);
      model.terms.push_back("projection:gpps-klu:" + std::to_string(g.nx) + "x" + std::to_string(g.ny));
    } else if (scene.projection == ProjectionMethod::orthogonal) {  // the coarse pressure space's dense LDLT (ppe_solver unused)
      char spacing[32];
      std::snprintf(spacing, sizeof spacing, "%gdx", scene.orthogonal_spacing);
      model.terms.push_back(std::string("projection:orthogonal-coarse-ldlt:") + spacing);
    } else if (model.projection->constrained()) {
      model.terms.push_back("projection:constrained-ppe-" + scene.ppe_solver);
    } else {
      model.terms.push_back("projection:ppe-" + scene.ppe_solver);
    }
    if (scene.centre_positions && !model.projection->constrained()) model.terms.push_back("projection:centred_positions");
    if (scene.projection_points == ProjectionPoints::stages) model.terms.push_back("projection:stages");
    if (density_corrections().at(scene.density_correction).traits.corrects_density) model.terms.push_back("correction:" + scene.density_correction);
  }
  return model;
}

double max_speed(const StateLayout& L, const double* y) {
  double m2 = 0;
  for (std::size_t a = 0; a < L.n; ++a) {
    double s2 = 0;
    for (int k = 0; k < L.dim; ++k) s2 += y[L.vel(k) + a] * y[L.vel(k) + a];
    m2 = std::max(m2, s2);
  }
  return std::sqrt(m2);
}

double stable_step(const Scene& scene, const Model& model, double max_speed, double max_accel) {
  const double h = model.h;
  double wall_speed = 0;
  for (int s = 0; s < 2 * scene.dimension; ++s)
    wall_speed = std::max(wall_speed, std::hypot(scene.sides[s].velocity[0], scene.sides[s].velocity[1]));
  const double speed = std::max(max_speed, wall_speed);
  double dt = std::numeric_limits<double>::infinity();
  const double signal = model.sound_speed + speed;  // eq. 35 (eq. 34 when c = 0)
  if (signal > 0) dt = std::min(dt, scene.cfl * h / signal);
  // eq. 36 (explicit only). With the pressure inside f at a free surface the viscous acceleration is
  // projected, and the projected operator reaches further along the negative axis: at 0.125 a column
  // at rest grew from round-off by 1.083 a Heun-Euler step (an eigenvalue at -2.08 / dt), and was
  // bounded at 0.116 and below; 0.1 keeps a margin.
  const double viscous = scene.pressure_in_f() && !scene.fluid_region.empty() ? 0.1 : 0.125;
  if (scene.viscosity > 0 && !scene.imex) dt = std::min(dt, viscous * h * h / scene.viscosity);
  if (max_accel > 0) dt = std::min(dt, 0.25 * std::sqrt(h / max_accel));        // eq. 37
  if (model.rhs) dt = std::min(dt, model.rhs->max_step());  // the terms' own limits (Term::max_step)
  if (!std::isfinite(dt)) dt = scene.end;
  return dt;
}

ErkOptions integrator_options(const Scene& scene) {
  ErkOptions o;
  o.table = scene.integrator;
  o.fixed_dt = scene.dt;
  const Tolerances tol = integrator_tolerances(scene, scene.dt);
  o.rtol = tol.rtol;
  o.atol = tol.atol;
  o.max_steps = scene.max_steps;
  if (scene.dt == 0 && !scene.imex && !erk_table_has_embedding(scene.integrator))
    throw InputError(scene.source + ": time.dt: table " + scene.integrator +
                     " has no embedding, so it needs a fixed step (time.dt > 0)");
  return o;
}

}  // namespace arksph
