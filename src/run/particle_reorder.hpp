// Re-sorting the particles by cell at sync points of the run (method.reorder_every): every
// `reorder_every` accepted steps the particles are permuted into row-major order of a grid of cell
// side = kernel support anchored at domain.min (periodic positions wrapped into the box first), so
// that the neighbours of a particle sit near it in memory. Particles mix as a flow runs; without
// re-sorting the neighbour loops gather from all over the arrays.
//
// Everything indexed by particle follows the one permutation (core/particle_order.hpp): the state
// vector, the particle set of the model and of the RHS evaluator, the ISPH warm starts, the
// number density at t = 0 of the diagnostics; the neighbour list, the ghosts and the IMEX
// Jacobian pattern are rebuilt, the IMEX split's caches dropped, and the integrator is
// re-initialised at (t, y) as after a checkpoint (restart_at: no FSAL value, Newton matrix or
// Jacobian in the old order survives). Particles keep their ids, which the output writes.
#pragma once
#include <vector>

#include "run/setup.hpp"
#include "core/particle_order.hpp"
#include "integrate/time_integrator.hpp"
#include "integrate/viscous_split.hpp"

namespace arksph {

// The model's per-particle data (particle sets of the model and the RHS evaluator, projection
// warm starts) permuted; the state vector is the caller's.
void permute_model(Model& model, const Permutation& from);

// A checkpoint written after re-sorts holds the particles in its own order: puts the model's
// particles into the order of `ids` (a no-op when the orders agree or when `ids` is not a
// permutation of the model's, which the checkpoint check then reports). Returns the permutation
// applied (empty: none), for the caller's own per-particle arrays.
Permutation adopt_particle_order(Model& model, const std::vector<std::int64_t>& ids);

class ParticleReorder {
 public:
  ParticleReorder(const Scene& scene, Model& model);
  // True after an accepted step whose total count is a multiple of method.reorder_every.
  bool due(long steps) const { return every_ > 0 && steps > 0 && steps % every_ == 0; }
  // Puts the state y (the model's layout) and the model into cell order; `d0` (number density at
  // t = 0) follows. Returns false when y was in cell order already (nothing changed).
  bool sort(double* y, std::vector<double>& d0);
  // At a sync point of the run: sort(integrator.state()), then the IMEX split (null if none) drops
  // its caches and the integrator is re-initialised at t.
  void apply(double t, TimeIntegrator& integrator, std::vector<double>& d0, ViscousSplit* split);
  // The permutation into cell order of the state y (positions in the layout of the model).
  Permutation order_of(const double* y) const;
  long count() const { return count_; }  // re-sorts that changed the order
  double seconds() const { return seconds_; }

 private:
  const Scene& scene_;
  Model& model_;
  long every_;
  double side_;
  long count_ = 0;
  double seconds_ = 0;
};

}  // namespace arksph
