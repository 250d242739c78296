// f(t, y) on one rank of a decomposed run. The rank's state y holds its own particles only; the
// right-hand side runs the ordinary evaluator (rhs/evaluator.hpp) over the rank's particles followed
// by the halo, copies of the other ranks' particles (and periodic images of its own) within
//   cutoff = 2 R + skin        (R the kernel support, skin = 0.15 R as the Verlet skin)
// of its box (parallel/halo.hpp), and keeps the derivatives of its own particles. The evaluator
// treats the halo copies as particles of its own: their derivatives are discarded, but the values
// they compute on the way and hand to the rank's particles are complete. Two supports, because a
// particle's sums read values its neighbours computed over their own neighbourhoods (density by
// summation, kernel correction, the density-diffusion gradient, velocity gradients at wall
// images); the copies within R of the rank's particles have their whole neighbourhood within 2 R.
// Wall images of the rank's particles and of the copies come from the evaluator's ghosts, which
// build walls only: the evaluator takes the rank's scene (rank_scene), whose periodic sides are
// marked as bringing halo copies (SideSpec::halo).
//
// At each evaluation the copies take the state's new positions, velocities, density and energy
// from their owners, and every rank its largest displacement since the last exchange from every
// other (HaloExchange::update_max: one all-to-all with the counts of the exchange, no other
// collective). When some particle has moved more than skin / 2 since the last exchange, the halo is
// exchanged anew from the current positions and an evaluator is built over the new set (its
// neighbour list built anew, as the Verlet list of one process is at the same rule). The halo rule uses
// each rank's block of the decomposition grown around its particles' current positions, so the
// halo stays complete however far particles have left their block since the last migration.
//
// Positions: the state keeps the positions of a one-process run (never wrapped). At an exchange
// each rank position is brought into the box along the periodic axes, and the offset between the
// two is kept until the next exchange: the evaluator sees positions that move continuously.
#pragma once
#include <memory>
#include <vector>

#include "core/scene.hpp"
#include "integrate/viscous_split.hpp"
#include "parallel/communicator.hpp"
#include "parallel/halo.hpp"
#include "parallel/rank_particles.hpp"
#include "parallel/rcb.hpp"
#include "rhs/evaluator.hpp"
#include "run/setup.hpp"

