#include "integrate/arkode_integrator.hpp"
#include "integrate/serial_vector.hpp"

#include <nvector/nvector_serial.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "core/errors.hpp"

namespace arksph {

ArkodeIntegrator::ArkodeIntegrator(const ArkodeStepModule& module, const std::vector<double>& y0, double t0,
                                   const StepOptions& opt)
    : module_(module),
      factory_(opt.state_vector),
      any_rank_(opt.any_rank),
      stab_(opt.stability),
      n_(y0.size()),
      t_(t0),
      fixed_dt_(opt.fixed_dt),
      current_h_(opt.fixed_dt),
      describe_entry_(opt.describe_entry) {
  if (SUNContext_Create(nullptr, &ctx_) < 0) throw NumericalFailure("ARKODE: SUNContext_Create failed");
  y_ = new_state_vector(n_);
  std::copy(y0.begin(), y0.end(), N_VGetArrayPointer(y_));
}

N_Vector ArkodeIntegrator::new_state_vector(std::size_t n) {
  const auto length = static_cast<sunindextype>(n);
  N_Vector v = factory_.make ? factory_.make(length, ctx_) : new_serial_vector(length, ctx_);
  if (!v) throw NumericalFailure("ARKODE: the state vector could not be created");
  return v;
}

void ArkodeIntegrator::destroy_state_vector(N_Vector v) {
  if (factory_.destroy)
    factory_.destroy(v);
  else
    N_VDestroy(v);
}

ArkodeIntegrator::~ArkodeIntegrator() {
  free_memory();
  if (y_) destroy_state_vector(y_);
  if (ctx_) SUNContext_Free(&ctx_);
}

void ArkodeIntegrator::free_memory() {
  if (mem_) module_.free(&mem_);
  mem_ = nullptr;
}

void ArkodeIntegrator::adopt(void* mem) {
  if (!mem) throw NumericalFailure(std::string("ARKODE: ") + module_.name + "Create failed");
  mem_ = mem;
  check(module_.set_user_data(mem_, this), "SetUserData");
  check(module_.set_err_handler_fn(
            mem_,
            [](int, const char*, const char* function, char* msg, void* user_data) noexcept {
              auto& me = self<ArkodeIntegrator>(user_data);
              me.guarded([&] {
                std::string m = std::string(function) + ": " + msg;
                std::replace(m.begin(), m.end(), '\n', ' ');
                me.last_message_ = m;
              });
            },
            this),
        "SetErrHandlerFn");
}

void ArkodeIntegrator::apply_step_options(const StepOptions& opt, bool tolerances_with_fixed_step) {
  check(module_.set_max_num_steps(mem_, opt.max_steps), "SetMaxNumSteps");
  if (tolerances_with_fixed_step) check(module_.ss_tolerances(mem_, opt.rtol, opt.atol), "SStolerances");
  if (opt.fixed_dt > 0) {
    check(module_.set_fixed_step(mem_, opt.fixed_dt), "SetFixedStep");
  } else {
    if (!tolerances_with_fixed_step) check(module_.ss_tolerances(mem_, opt.rtol, opt.atol), "SStolerances");
    if (stab_) {
      check(module_.set_stability_fn(mem_, &ArkodeIntegrator::stability_cb, this), "SetStabilityFn");
      // h <= cfl_fraction * hstab; the callback returns limit / 0.99 so that h <= limit exactly.
      check(module_.set_cfl_fraction(mem_, 0.99), "SetCFLFraction");
      check(module_.set_fixed_step_bounds(mem_, 1.0, 1.0), "SetFixedStepBounds");
    }
    if (opt.initial_dt > 0) check(module_.set_init_step(mem_, opt.initial_dt), "SetInitStep");
  }
}

void ArkodeIntegrator::check(int flag, const char* call) {
  rethrow_callback_error(callback_error_);  // a callback that threw during the call explains its failure
  if (flag < 0)
    throw NumericalFailure(std::string("ARKODE: ") + module_.name + call + " failed with flag " + std::to_string(flag));
}

int ArkodeIntegrator::evaluate_rhs(const RhsFunction& f, double t, N_Vector y, N_Vector ydot) noexcept {
  return guarded([&] {
    f(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot));
    const double* d = N_VGetArrayPointer(ydot);
    bool bad = false;
    for (std::size_t i = 0; i < n_ && !bad; ++i)
      if (!std::isfinite(d[i])) {
        if (!non_finite_.found) non_finite_ = {true, t, d[i], i};
        bad = true;
      }
    if (any_rank_) bad = any_rank_(bad);
    return bad ? 1 : 0;  // 1, recoverable: ARKODE retries with a smaller step
  });
}

int ArkodeIntegrator::stability_cb(N_Vector y, double t, double* hstab, void* user_data) noexcept {
  auto& me = self<ArkodeIntegrator>(user_data);
  return me.guarded([&] { *hstab = me.stab_(t, N_VGetArrayPointer(y)) / 0.99; });
}

