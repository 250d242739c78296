#include "integrate/erk_integrator.hpp"
#include "integrate/serial_vector.hpp"

#include <arkode/arkode_butcher_erk.h>
#include <arkode/arkode_erkstep.h>
#include <nvector/nvector_serial.h>

#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "core/errors.hpp"

namespace arksph {

namespace {
constexpr const char* kForwardEuler = "ARKSPH_FORWARD_EULER_1_1";

// Loads a table by name; the caller frees it. Forward Euler is ours: ARKODE 6.4 has none.
ARKodeButcherTable load_table(const std::string& name) {
  if (name == kForwardEuler) {
    const sunrealtype c[1] = {0}, A[1] = {0}, b[1] = {1};
    return ARKodeButcherTable_Create(1, 1, 0, const_cast<sunrealtype*>(c), const_cast<sunrealtype*>(A),
                                     const_cast<sunrealtype*>(b), nullptr);
  }
  return ARKodeButcherTable_LoadERKByName(name.c_str());
}

// ERKStepGetReturnFlagName returns a malloc'ed string: copy it and free it.
std::string flag_name(int flag) {
  char* name = ERKStepGetReturnFlagName(flag);
  std::string out = name ? name : "unknown";
  std::free(name);
  return out;
}

int check(int flag, const char* call) {
  if (flag < 0) throw NumericalFailure(std::string("ARKODE: ") + call + " failed with flag " + std::to_string(flag));
  return flag;
}
}  // namespace

std::vector<std::string> erk_table_names() {
  std::vector<std::string> names = {kForwardEuler};
  const char* builtin[] = {"ARKODE_HEUN_EULER_2_1_2",       "ARKODE_BOGACKI_SHAMPINE_4_2_3",
                           "ARKODE_ARK324L2SA_ERK_4_2_3",   "ARKODE_ZONNEVELD_5_3_4",
                           "ARKODE_ARK436L2SA_ERK_6_3_4",   "ARKODE_SAYFY_ABURUB_6_3_4",
                           "ARKODE_CASH_KARP_6_4_5",        "ARKODE_FEHLBERG_6_4_5",
                           "ARKODE_DORMAND_PRINCE_7_4_5",   "ARKODE_ARK548L2SA_ERK_8_4_5",
                           "ARKODE_VERNER_8_5_6",           "ARKODE_FEHLBERG_13_7_8",
                           "ARKODE_KNOTH_WOLKE_3_3",        "ARKODE_ARK437L2SA_ERK_7_3_4",
                           "ARKODE_ARK548L2SAb_ERK_8_4_5"};
  for (const char* b : builtin) names.emplace_back(b);
  return names;
}

bool erk_table_has_fsal_bug(const std::string& name) {
  ARKodeButcherTable B = load_table(name);
  if (!B) return false;
  const int s = B->stages;
  bool bug = false;
  if (std::abs(B->c[s - 1] - 1.0) < 1e-14) {
    for (int j = 0; j < s; ++j)
      if (B->A[s - 1][j] != B->b[j]) bug = true;
  }
  ARKodeButcherTable_Free(B);
  return bug;
}

bool erk_table_has_embedding(const std::string& name) {
  ARKodeButcherTable B = load_table(name);
  const bool emb = B && B->d != nullptr;
  if (B) ARKodeButcherTable_Free(B);
  return emb;
}

int erk_table_order(const std::string& name) {
  ARKodeButcherTable B = load_table(name);
  const int q = B ? B->q : 0;
  if (B) ARKodeButcherTable_Free(B);
  return q;
}

ErkIntegrator::ErkIntegrator(RhsFunction f, const std::vector<double>& y0, double t0, const ErkOptions& opt)
    : f_(std::move(f)), stab_(opt.stability), post_(opt.postprocess), post_stage_(opt.postprocess_stage), n_(y0.size()), t_(t0),
      fixed_dt_(opt.fixed_dt), current_h_(opt.fixed_dt) {
  check(SUNContext_Create(nullptr, &ctx_), "SUNContext_Create");
  y_ = new_serial_vector(static_cast<sunindextype>(n_), ctx_);
  std::copy(y0.begin(), y0.end(), N_VGetArrayPointer(y_));
  mem_ = ERKStepCreate(&ErkIntegrator::rhs_cb, t0, y_, ctx_);
  if (!mem_) throw NumericalFailure("ARKODE: ERKStepCreate failed");
  check(ERKStepSetUserData(mem_, this), "ERKStepSetUserData");
  // ARKODE's messages are kept, not printed: a failure then reports them in its one-line diagnosis.
  check(ERKStepSetErrHandlerFn(
            mem_,
            [](int, const char*, const char* function, char* msg, void* self) {
              std::string m = std::string(function) + ": " + msg;
              for (char& c : m)
                if (c == '\n') c = ' ';
              static_cast<ErkIntegrator*>(self)->last_message_ = m;
            },
            this),
        "ERKStepSetErrHandlerFn");
  ARKodeButcherTable B = load_table(opt.table);
  if (!B) throw InputError("unknown ARKODE table '" + opt.table + "'");
  const int flag = ERKStepSetTable(mem_, B);
  ARKodeButcherTable_Free(B);
  check(flag, "ERKStepSetTable");
  if (post_) {
    check(ERKStepSetPostprocessStepFn(mem_,
                                      [](sunrealtype t, N_Vector y, void* self) {
                                        static_cast<ErkIntegrator*>(self)->post_(t, N_VGetArrayPointer(y));
                                        return 0;
                                      }),
          "ERKStepSetPostprocessStepFn");
    workaround_ = erk_table_has_fsal_bug(opt.table);
  } else if (opt.apply_fsal_workaround && erk_table_has_fsal_bug(opt.table)) {
    check(ERKStepSetPostprocessStepFn(mem_, [](sunrealtype, N_Vector, void*) { return 0; }),
          "ERKStepSetPostprocessStepFn");
    workaround_ = true;
  }
  if (post_stage_) {
    check(ERKStepSetPostprocessStageFn(mem_,
                                       [](sunrealtype t, N_Vector y, void* self) {
                                         static_cast<ErkIntegrator*>(self)->post_stage_(t, N_VGetArrayPointer(y));
                                         return 0;
                                       }),
          "ERKStepSetPostprocessStageFn");
  }
  check(ERKStepSetMaxNumSteps(mem_, opt.max_steps), "ERKStepSetMaxNumSteps");
  if (opt.fixed_dt > 0) {
    check(ERKStepSetFixedStep(mem_, opt.fixed_dt), "ERKStepSetFixedStep");
  } else {
    check(ERKStepSStolerances(mem_, opt.rtol, opt.atol), "ERKStepSStolerances");
    if (stab_) {
      check(ERKStepSetStabilityFn(mem_, &ErkIntegrator::stab_cb, this), "ERKStepSetStabilityFn");
      // h <= cfl_fraction * hstab; the callback returns limit / 0.99 so that h <= limit exactly.
      check(ERKStepSetCFLFraction(mem_, 0.99), "ERKStepSetCFLFraction");
      check(ERKStepSetFixedStepBounds(mem_, 1.0, 1.0), "ERKStepSetFixedStepBounds");
    }
    if (opt.initial_dt > 0) check(ERKStepSetInitStep(mem_, opt.initial_dt), "ERKStepSetInitStep");
  }
}

ErkIntegrator::~ErkIntegrator() {
  if (mem_) ERKStepFree(&mem_);
  if (y_) N_VDestroy(y_);
  if (ctx_) SUNContext_Free(&ctx_);
}

int ErkIntegrator::rhs_cb(double t, N_Vector y, N_Vector ydot, void* self) {
  auto* me = static_cast<ErkIntegrator*>(self);
  me->f_(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot));
  const double* d = N_VGetArrayPointer(ydot);
  for (std::size_t i = 0; i < me->n_; ++i)
    if (!std::isfinite(d[i])) return 1;  // recoverable: ARKODE retries with a smaller step
  return 0;
}

