#include "integrate/erk_integrator.hpp"

#include <arkode/arkode_butcher_erk.h>
#include <arkode/arkode_erkstep.h>
#include <nvector/nvector_serial.h>

#include <cmath>

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

// The ERKStep functions of ArkodeIntegrator.
const ArkodeStepModule kErkStep = {"ERKStep",
                                   ERKStepSetUserData,
                                   ERKStepSetErrHandlerFn,
                                   ERKStepSetMaxNumSteps,
                                   ERKStepSStolerances,
                                   ERKStepSetFixedStep,
                                   ERKStepSetStabilityFn,
                                   ERKStepSetCFLFraction,
                                   ERKStepSetFixedStepBounds,
                                   ERKStepSetInitStep,
                                   ERKStepSetStopTime,
                                   ERKStepEvolve,
                                   ERKStepReset,
                                   ERKStepResize,
                                   ERKStepGetCurrentStep,
                                   ERKStepGetLastStep,
                                   ERKStepGetReturnFlagName,
                                   ERKStepFree};
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

ErkTable erk_table(const std::string& name) {
  ARKodeButcherTable B = load_table(name);
  if (!B) throw InputError("unknown ERK table '" + echo_value(name) + "' (arksph list names them under erk_table)");
  ErkTable t;
  t.stages = B->stages;
  t.order = B->q;
  t.embedded_order = B->p;
  for (int i = 0; i < B->stages; ++i) {
    t.A.emplace_back(B->A[i], B->A[i] + B->stages);
    t.b.push_back(B->b[i]);
    t.c.push_back(B->c[i]);
    if (B->d) t.d.push_back(B->d[i]);
  }
  ARKodeButcherTable_Free(B);
  return t;
}

ErkIntegrator::ErkIntegrator(RhsFunction f, const std::vector<double>& y0, double t0, const ErkOptions& opt)
    : ArkodeIntegrator(kErkStep, y0, t0, opt), f_(std::move(f)), post_(opt.postprocess), post_stage_(opt.postprocess_stage) {
  adopt(ERKStepCreate(&ErkIntegrator::rhs_cb, t0, y_, ctx_));
  ARKodeButcherTable B = load_table(opt.table);
  if (!B) throw InputError("unknown ARKODE table '" + opt.table + "'");
  const int flag = ERKStepSetTable(mem_, B);
  ARKodeButcherTable_Free(B);
  check(flag, "SetTable");
  if (post_) {
    check(ERKStepSetPostprocessStepFn(mem_,
                                      [](sunrealtype t, N_Vector y, void* user_data) noexcept {
                                        auto& me = self<ErkIntegrator>(user_data);
                                        return me.guarded([&] { me.post_(t, N_VGetArrayPointer(y)); });
                                      }),
          "SetPostprocessStepFn");
    workaround_ = erk_table_has_fsal_bug(opt.table);
  } else if (opt.apply_fsal_workaround && erk_table_has_fsal_bug(opt.table)) {
    check(ERKStepSetPostprocessStepFn(mem_, [](sunrealtype, N_Vector, void*) noexcept { return 0; }), "SetPostprocessStepFn");
    workaround_ = true;
  }
  if (post_stage_) {
    check(ERKStepSetPostprocessStageFn(mem_,
                                       [](sunrealtype t, N_Vector y, void* user_data) noexcept {
                                         auto& me = self<ErkIntegrator>(user_data);
                                         return me.guarded([&] { me.post_stage_(t, N_VGetArrayPointer(y)); });
                                       }),
          "SetPostprocessStageFn");
  }
  apply_step_options(opt, false);
}

int ErkIntegrator::rhs_cb(double t, N_Vector y, N_Vector ydot, void* user_data) noexcept {
  auto& me = self<ErkIntegrator>(user_data);
  return me.evaluate_rhs(me.f_, t, y, ydot);
}

void ErkIntegrator::reinit(double t) { check(ERKStepReInit(mem_, &ErkIntegrator::rhs_cb, t, y_), "ReInit"); }

StepStats ErkIntegrator::module_stats() const {
  StepStats s;
  long nst = 0, nacc = 0, natt = 0, nfe = 0, netf = 0;
  ERKStepGetTimestepperStats(mem_, &nacc, &nst, &natt, &nfe, &netf);
  ERKStepGetNumSteps(mem_, &nst);
  s.steps = nst;
  s.rhs_evals = nfe;
  s.attempts = natt;
  s.error_test_fails = netf;
  return s;
}

}  // namespace arksph
