// What the two ARKODE 6.4 time integrators share, ERKStep (erk_integrator.hpp) and ARKStep IMEX
// (imex_integrator.hpp): the SUNContext and the state vector, the step-size control of
// StepOptions, fixed steps that land on a stop time, reset and restart, the counters across
// restarts, ARKODE's messages, and the exceptions of the C++ callbacks (callback_guard.hpp), which
// are rethrown, unchanged, once ARKODE has returned.
//
// ARKODE 6.4 has no functions common to its step modules (ERKStep, ARKStep, ...): each module
// names its own, with the same signatures. ArkodeStepModule lists the ones used here; a derived
// class hands over the table of its module and the step module memory it created.
#pragma once
#include <cstddef>
#include <exception>
#include <string>
#include <utility>
#include <vector>

#include <arkode/arkode.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_nvector.h>

#include "integrate/callback_guard.hpp"
#include "integrate/step_options.hpp"
#include "integrate/time_integrator.hpp"

namespace arksph {

// One ARKODE step module's functions (ERKStepEvolve, ARKStepEvolve, ...).
struct ArkodeStepModule {
  const char* name;  // "ERKStep", "ARKStep": the functions' prefix, for messages
  int (*set_user_data)(void*, void*);
  int (*set_err_handler_fn)(void*, ARKErrHandlerFn, void*);
  int (*set_max_num_steps)(void*, long);
  int (*ss_tolerances)(void*, sunrealtype, sunrealtype);
  int (*set_fixed_step)(void*, sunrealtype);
  int (*set_stability_fn)(void*, ARKExpStabFn, void*);
  int (*set_cfl_fraction)(void*, sunrealtype);
  int (*set_fixed_step_bounds)(void*, sunrealtype, sunrealtype);
  int (*set_init_step)(void*, sunrealtype);
  int (*set_stop_time)(void*, sunrealtype);
  int (*evolve)(void*, sunrealtype, N_Vector, sunrealtype*, int);
  int (*reset)(void*, sunrealtype, N_Vector);
  int (*resize)(void*, N_Vector, sunrealtype, sunrealtype, ARKVecResizeFn, void*);
  int (*get_current_step)(void*, sunrealtype*);
  int (*get_last_step)(void*, sunrealtype*);
  char* (*return_flag_name)(long);  // malloc'ed
  void (*free)(void**);
};

class ArkodeIntegrator : public TimeIntegrator {
 public:
  ~ArkodeIntegrator() override;
  ArkodeIntegrator(const ArkodeIntegrator&) = delete;
  ArkodeIntegrator& operator=(const ArkodeIntegrator&) = delete;

  // Advances to tout exactly (stop time). Returns the reached time; throws NumericalFailure on
  // error, or the exception a callback threw.
  double evolve_to(double tout) final;
  // One internal step, not past tstop.
  double step(double tstop) final;
  double* state() final;
  // Re-initialises the method at (t, state()) after the state was changed outside ARKODE.
  void reset(double t) final;
  std::size_t size() const final { return n_; }
  StepStats stats() const final;
  // Checkpoints (io/checkpoint.hpp): re-initialises at (t, state()) as a new integrator created
  // there would start (first step h in adaptive mode; the fixed step otherwise), so that a run
  // restarted from the checkpoint continues bit for bit.
  void restart_at(double t, double h) final;
  double next_step() const final;  // the step size ARKODE will attempt next
  // Whether the last failure of an evolve call named a non-finite right-hand side entry of this
  // process's state (several ranks: the rank holding the particle).
  bool failure_names_entry() const { return non_finite_.found; }
  // A run over several ranks after a migration: the state becomes y (this rank's new particles, any
  // length), and the integrator is re-initialised at t as by restart_at(t, h).
  void resize(const std::vector<double>& y, double t, double h);

 protected:
  // Creates the context and the state vector y0 at t0; the derived constructor then creates the
  // step module on them and calls adopt().
  ArkodeIntegrator(const ArkodeStepModule& module, const std::vector<double>& y0, double t0, const StepOptions& opt);
  // Takes the step module memory of XStepCreate (throws if null): this object becomes its user
  // data (see self()), ARKODE's messages are kept for the failure message instead of printed.
  void adopt(void* mem);
  // The step control of the options (the derived constructor's last call). Tolerances are set in
  // adaptive mode, and also with a fixed step when `tolerances_with_fixed_step` (ARKStep: they set
  // the Newton tolerance there).
  void apply_step_options(const StepOptions& opt, bool tolerances_with_fixed_step);
  // Throws NumericalFailure when a call `module.name + call` failed (flag < 0).
  void check(int flag, const char* call);
  // A right-hand side callback: ydot = f(t, y); flag 1 (recoverable: ARKODE retries with a smaller
  // step) when ydot is not finite, kCallbackFailed when f threw. The first non-finite entry is kept:
  // if ARKODE then gives up, the failure names it (time, entry via StepOptions::describe_entry).
  int evaluate_rhs(const RhsFunction& f, double t, N_Vector y, N_Vector ydot) noexcept;
  // Runs the body of a callback with its exception kept for the wrapper (callback_guard.hpp).
  template <class Body>
  int guarded(Body&& body) noexcept {
    return guarded_callback(callback_error_, std::forward<Body>(body));
  }
  // The integrator behind a callback's user data.
  template <class Derived>
  static Derived& self(void* user_data) {
    return static_cast<Derived&>(*static_cast<ArkodeIntegrator*>(user_data));
  }
  // Frees the step module memory; a derived destructor calls it before freeing what the module
  // refers to (linear solver, matrix).
  void free_memory();
  // XStepReInit at (t, state()) with the module's callbacks, and the derived class's own
  // counters back to zero: the start of a new integrator.
  virtual void reinit(double t) = 0;
  // After resize replaced the state vector, before the re-initialisation: what the derived class
  // keeps of the old length (an iterative linear solver's vectors) made anew.
  virtual void resized() {}
  // The counters since the creation or the last reinit (without the offset of a restart).
  virtual StepStats module_stats() const = 0;

  SUNContext ctx_ = nullptr;
  N_Vector y_ = nullptr;
  void* mem_ = nullptr;

 private:
  static int stability_cb(N_Vector y, double t, double* hstab, void* user_data) noexcept;
  void evolve(double tout, int itask);
  N_Vector new_state_vector(std::size_t n);
  void destroy_state_vector(N_Vector v);
  const ArkodeStepModule& module_;
  StateVectorFactory factory_;
  AnyRank any_rank_;
  StabilityFunction stab_;
  std::size_t n_;
  double t_;
  double fixed_dt_ = 0;
  double current_h_ = 0;  // fixed-step mode: the step currently set in ARKODE (the last one may be shorter)
  std::string last_message_;  // last ARKODE warning or error
  EntryDescription describe_entry_;
  struct NonFinite {
    bool found = false;
    double t = 0, value = 0;
    std::size_t index = 0;
  } non_finite_;  // the first non-finite right-hand side entry of the current evolve call
  std::exception_ptr callback_error_;
};

}  // namespace arksph
