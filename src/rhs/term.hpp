// One physical term of the right-hand side. Each term lives in its own file, named after the term
// and its source, and is constructed only when the scene needs it (rhs/terms_from_scene.cpp).
#pragma once
#include <cstddef>
#include <limits>
#include <string>
#include <utility>

#include "core/registry.hpp"
#include "neighbors/neighborhood.hpp"
#include "rhs/fluid_fields.hpp"

namespace arksph {

class Term {
 public:
  // Terms run in stage order: density (fills rho of real particles), pressure (fills p),
  // force (adds to dudt, dvdt, drhodt). Ghost copies of rho and p are refreshed between stages.
  enum class Stage { density, pressure, force };
  virtual ~Term() = default;
  virtual std::string name() const = 0;  // "kind:model", listed in summary.json "terms"
  virtual Stage stage() const = 0;
  virtual void apply(FluidFields& f) const = 0;
  // Whether the term adds a regularisation velocity to f.shift_u, f.shift_v (dr/dt = u + du_s).
  virtual bool moves_particles() const { return false; }
  // The largest step an explicit Runge-Kutta method may take for this term's own dynamics to stay
  // stable, where the term has a stiffness of its own that the CFL, viscous and force limits do not
  // cover (run/setup.hpp, stable_step); +infinity for the others.
  virtual double max_step() const { return std::numeric_limits<double>::infinity(); }
  // Whether apply() walks f.pairs (an equation of state or a body force does not).
  virtual bool uses_neighbors() const { return true; }
  // Terms that only read neighbours and add to real particle a's derivatives (rhs/particle_term.hpp)
  // can also be applied one particle at a time from a gathered neighbourhood: the evaluator then
  // runs consecutive such terms in one sweep over the particles (method.force_sweep).
  virtual bool per_particle() const { return false; }
  virtual void apply_particle(FluidFields&, std::size_t, const Neighborhood&) const {}
  // Whether apply_particle reads W_ab other than through corrected_gradient (which needs it only
  // when a kernel correction is on). The sweep skips W when no term needs it.
  virtual bool reads_kernel_value() const { return true; }
  // Whether this term adds `other`'s contribution in its own pair loop from now on, so that one walk
  // over the neighbours serves both: the evaluator asks this of force terms of the same partition
  // (with the IMEX split, the Term::can_be_implicit terms form their own) and then runs `other` no
  // more (in the sweep and over the pairs alike). A term that says yes keeps what it needs of
  // `other`. Terms built outside the evaluator are not asked and stay whole.
  virtual bool take_over(const Term& /*other*/) { return false; }
  // Forgets every term taken over: they run on their own again (the evaluator asks anew whenever its
  // partitions change, RhsOptions::imex_split).
  virtual void give_back() {}
  // The traits of the registered part that built the term (core/registry.hpp), set by
  // terms_from_scene; a term built without a part has the default traits.
  const PartTraits& traits() const { return traits_; }
  void set_traits(PartTraits traits) { traits_ = std::move(traits); }
  // Whether the term may go into the implicit partition of an IMEX split (time.imex): it adds only
  // to dudt, dvdt, and affinely in the velocities (the viscous terms).
  bool can_be_implicit() const { return traits_.can_be_implicit; }
  // Whether the term needs the velocity gradient at the ghosts themselves, so that a ghost needs its
  // own full neighbourhood: the ghost layers are then twice the support radius deep (Basa et al.
  // 2008 §5.2, the two-pass viscosity: stencil depth 2).
  bool needs_ghost_velocity_gradients() const { return traits_.stencil_depth > 1; }

 private:
  PartTraits traits_;
};

}  // namespace arksph