namespace arksph::distributed {

// The scene of one rank's evaluator: the run's, its periodic sides marked as bringing halo copies.
Scene rank_scene(const Scene& scene);

// The whole model's evaluator as a rank keeps it, without particle data: the layout, kernel and
// terms (their step limits, Term::max_step) that the run reads of the model, which no rank
// evaluates (RankProcess puts it in place of the model's evaluator once the particles are dealt).
std::unique_ptr<RhsEvaluator> without_particles(const Scene& scene, const Model& model);

class HaloRhs {
 public:
  HaloRhs(const Scene& scene, const Model& model, const parallel::Communicator& comm, parallel::RankParticles& owned);
  // The decomposition the rank's particles were last migrated by; the next eval exchanges anew.
  void set_decomposition(const parallel::Decomposition& decomposition);
  // Collective. ydot = f(t, y) for this rank's particles (ydot null: the evaluator's fields only,
  // as RhsEvaluator::eval refreshes them; the largest acceleration is kept from the last f).
  void eval(double t, const double* y, double* ydot);
  // The largest |du/dt| of this rank's particles at the last eval.
  double local_max_acceleration() const { return max_accel_; }
  // The evaluator of the last eval: its fields hold this rank's particles first, then the halo.
  const RhsEvaluator& evaluator() const { return *evaluator_; }
  RhsEvaluator& evaluator() { return *evaluator_; }
  // The state the evaluator took at the last eval, in its layout: this rank's particles, then the
  // halo copies with their owners' values (the velocities a pair loop reads at the copies).
  const double* evaluated_state() const { return y_all_.data(); }
  // Frees the evaluator until the next eval, which builds it anew (build_evaluator): while rank 0
  // holds a whole frame or checkpoint.
  void release_storage() {
    evaluator_.reset();
    ++builds_;  // the fields of the last eval are gone
  }
  long exchanges() const { return exchanges_; }  // halo exchanges (each with a new neighbour list) so far
  // This rank's wall time in eval: halo exchanges (geometry, copies, the evaluator's new particle
  // set), halo updates (the all-to-all of each eval, waiting for the other ranks included) and the
  // evaluator (neighbour list and terms).
  struct Seconds {
    double exchange = 0, update = 0, evaluator = 0;
  };
  const Seconds& seconds() const { return seconds_; }
  // Collective. The values *own[k] of this rank's particles (one each, in the rank's order) at their
  // halo copies of the last eval (element k), in the evaluator's order of the copies (the
  // projection's row numbers and pressures: halo_domain.hpp). One all-to-all along the exchange's
  // send lists.
  std::vector<std::vector<double>> halo_values(const std::vector<const std::vector<double>*>& own) const;
  // time.imex (RhsOptions::imex_split) for this evaluator and those of later exchanges: eval's ydot
  // holds f_E, implicit_part f_I (split_source below).
  void set_imex_split(bool on);
  // f_I of the last eval with the split, this rank's rows in its own layout (size y).
  void implicit_part(double* ydot_i);
  // Collective. The viscous acceleration of this rank's particles (RhsEvaluator::viscous_acceleration)
  // for the velocities (u, v) of this rank's particles, their halo copies given their owners'
  // values (one all-to-all), at the fields of the last eval.
  void viscous_acceleration(const double* u, const double* v, double* au, double* av);
  // Changes whenever the fields of the last eval are replaced or freed (an exchange, a new
  // evaluator, release_storage).
  long builds() const { return builds_; }
  // RhsEvaluator::set_slip_origin, kept for the evaluators of later exchanges (the projection's
  // body-force split: the stages of a step carry the increment (t - t0) g, projection/projection.hpp).
  void set_slip_origin(bool on, double t0);

 private:
  void exchange();
  void build_evaluator();

  const Scene scene_;  // rank_scene of the run's
  const Model& model_;
  const parallel::Communicator& comm_;
  parallel::RankParticles& owned_;
  const parallel::Decomposition* decomposition_ = nullptr;
  double radius_, skin_, cutoff_;
  parallel::HaloExchange exchange_;
  parallel::ParticleFields halo_;
  std::vector<int> update_fields_;           // sent at every eval
  std::vector<int> blocks_;                  // parallel::RankFieldIndex::state_blocks(true)
  std::vector<std::vector<double>> offset_;  // per axis: state position - seen position
  std::vector<std::vector<double>> ref_;     // per axis: seen positions at the exchange
  std::unique_ptr<RhsEvaluator> evaluator_;
  std::vector<double> y_all_, ydot_all_;
  double max_accel_ = 0;
  long exchanges_ = 0;
  bool exchange_due_ = true;
  Seconds seconds_;
  bool slip_on_ = false;
  double slip_t0_ = 0;
  bool imex_split_ = false;
  long builds_ = 0;
  std::vector<double> own_u_, own_v_, all_u_, all_v_, all_au_, all_av_;  // scratch of viscous_acceleration
};

// time.imex on a rank: its f as the split's source (integrate/viscous_split.hpp), f_E and f_I of the
// rank's particles with the split evaluation switched on, the halo copies' velocities from their
// owners, and whether a cached evaluation serves agreed by the ranks (each evaluation is
// collective). Its stages are solved by SPGMR over KrylovViscousSplit's operator (no periodic axes:
// the halo copies carry the periodic images).
std::unique_ptr<SplitSource> split_source(HaloRhs& f, const parallel::RankParticles& mine,
                                          const parallel::Communicator& comm);

}  // namespace arksph::distributed
