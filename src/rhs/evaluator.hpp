// f(t, y) of the semi-discrete particle system: loads the state y into the fields, refreshes the
// ghosts (rhs/ghost_field.hpp) and the neighbours (rhs/neighbor_cache.hpp) at its positions, sums
// the terms in stage order and returns [u ; du/dt ; drho/dt] in the state layout.
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/particles.hpp"
#include "kernels/kernel.hpp"
#include "rhs/fluid_fields.hpp"
#include "rhs/ghost_field.hpp"
#include "rhs/neighbor_cache.hpp"
#include "rhs/term.hpp"

namespace arksph {

struct RhsTiming {
  double neighbors = 0;  // ghosts, cell list, pair list
  double terms = 0;      // the physical terms
};

// The terms a sum runs: every term, or one side of the IMEX split (Term::can_be_implicit).
enum class Partition { all, explicit_terms, implicit_terms };

struct RhsOptions {
  // IMEX (time.imex): eval() leaves the implicit partition out of ydot (f_E) and keeps its
  // acceleration for implicit_part() (f_I). Off: ydot holds every term.
  bool imex_split = false;
  // The plain pair loops where the fields allow them (rhs/particle_term.hpp). Off, the general loops
  // always: they give the same bits, which the tests compare.
  bool plain_pair_loops = true;
  // The pair list stored at every f, for a caller that walks fields().pairs after eval(t, y, ydot)
  // (the constrained projection).
  bool pairs_at_every_f = false;
  // Only the first derivative_count real particles' derivatives are wanted (one rank's own
  // particles; the rest are its halo copies, whose derivatives are discarded): the force stage's
  // per-particle sweep skips the others. The stages before it (density, pressure) and the force
  // terms with loops of their own still cover every real particle, whose values the first ones
  // read. Those terms write a particle's own derivatives only, so the first ones get the bits of a
  // sweep over all.
  std::size_t derivative_count = static_cast<std::size_t>(-1);
};

class RhsEvaluator {
 public:
  RhsEvaluator(const Scene& scene, const ParticleSet& particles, Kernel kernel,
               std::vector<std::unique_ptr<Term>> terms, RhsOptions options = {});

  const StateLayout& layout() const { return layout_; }
  // Fills the initial state vector (size layout().size()).
  void initial_state(double* y) const;
  // ydot = f(t, y). Safe to call with ydot == nullptr to refresh fields only (diagnostics).
  void eval(double t, const double* y, double* ydot);

  const RhsOptions& options() const { return options_; }
  void set_options(const RhsOptions& options);
  // Projection schemes under a body force: the stages of the step from t0 carry the increment
  // (t - t0) g that the projection will take out; the wall images get it unreflected (GhostField::
  // set_slip_origin). Off (on = false) for the projection's own field refresh and outside steps.
  void set_slip_origin(bool on, double t0) { ghosts_.set_slip_origin(on, t0); }
  // Called between the phases of eval (ghosts, neighbour search, pairs, term stages); it may throw. The
  // set-up polls for a signal this way while the first evaluations of a large run take seconds;
  // empty (the default) during the time loop, where eval runs inside SUNDIALS callbacks.
  void set_between_phases(std::function<void()> hook) { between_phases_ = std::move(hook); }
  const FluidFields& fields() const { return fields_; }
  const Kernel& kernel() const { return kernel_; }
  const ParticleSet& particles() const { return particles_; }
  std::vector<std::string> term_names() const;
  double ghost_depth() const { return ghosts_.depth(); }
  double max_acceleration() const { return max_accel_; }  // from the last eval, real particles
  // The smallest Term::max_step of the terms (+infinity when none has a limit of its own).
  double max_step() const;
  long evaluations() const { return evals_; }
  long neighbor_rebuilds() const { return neighbors_.rebuilds(); }
  // Forces a fresh ghost set and candidate list at the next eval, as after a restart from a
  // checkpoint: called at every checkpoint so that a restarted run sums pairs in the same order.
  void invalidate_neighbors() { neighbors_.invalidate(); }
  // The particles re-ordered (core/particle_order.hpp: new index i is old index from[i]): the
  // constant per-particle data follow, the neighbour list and ghosts are rebuilt at the next eval.
  // The state vector is the caller's to permute; fields() are stale until the next eval.
  void permute_particles(const std::vector<std::uint32_t>& from);
  const RhsTiming& timing() const { return timing_; }

  // f_I of the last eval() with options().imex_split: zero except the velocity block, which holds
  // the acceleration of the implicit partition.
  void implicit_part(double* ydot_i) const;
  // The acceleration (au, av) of the implicit partition (the viscous terms) of the real particles
  // for real velocities (u, v) (v, av unused in 1D), at the positions, densities and kernel
  // corrections of the last eval(), which stay frozen: ghost velocities follow from (u, v) by the
  // wall rules. Leaves fields() as it found them. Affine in (u, v): the probes of the implicit
  // Jacobian (integrate/viscous_jacobian.hpp).
  void viscous_acceleration(const double* u, const double* v, double* au, double* av);
  // sum_a m_a u_a . a_visc,a over the first `count` real particles (all: count >= n), a_visc the
  // acceleration of the viscous terms (Term::can_be_implicit), ghost neighbours included, at the
  // fields of the last eval, which must have been a field refresh (ydot null: the pair list is
  // stored). Every viscous term runs on its own here, also one that another term takes over in its
  // pair loop (Term::take_over). Leaves fields() as it found them. The viscous power of the energy
  // budget (diagnostics/energy_budget.hpp); <= 0 for the dissipative models.
  double viscous_power(std::size_t count);

 private:
  bool in(Partition part, std::size_t k) const {
    return part == Partition::all || implicit_[k] == (part == Partition::implicit_terms);
  }
  double load_state(double t, const double* y);
  double store_derivatives(const double* y, double* ydot) const;
  void sum_stages(Partition part);
  void implicit_acceleration(std::vector<double>& au, std::vector<double>& av);
  template <class Use>
  void with_implicit_terms(bool taken_too, Use&& use);
  void sweep(std::size_t first, std::size_t last, std::size_t count);

  StateLayout layout_;
  ParticleSet particles_;
  Kernel kernel_;
  std::vector<std::unique_ptr<Term>> terms_;  // in stage order
  std::vector<bool> implicit_;                // per term: Term::can_be_implicit
  std::vector<char> taken_;                   // per term: taken over by another (Term::take_over)
  GhostField ghosts_;
  NeighborCache neighbors_;
  FluidFields fields_;
  RhsOptions options_;
  std::function<void()> between_phases_;
  PairUse pairs_for_terms_ = PairUse::repeated;  // f.pairs at every f: for terms that walk them
  PairUse pairs_for_refresh_ = PairUse::once;    // and after a field refresh, for its readers
  bool moves_particles_ = false;  // some term sets a regularisation velocity (FluidFields::shift_u)
  bool periodic_[2] = {false, false};
  double lo_[2] = {0, 0}, len_[2] = {1, 1};
  double max_accel_ = 0;
  long evals_ = 0;
  RhsTiming timing_;
  std::vector<double> implicit_u_, implicit_v_;  // IMEX: f_I's acceleration of the last eval
  std::vector<double> keep_u_, keep_v_, keep_ud_, keep_vd_, keep_du_, keep_dv_;  // scratch of viscous_acceleration
  std::vector<double> probe_u_, probe_v_;
};

}  // namespace arksph
