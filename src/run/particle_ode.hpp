// The particle system of a scene as a plain ODE, y' = f(t, y), for integrators outside arksph (the
// Python module, python/): the state in a fixed particle order, f, the projection after a step, and
// the IMEX split.
//
// The state is set up as `arksph run` sets it up: the initial fields, the re-sort into cell order
// at t = 0 (method.reorder_every > 0), a field refresh, and for the constrained projection the
// initial velocity made divergence-free. Inside, the particles stay in that order (the neighbour
// loops want cell order); outside, every y and every f is in the order of increasing particle id
// (the order of the initial lattice), whatever arksph does inside. Each block of the layout
// (x, y, u, v, rho, energy) holds one value per particle in that order.
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "core/particle_order.hpp"
#include "core/scene.hpp"
#include "run/setup.hpp"

namespace arksph {

class ViscousSplit;

class ParticleOde {
 public:
  explicit ParticleOde(const Scene& scene);
  ~ParticleOde();

  const Scene& scene() const { return scene_; }
  const StateLayout& layout() const;
  // The particle ids in the outside order (increasing).
  const std::vector<std::int64_t>& ids() const { return ids_; }
  // The initial state y0 (outside order), as the first step of `arksph run` sees it.
  const std::vector<double>& initial_state() const { return y0_; }
  double smoothing_length() const { return model_.h; }
  double sound_speed() const { return model_.sound_speed; }

  // ydot = f(t, y): every term, and the constrained projection's pressure where the scene has it.
  void rhs(double t, const double* y, double* ydot);
  // C&R's projection of the end-of-step state y at t in place (isph, isph-gpps with
  // method.projection = "cummins_rudman"; the state at the start of the step, t_start and y_start, centres the
  // positions, C&R eq. 12).
  void project(double t_start, const double* y_start, double t, double* y);
  bool has_projection() const;
  bool projection_is_constrained() const;

  // The IMEX split (time.imex's): f = f_E + f_I with f_I the viscous acceleration. f_E carries the
  // constrained projection where there is one.
  void explicit_rhs(double t, const double* y, double* ydot);
  void implicit_rhs(double t, const double* y, double* ydot);
  // w = J v, J = df_I/dy at y with positions and densities frozen (f_I is linear in the velocities,
  // so J v is exact for a v in the velocity block; other blocks of v do not enter).
  void implicit_jvp(double t, const double* y, const double* v, double* w);

  // The largest stable step at y (Szewc et al. 2012 eqs. 34-37, run/setup.hpp), from the fields of
  // the last evaluation of f.
  double stable_step(const double* y);
  long evaluations() const;
  // Wall seconds per evaluation of f at y over `repeats` evaluations in the inside order, without
  // the copies in and out: the C++ cost a caller of rhs() is measured against (bench/).
  double seconds_per_inside_rhs(double t, const double* y, int repeats);

 private:
  void to_inside(const double* y, std::vector<double>& inside) const;
  void to_outside(const std::vector<double>& inside, double* y) const;
  ViscousSplit& split();

  Scene scene_;
  Model model_;
  Permutation from_;  // inside index i holds the outside index from_[i]
  std::vector<std::int64_t> ids_;
  std::vector<double> y0_;
  std::vector<double> y_in_, f_in_, v_in_, y_start_in_;  // scratch in the inside order
  std::unique_ptr<ViscousSplit> split_;                  // on first use of the IMEX functions
  std::unique_ptr<Model> imex_model_;                    // the IMEX split evaluates its own model
};

}  // namespace arksph