int ErkIntegrator::stab_cb(N_Vector y, double t, double* hstab, void* self) {
  auto* me = static_cast<ErkIntegrator*>(self);
  *hstab = me->stab_(t, N_VGetArrayPointer(y)) / 0.99;
  return 0;
}

double ErkIntegrator::evolve_to(double tout) {
  if (fixed_dt_ > 0) {  // see step(): land on tout by shortening the last step, no stop time
    while (t_ < tout) step(tout);
    return t_;
  }
  check(ERKStepSetStopTime(mem_, tout), "ERKStepSetStopTime");
  const int flag = ERKStepEvolve(mem_, tout, y_, &t_, ARK_NORMAL);
  if (flag < 0) throw NumericalFailure("ARKODE: ERKStepEvolve failed at t = " + std::to_string(t_) +
                                       " with flag " + std::to_string(flag) + " (" +
                                       flag_name(flag) + "; " + last_message_ + ")");
  return t_;
}

double ErkIntegrator::step(double tstop) {
  if (fixed_dt_ > 0) {
    // Fixed step: the last step before tstop is shortened to land on it. ERKStep's own stop time
    // is not used here: it returns the interpolant at tstop, and for first-order tables (degree-0
    // interpolant) that is not the solution (measured: y' = 1 gave y(0.01) = 0.005).
    const double remaining = tstop - t_;
    const double h = remaining <= fixed_dt_ * (1 + 1e-10) ? remaining : fixed_dt_;
    if (h != current_h_) {
      check(ERKStepSetFixedStep(mem_, h), "ERKStepSetFixedStep");
      current_h_ = h;
    }
    const int flag = ERKStepEvolve(mem_, tstop, y_, &t_, ARK_ONE_STEP);
    if (flag < 0) throw NumericalFailure("ARKODE: ERKStepEvolve failed at t = " + std::to_string(t_) + " with flag " +
                                         std::to_string(flag) + " (" + flag_name(flag) + "; " +
                                         last_message_ + ")");
    if (std::abs(tstop - t_) <= 1e-12 * std::max(1.0, std::abs(tstop))) t_ = tstop;  // round-off of t + h
    return t_;
  }
  check(ERKStepSetStopTime(mem_, tstop), "ERKStepSetStopTime");
  const int flag = ERKStepEvolve(mem_, tstop, y_, &t_, ARK_ONE_STEP);
  if (flag < 0) throw NumericalFailure("ARKODE: ERKStepEvolve failed at t = " + std::to_string(t_) +
                                       " with flag " + std::to_string(flag) + " (" +
                                       flag_name(flag) + "; " + last_message_ + ")");
  return t_;
}