void ArkodeIntegrator::evolve(double tout, int itask) {
  non_finite_ = {};
  const int flag = module_.evolve(mem_, tout, y_, &t_, itask);
  rethrow_callback_error(callback_error_);  // the callback's own exception, not ARKODE's flag for it
  if (flag < 0 && non_finite_.found) {  // ARKODE gave up on a right-hand side that stayed non-finite
    char at[48];
    std::snprintf(at, sizeof at, "t = %.9g, ", non_finite_.t);
    throw NumericalFailure(at + (describe_entry_ ? describe_entry_(non_finite_.index, non_finite_.value)
                                                 : "right-hand side entry " + std::to_string(non_finite_.index) +
                                                       " = " + arksph::message_number(non_finite_.value)));
  }
  if (flag < 0) {
    char* name = module_.return_flag_name(flag);
    const std::string flag_name = name ? name : "unknown";
    std::free(name);
    throw NumericalFailure(std::string("ARKODE: ") + module_.name + "Evolve failed at t = " + arksph::message_number(t_) +
                           " with flag " + std::to_string(flag) + " (" + flag_name + "; " + last_message_ + ")");
  }
}

double ArkodeIntegrator::evolve_to(double tout) {
  if (fixed_dt_ > 0) {  // see step(): land on tout by shortening the last step, no stop time
    while (t_ < tout) step(tout);
    return t_;
  }
  check(module_.set_stop_time(mem_, tout), "SetStopTime");
  evolve(tout, ARK_NORMAL);
  return t_;
}

double ArkodeIntegrator::step(double tstop) {
  if (fixed_dt_ > 0) {
    // Fixed step: the last step before tstop is shortened to land on it. ARKODE's own stop time
    // is not used here: it returns the interpolant at tstop, and for first-order tables (degree-0
    // interpolant) that is not the solution (measured: y' = 1 gave y(0.01) = 0.005).
    const double remaining = tstop - t_;
    const double h = remaining <= fixed_dt_ * (1 + 1e-10) ? remaining : fixed_dt_;
    if (h != current_h_) {
      check(module_.set_fixed_step(mem_, h), "SetFixedStep");
      current_h_ = h;
    }
    evolve(tstop, ARK_ONE_STEP);
    if (std::abs(tstop - t_) <= 1e-12 * std::max(1.0, std::abs(tstop))) t_ = tstop;  // round-off of t + h
    return t_;
  }
  check(module_.set_stop_time(mem_, tstop), "SetStopTime");
  evolve(tstop, ARK_ONE_STEP);
  return t_;
}

double* ArkodeIntegrator::state() { return N_VGetArrayPointer(y_); }

void ArkodeIntegrator::reset(double t) {
  check(module_.reset(mem_, t, y_), "Reset");
  t_ = t;
}

void ArkodeIntegrator::restart_at(double t, double h) {
  // ReInit, unlike Reset, also clears the step-size controller's history and the counters, as in a
  // new integrator; the counters live on in offset_.
  const StepStats total = stats();
  reinit(t);
  t_ = t;
  offset_ = total;
  if (fixed_dt_ > 0) {
    check(module_.set_fixed_step(mem_, fixed_dt_), "SetFixedStep");
    current_h_ = fixed_dt_;
  } else if (h > 0) {
    check(module_.set_init_step(mem_, h), "SetInitStep");
  }
}

void ArkodeIntegrator::resize(const std::vector<double>& y, double t, double h) {
  N_Vector fresh = new_state_vector(y.size());
  std::copy(y.begin(), y.end(), N_VGetArrayPointer(fresh));
  const int flag = module_.resize(mem_, fresh, 1.0, t, nullptr, nullptr);
  if (flag < 0) {
    destroy_state_vector(fresh);
    check(flag, "Resize");
  }
  destroy_state_vector(y_);
  y_ = fresh;
  n_ = y.size();
  resized();
  restart_at(t, h);
}

double ArkodeIntegrator::next_step() const {
  double h = 0;
  module_.get_current_step(mem_, &h);
  return h;
}

StepStats ArkodeIntegrator::stats() const {
  StepStats s = module_stats();
  s.steps += offset_.steps;  // restart: the counters of the run before
  s.rhs_evals += offset_.rhs_evals;
  s.attempts += offset_.attempts;
  s.error_test_fails += offset_.error_test_fails;
  s.implicit_rhs_evals += offset_.implicit_rhs_evals;
  s.newton_iters += offset_.newton_iters;
  s.newton_fails += offset_.newton_fails;
  s.linear_setups += offset_.linear_setups;
  s.jacobian_evals += offset_.jacobian_evals;
  s.symbolic_analyses += offset_.symbolic_analyses;
  s.linear_iters += offset_.linear_iters;
  module_.get_last_step(mem_, &s.last_step);
  if (s.last_step == 0) s.last_step = offset_.last_step;
  return s;
}

}  // namespace arksph
