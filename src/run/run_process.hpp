// What differs between a run on one process and a run decomposed over MPI ranks, as a strategy
// that the one set-up and the one run loop (run/model_run.hpp, run/run_loop.hpp) are given:
//   - the collectives: agree on a verdict, max, sum (the identity on one process);
//   - the particles of the process: the whole model's, re-sorted at the sync points (one process),
//     or the rank's, dealt by a bisection and migrated at the sync points, with their halo;
//   - f(t, y) over them, the state vector (serial, or MPIPlusX with global norms), the projection;
//   - the frame's diagnostics and rows (computed by RunOutput, or reduced over the ranks and the rows
//     joined on rank 0 or written as pieces);
//   - the whole state for the checkpoints (the integrator's, or gathered from the ranks), and what
//     the run does after a scheduled checkpoint (restart_at, or a new deal and integrator).
// Two implementations: OneProcess (run/simulation.cpp) and distributed::RankProcess
// (distributed/distributed_run.cpp).
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "core/particle_order.hpp"
#include "core/scene.hpp"
#include "diagnostics/frame_reduction.hpp"
#include "integrate/time_integrator.hpp"
#include "io/frame.hpp"
#include "io/checkpoint.hpp"
#include "run/run_output.hpp"
#include "run/setup.hpp"
#include "run/state_check.hpp"
#include "core/verdict.hpp"

namespace arksph {

// Throws what the ranks agreed on: code 2 InputError, 3 NumericalFailure, 5 OutputError, another
// non-zero code std::runtime_error; nothing for 0.
void raise(const Verdict& v);

// This process's particles in a frame, at the fields of a refresh at the frame's state.
struct FrameSource {
  FrameParticles particles;  // the fields (the process's particles first), their d0 and phases
  // Whether this process adds the diagnostics' sample point (x, y) (FrameReduction::add).
  std::function<bool(double, double)> owns;
  const double* x = nullptr;  // the particles' positions in the box (y null in 1D)
  const double* y = nullptr;
  const double* pressure = nullptr;  // the projection's (isph), or the fields'
  const std::int64_t* id = nullptr;
  double support = 0;  // the kernel's support radius R (the wall points written, run/wall_frame.hpp)
  // The fields' periodic neighbours are halo copies, not images (a rank's: distributed/halo_rhs.hpp).
  bool halo_copies = false;
};

class RunProcess {
 public:
  virtual ~RunProcess() = default;

  // The collectives over the run's processes; on one process the identity.
  virtual int ranks() const { return 1; }
  // The process that writes the output folder's files.
  virtual bool root() const { return true; }
  // Collective: the verdict every process leaves with (the largest code; parallel/agreement.hpp),
  // and `flag` replaced by its largest value over the processes.
  virtual Verdict agree(const Verdict& mine, std::int64_t& /*flag*/) const { return mine; }
  Verdict agree(const Verdict& mine) const {
    std::int64_t none = 0;
    return agree(mine, none);
  }
  virtual double sum(double x) const { return x; }
  virtual std::int64_t max(std::int64_t x) const { return x; }
  virtual void sum_in_place(std::vector<double>&) const {}
  virtual void max_in_place(std::vector<double>&) const {}
  // Every process's v concatenated in process order, on the root.
  virtual std::vector<double> gather(const std::vector<double>& v) const { return v; }
  // Runs body on this process; over several ranks its InputError, OutputError or NumericalFailure
  // becomes this rank's verdict, which every rank then throws (raise), so that no rank is left
  // waiting in a collective call.
  template <class Body>
  void together(Body&& body) const;