double* ErkIntegrator::state() { return N_VGetArrayPointer(y_); }

void ErkIntegrator::reset(double t) {
  check(ERKStepReset(mem_, t, y_), "ERKStepReset");
  t_ = t;
}

void ErkIntegrator::restart_at(double t, double h) {
  // ERKStepReInit, unlike ERKStepReset, also clears the step-size controller's history and the
  // counters, as in a new integrator; the counters live on in offset_.
  const ErkStats total = stats();
  check(ERKStepReInit(mem_, &ErkIntegrator::rhs_cb, t, y_), "ERKStepReInit");
  t_ = t;
  offset_ = total;
  if (fixed_dt_ > 0) {
    check(ERKStepSetFixedStep(mem_, fixed_dt_), "ERKStepSetFixedStep");
    current_h_ = fixed_dt_;
  } else if (h > 0) {
    check(ERKStepSetInitStep(mem_, h), "ERKStepSetInitStep");
  }
}

double ErkIntegrator::next_step() const {
  double h = 0;
  ERKStepGetCurrentStep(mem_, &h);
  return h;
}

ErkStats ErkIntegrator::stats() const {
  ErkStats s;
  long nst = 0, nacc = 0, natt = 0, nfe = 0, netf = 0;
  ERKStepGetTimestepperStats(mem_, &nacc, &nst, &natt, &nfe, &netf);
  ERKStepGetNumSteps(mem_, &nst);
  s.steps = nst;
  s.rhs_evals = nfe;
  s.attempts = natt;
  s.error_test_fails = netf;
  ERKStepGetLastStep(mem_, &s.last_step);
  s.steps += offset_.steps;  // restart: the counters of the run before
  s.rhs_evals += offset_.rhs_evals;
  s.attempts += offset_.attempts;
  s.error_test_fails += offset_.error_test_fails;
  if (s.last_step == 0) s.last_step = offset_.last_step;
  return s;
}

}  // namespace arksph
