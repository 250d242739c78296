// f(t, y) of the semi-discrete particle system: refreshes ghosts and neighbours at the positions in
// y, runs the enabled terms in stage order and returns [u ; du/dt ; drho/dt] in the state layout.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "boundary/WallVelocity_Linear_Basa2008.hpp"
#include "boundary/WallVelocity_Quadratic_Basa2008.hpp"
#include "boundary/ghosts.hpp"
#include "core/particles.hpp"
#include "kernels/kernel.hpp"
#include "neighbors/cell_list.hpp"
#include "neighbors/neighborhood.hpp"
#include "rhs/fluid_fields.hpp"
#include "rhs/term.hpp"

namespace arksph {

struct RhsTiming {
  double neighbors = 0;  // ghosts, cell list, pair list
  double terms = 0;      // the physical terms
};

class RhsEvaluator {
 public:
  RhsEvaluator(const Scene& scene, const ParticleSet& particles, Kernel kernel,
               std::vector<std::unique_ptr<Term>> terms);

  const StateLayout& layout() const { return layout_; }
  // Fills the initial state vector (size layout().size()).
  void initial_state(double* y) const;
  // ydot = f(t, y). Safe to call with ydot == nullptr to refresh fields only (diagnostics).
  void eval(double t, const double* y, double* ydot);

  const FluidFields& fields() const { return fields_; }
  const Kernel& kernel() const { return kernel_; }
  const ParticleSet& particles() const { return particles_; }
  std::vector<std::string> term_names() const;
  double max_acceleration() const { return max_accel_; }  // from the last eval, real particles
  long evaluations() const { return evals_; }
  long neighbor_rebuilds() const { return rebuilds_; }
  // Forces a fresh ghost set and candidate list at the next eval, as after a restart from a
  // checkpoint: called at every checkpoint so that a restarted run sums pairs in the same order.
  void invalidate_neighbors() { ref_x_.clear(); }
  // The particles re-ordered (core/particle_order.hpp: new index i is old index from[i]): the
  // constant per-particle data follow, the neighbour list and ghosts are rebuilt at the next eval.
  // The state vector is the caller's to permute; fields() are stale until the next eval.
  void permute_particles(const std::vector<std::uint32_t>& from);
  const RhsTiming& timing() const { return timing_; }

  // IMEX (time.imex): with `on`, eval() leaves the viscous terms out of ydot (f_E) and keeps their
  // acceleration for implicit_part() (f_I). Off (the default), eval() is the explicit path unchanged.
  void set_viscosity_implicit(bool on) { implicit_viscosity_ = on; }
  bool viscosity_implicit() const { return implicit_viscosity_; }
  // f_I of the last eval(): zero except the velocity block, which holds the viscous acceleration.
  void implicit_part(double* ydot_i) const;
  // The viscous acceleration (au, av) of the real particles for real velocities (u, v) (v, av unused
  // in 1D), at the positions, densities and kernel corrections of the last eval(), which stay
  // frozen: ghost velocities follow from (u, v) by the wall rules. Leaves fields() as it found them.
  // Affine in (u, v): the probes of the implicit Jacobian (app/viscous_jacobian.hpp).
  void viscous_acceleration(const double* u, const double* v, double* au, double* av);

 private:
  double load_state(double t, const double* y);
  double store_derivatives(const double* y, double* ydot) const;
  void refresh_ghosts(bool rebuild);
  void copy_to_ghosts(std::vector<double>& field);
  void ghost_velocities();
  void apply_viscous_terms(std::vector<double>& au, std::vector<double>& av);
  void force_sweep(std::size_t first, std::size_t last);

  StateLayout layout_;
  ParticleSet particles_;
  Kernel kernel_;
  std::vector<std::unique_ptr<Term>> terms_;
  GhostBuilder ghost_builder_;
  GhostSet ghosts_;
  std::unique_ptr<LinearWallVelocity> linear_wall_;  // only with boundary.wall_velocity = "linear"
  std::unique_ptr<QuadraticWallVelocity> quadratic_wall_;  // only with boundary.wall_velocity = "quadratic"
  CellList cells_;
  CandidateList candidates_;
  std::vector<double> ref_x_, ref_y_;  // real positions at the last candidate rebuild
  double skin_ = 0;
  long rebuilds_ = 0;
  FluidFields fields_;
  bool lean_pairs_;  // method.neighbor_storage = "candidates": no per-pair kernel values stored
  bool sweep_;       // method.force_sweep: per-particle terms share one gathered neighbourhood
  bool stored_pairs_on_refresh_;  // a field refresh stores the pair list (the projection schemes)
  bool pairs_every_eval_ = true;  // some term or the scheme reads f.pairs: build them at every f
  std::vector<Neighborhood> scratch_;
  std::size_t sweep_room_ = 0;  // the largest candidate row since the last rebuild  // force sweep: one neighbourhood buffer per thread
  bool periodic_[2] = {false, false};
  double lo_[2] = {0, 0}, len_[2] = {1, 1};
  double max_accel_ = 0;
  long evals_ = 0;
  RhsTiming timing_;
  bool implicit_viscosity_ = false;
  std::vector<bool> viscous_;                   // per term (sorted order): a viscosity term
  std::vector<double> visc_u_, visc_v_;         // IMEX: viscous acceleration of the last eval
  std::vector<double> keep_u_, keep_v_, keep_ud_, keep_vd_, keep_du_, keep_dv_;  // scratch of viscous_acceleration
  std::vector<double> probe_u_, probe_v_;
};

}  // namespace arksph