  // Set-up, in this order (run/model_run.cpp).
  // InputError (one line, naming the key) for what this process cannot run.
  virtual void refuse_unsupported(const Scene&) const {}
  // The model is built (before the header names its terms): what the process changes in it.
  virtual void built(Model&) {}
  // The header's words for the processes (" on 3 MPI ranks") and the form of the frames.
  virtual std::string where() const { return ""; }
  virtual std::string frame_form() const { return ""; }
  // The particles of the initial state of `model` (every process built the whole model) and their
  // fields at t = 0: the number density d0 the frames' diagnostics compare with, and the largest
  // acceleration (initial_acceleration).
  virtual void initial_state(Model& model) = 0;
  // Restart: the model's particles were put into the checkpoint's order (core/particle_order.hpp;
  // empty: no change).
  virtual void adopted_order(const Permutation&) {}
  // The largest |du/dt| at t = 0 over every particle (the state checker's speed bound).
  virtual double initial_acceleration() const = 0;
  // The projection and the integrator at t0, at the initial state or at the checkpoint's
  // (`restart`, null for a fresh run), with the counters of the run so far. Returns the evaluations
  // of f the set-up made for the output (summary.json diagnostic_evals).
  virtual long start_stepping(double t0, const Checkpoint* restart, const StepStats& counters) = 0;
  // output.pieces: the ranks whose pieces a frame's index names (0: whole frames).
  virtual int pieces() const { return 0; }
  // Between the last phases of the set-up: a pending signal ends the set-up (run/interrupt.hpp;
  // one process: a rank cannot leave the others waiting in a collective).
  virtual void poll_interrupt() const {}
  // The output at the start is written (or a restart has it): the run steps from here.
  virtual void started() {}

  // Stepping.
  virtual TimeIntegrator& integrator() = 0;
  // One step from t towards `stop` (run/run_loop.hpp).
  virtual double step(double t, double stop) = 0;
  // The wall reflections of this process's particles after a step (boundary/wall_reflection.hpp);
  // the integrator is re-initialised by the caller when any process reflected. Returns their count.
  virtual long reflect() = 0;
  // The state check of this process's particles at t. Throws NumericalFailure.
  virtual void check(const StateChecker& checker, double t) = 0;
  // The sync point after the step that made `steps` accepted steps: re-sort or migrate when due.
  virtual void sync_point(double t, long steps) = 0;
  // sum m u . a_visc of this process's particles at a field refresh of the state at t
  // (RhsEvaluator::viscous_power).
  virtual double viscous_power(double t) = 0;
  // The frame at t: this process's particles after a field refresh at the state (one evaluation of
  // f), valid until the next call.
  virtual FrameSource frame_source(double t) = 0;
  // The frame's rows `mine` (this process's particles), the wall points of those particles
  // (output.walls, run/wall_frame.hpp; else null) and the record of the frame by `out`, the run's
  // output on the root (null elsewhere): on one process the whole frame; over ranks each rank's
  // piece (output.pieces), or the rows joined on rank 0.
  virtual void write_rows(const FrameDiagnostics& diag, const StepStats& stats, const Frame& mine, const Frame* walls,
                          RunOutput* out) {
    out->record(diag, stats, &mine, walls);
  }

  // Checkpoints: `use` gets the whole state in the model's layout and particle order (on the root;
  // on every process with `everywhere`; elsewhere null).
  virtual void with_whole_state(bool everywhere, const std::function<void(const double*)>& use) = 0;
  // After the scheduled checkpoint of the whole state y at t: the run continues as a restart from
  // it does (a new integrator at t, first step h, counters `counters`).
  virtual void continue_from_checkpoint(double t, double h, const StepStats& counters, const double* y) = 0;

  // Failures: ARKODE gave up at or after t (the verdict is the same on every process); where the
  // flow is most violent at t ("" where that is not known without a collective); an allocation
  // failed (the verdict, or rethrows: called from the handler).
  virtual Verdict numerical_failure(double t, const std::string& what) = 0;
  virtual std::string failure_location(double) { return ""; }
  virtual Verdict out_of_memory(double t) = 0;
  // Collective: what this process adds to summary.json (neighbour rebuilds, re-sorts or
  // migrations, "mpi").
  virtual void report(RunTotals& totals) = 0;
};

template <class Body>
void RunProcess::together(Body&& body) const {
  if (ranks() == 1) {
    body();
    return;
  }
  Verdict mine;
  try {
    body();
  } catch (const InputError& e) {
    mine = {2, e.what()};
  } catch (const OutputError& e) {
    mine = {5, e.what()};
  } catch (const NumericalFailure& e) {
    mine = {3, e.what()};
  }
  raise(agree(mine));
}

}  // namespace arksph
