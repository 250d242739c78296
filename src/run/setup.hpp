// Builds the numerical pieces a scene needs, and only those.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "core/particles.hpp"
#include "core/scene.hpp"
#include "integrate/erk_integrator.hpp"
#include "projection/projection.hpp"
#include "rhs/evaluator.hpp"

namespace arksph {

struct Model {
  ParticleSet particles;
  double h = 0;            // smoothing length
  double sound_speed = 0;  // wcsph only
  double reference_speed = 0;  // U of the regularisation velocities: the flow speed (rhs/reference_speed.hpp); 0 without
  std::unique_ptr<RhsEvaluator> rhs;
  std::unique_ptr<Projection> projection;  // isph only
  std::vector<std::string> terms;  // everything constructed: RHS terms, boundaries, integrator
};

// Throws InputError for combinations only detectable here (e.g. support larger than the box).
Model build_model(const Scene& scene);

// Largest stable step (Szewc et al. 2012 eqs. 34-37) at the current fields:
//   CFL  dt <= cfl h / (c + |u|max)  (wcsph, eq. 35) or cfl h / |u|max (eq. 34),
//   viscous dt <= 0.125 h^2 / nu (eq. 36; not with time.imex, where viscosity is implicit),
//   force dt <= 0.25 sqrt(h / |a|max) (eq. 37),
// and the limits of terms stiff in their own right (Term::max_step: particle shifting).
double stable_step(const Scene& scene, const Model& model, double max_speed, double max_accel);
// Largest particle speed |u| of the state y (the particles in layout L).
double max_speed(const StateLayout& L, const double* y);

// ERKStep options from the scene (table, fixed or adaptive step).
ErkOptions integrator_options(const Scene& scene);

}  // namespace arksph
