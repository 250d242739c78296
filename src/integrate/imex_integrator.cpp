#include "integrate/imex_integrator.hpp"
#include "integrate/serial_vector.hpp"

#include <arkode/arkode_arkstep.h>
#include <arkode/arkode_butcher_dirk.h>
#include <arkode/arkode_butcher_erk.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "core/errors.hpp"

namespace arksph {

namespace {
struct PairInfo {
  const char* name;
  const char* dirk;
  const char* erk;
};
// The additive pairs of ARKODE 6.4 (Kennedy & Carpenter 2003, 2019): ESDIRK + ERK with a shared c.
constexpr PairInfo kPairs[] = {
    {"ARK324L2SA", "ARKODE_ARK324L2SA_DIRK_4_2_3", "ARKODE_ARK324L2SA_ERK_4_2_3"},
    {"ARK436L2SA", "ARKODE_ARK436L2SA_DIRK_6_3_4", "ARKODE_ARK436L2SA_ERK_6_3_4"},
    {"ARK437L2SA", "ARKODE_ARK437L2SA_DIRK_7_3_4", "ARKODE_ARK437L2SA_ERK_7_3_4"},
    {"ARK548L2SA", "ARKODE_ARK548L2SA_DIRK_8_4_5", "ARKODE_ARK548L2SA_ERK_8_4_5"},
    {"ARK548L2SAb", "ARKODE_ARK548L2SAb_DIRK_8_4_5", "ARKODE_ARK548L2SAb_ERK_8_4_5"},
};

const PairInfo& pair_info(const std::string& name) {
  for (const auto& p : kPairs)
    if (name == p.name) return p;
  throw InputError("unknown IMEX pair '" + name + "'");
}

std::string flag_name(int flag) {
  char* name = ARKStepGetReturnFlagName(flag);
  std::string out = name ? name : "unknown";
  std::free(name);
  return out;
}

int check(int flag, const char* call) {
  if (flag < 0) throw NumericalFailure(std::string("ARKODE: ") + call + " failed with flag " + std::to_string(flag));
  return flag;
}
}  // namespace

std::vector<std::string> imex_pair_names() {
  std::vector<std::string> n;
  for (const auto& p : kPairs) n.emplace_back(p.name);
  return n;
}

int imex_pair_order(const std::string& pair) { return erk_table_order(pair_info(pair).erk); }
std::string imex_pair_dirk_table(const std::string& pair) { return pair_info(pair).dirk; }
std::string imex_pair_erk_table(const std::string& pair) { return pair_info(pair).erk; }

ImexIntegrator::ImexIntegrator(ImexFunctions f, const std::vector<double>& y0, double t0, const ImexOptions& opt)
    : f_(std::move(f)), stab_(opt.stability), linear_(opt.linear), n_(y0.size()), t_(t0), fixed_dt_(opt.fixed_dt), current_h_(opt.fixed_dt) {
  const PairInfo& pair = pair_info(opt.pair);
  check(SUNContext_Create(nullptr, &ctx_), "SUNContext_Create");
  const auto n = static_cast<sunindextype>(n_);
  y_ = new_serial_vector(n, ctx_);
  frozen_ = new_serial_vector(n, ctx_);
  std::copy(y0.begin(), y0.end(), N_VGetArrayPointer(y_));
  mem_ = ARKStepCreate(&ImexIntegrator::fe_cb, &ImexIntegrator::fi_cb, t0, y_, ctx_);
  if (!mem_) throw NumericalFailure("ARKODE: ARKStepCreate failed");
  check(ARKStepSetUserData(mem_, this), "ARKStepSetUserData");
  check(ARKStepSetErrHandlerFn(
            mem_,
            [](int, const char*, const char* function, char* msg, void* self) {
              std::string m = std::string(function) + ": " + msg;
              std::replace(m.begin(), m.end(), '\n', ' ');
              static_cast<ImexIntegrator*>(self)->last_message_ = m;
            },
            this),
        "ARKStepSetErrHandlerFn");
  check(ARKStepSetTableName(mem_, pair.dirk, pair.erk), "ARKStepSetTableName");
  // Newton matrix: CSR, KLU with AMD ordering (faster than the default COLAMD); the size grows in the linsys callback.
  A_ = SUNSparseMatrix(n, n, std::max<sunindextype>(n, 1), CSR_MAT, ctx_);
  ls_ = SUNLinSol_KLU(y_, A_, ctx_);
  if (!A_ || !ls_) throw NumericalFailure("SUNDIALS: cannot create the sparse matrix or KLU solver");
  check(SUNLinSol_KLUSetOrdering(ls_, 0), "SUNLinSol_KLUSetOrdering");
  check(ARKStepSetLinearSolver(mem_, ls_, A_), "ARKStepSetLinearSolver");
  check(ARKStepSetLinSysFn(mem_, &ImexIntegrator::linsys_cb), "ARKStepSetLinSysFn");
  if (opt.linear) check(ARKStepSetLinear(mem_, 1), "ARKStepSetLinear");  // 1: J changes with the positions
  // The SUNDIALS 6.4.1 FSAL bug of ERKStep (erk_integrator.hpp) does not show here: the IMEX order
  // study (cases/studies/order_imex.toml) measures the same orders, to 4 digits, with and without
  // ERKStep's workaround (a no-op post-processing step function), so none is installed.
  check(ARKStepSetMaxNumSteps(mem_, opt.max_steps), "ARKStepSetMaxNumSteps");
  // The tolerances set the error control (adaptive) and, in both modes, the Newton tolerance.
  check(ARKStepSStolerances(mem_, opt.rtol, opt.atol), "ARKStepSStolerances");
  if (opt.fixed_dt > 0) {
    check(ARKStepSetFixedStep(mem_, opt.fixed_dt), "ARKStepSetFixedStep");
  } else {
    if (stab_) {
      check(ARKStepSetStabilityFn(mem_, &ImexIntegrator::stab_cb, this), "ARKStepSetStabilityFn");
      check(ARKStepSetCFLFraction(mem_, 0.99), "ARKStepSetCFLFraction");  // as ErkIntegrator
      check(ARKStepSetFixedStepBounds(mem_, 1.0, 1.0), "ARKStepSetFixedStepBounds");
    }
    if (opt.initial_dt > 0) check(ARKStepSetInitStep(mem_, opt.initial_dt), "ARKStepSetInitStep");
  }
}

ImexIntegrator::~ImexIntegrator() {
  if (mem_) ARKStepFree(&mem_);
  if (ls_) SUNLinSolFree(ls_);
  if (A_) SUNMatDestroy(A_);
  if (frozen_) N_VDestroy(frozen_);
  if (y_) N_VDestroy(y_);
  if (ctx_) SUNContext_Free(&ctx_);
}

int ImexIntegrator::evaluate(const RhsFunction& f, double t, N_Vector y, N_Vector ydot) {
  f(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot));
  const double* d = N_VGetArrayPointer(ydot);
  for (std::size_t i = 0; i < n_; ++i)
    if (!std::isfinite(d[i])) return 1;  // recoverable: ARKODE retries with a smaller step
  return 0;
}

int ImexIntegrator::fe_cb(double t, N_Vector y, N_Vector ydot, void* self) {
  auto* me = static_cast<ImexIntegrator*>(self);
  return me->evaluate(me->f_.explicit_rhs, t, y, ydot);
}

int ImexIntegrator::fi_cb(double t, N_Vector y, N_Vector ydot, void* self) {
  auto* me = static_cast<ImexIntegrator*>(self);
  return me->evaluate(me->f_.implicit_rhs, t, y, ydot);
}

int ImexIntegrator::stab_cb(N_Vector y, double t, double* hstab, void* self) {
  auto* me = static_cast<ImexIntegrator*>(self);
  *hstab = me->stab_(t, N_VGetArrayPointer(y)) / 0.99;
  return 0;
}

// A = I - gamma J. J is evaluated at the stage's frozen state zpred + sdata: on every row where f_I
// vanishes the stage equation z - gamma f_I(z) = zpred + sdata fixes z exactly.
// Without `linear`, ARKODE's hint jok (J recent enough) is honoured: the last J with the new gamma.
int ImexIntegrator::linsys_cb(double t, N_Vector y, N_Vector, SUNMatrix A, SUNMatrix, int jok, int* jcur, double gamma,
                              void* self, N_Vector, N_Vector, N_Vector) {
  auto* me = static_cast<ImexIntegrator*>(self);
  if (!me->linear_ && jok && me->last_J_) return me->fill_newton_matrix(*me->last_J_, A, gamma, jcur, false);
  double tcur = t, gam = gamma;
  N_Vector zpred = nullptr, z = nullptr, Fi = nullptr, sdata = nullptr;
  void* ud = nullptr;
  const double* frozen = N_VGetArrayPointer(y);
  if (ARKStepGetNonlinearSystemData(me->mem_, &tcur, &zpred, &z, &Fi, &gam, &sdata, &ud) == ARK_SUCCESS && zpred &&
      sdata) {
    N_VLinearSum(1.0, zpred, 1.0, sdata, me->frozen_);
    frozen = N_VGetArrayPointer(me->frozen_);
  }
  const SparseCsr* J = nullptr;
  try {
    J = &me->f_.jacobian(t, frozen);
  } catch (const std::exception& e) {
    me->last_message_ = e.what();
    return -1;
  }
  ++me->jacobians_;
  me->last_J_ = J;
  return me->fill_newton_matrix(*J, A, gamma, jcur, true);
}

int ImexIntegrator::fill_newton_matrix(const SparseCsr& Jr, SUNMatrix A, double gamma, int* jcur, bool fresh) {
  ImexIntegrator* me = this;
  const SparseCsr* J = &Jr;
  const auto nnz = static_cast<sunindextype>(J->ptr.back());
  if (J->pattern_version != me->pattern_version_) {
    if (SM_NNZ_S(A) < nnz && SUNSparseMatrix_Reallocate(A, nnz) != 0) return -1;
  }
  sunindextype* ptr = SM_INDEXPTRS_S(A);
  sunindextype* idx = SM_INDEXVALS_S(A);
  double* val = SM_DATA_S(A);
  for (long r = 0; r <= J->n; ++r) ptr[r] = static_cast<sunindextype>(J->ptr[r]);
  for (long r = 0; r < J->n; ++r)
    for (long k = J->ptr[r]; k < J->ptr[r + 1]; ++k) {
      idx[k] = static_cast<sunindextype>(J->idx[k]);
      val[k] = (J->idx[k] == r ? 1.0 : 0.0) - gamma * J->val[k];
    }
  if (J->pattern_version != me->pattern_version_) {  // new pattern: new symbolic analysis at the next setup
    if (me->pattern_version_ >= 0 && SUNLinSol_KLUReInit(me->ls_, A, nnz, SUNKLU_REINIT_PARTIAL) != 0) return -1;
    me->pattern_version_ = J->pattern_version;
    ++me->symbolic_;
  }
  *jcur = fresh ? 1 : 0;
  return 0;
}

void ImexIntegrator::fail_if(int flag, const char* call) const {
  if (flag < 0)
    throw NumericalFailure(std::string("ARKODE: ") + call + " failed at t = " + std::to_string(t_) + " with flag " +
                           std::to_string(flag) + " (" + flag_name(flag) + "; " + last_message_ + ")");
}

double ImexIntegrator::evolve_to(double tout) {
  if (fixed_dt_ > 0) {
    while (t_ < tout) step(tout);
    return t_;
  }
  check(ARKStepSetStopTime(mem_, tout), "ARKStepSetStopTime");
  fail_if(ARKStepEvolve(mem_, tout, y_, &t_, ARK_NORMAL), "ARKStepEvolve");
  return t_;
}

double ImexIntegrator::step(double tstop) {
  if (fixed_dt_ > 0) {  // as ErkIntegrator::step: the last step is shortened to land on tstop
    const double remaining = tstop - t_;
    const double h = remaining <= fixed_dt_ * (1 + 1e-10) ? remaining : fixed_dt_;
    if (h != current_h_) {
      check(ARKStepSetFixedStep(mem_, h), "ARKStepSetFixedStep");
      current_h_ = h;
    }
    fail_if(ARKStepEvolve(mem_, tstop, y_, &t_, ARK_ONE_STEP), "ARKStepEvolve");
    if (std::abs(tstop - t_) <= 1e-12 * std::max(1.0, std::abs(tstop))) t_ = tstop;
    return t_;
  }
  check(ARKStepSetStopTime(mem_, tstop), "ARKStepSetStopTime");
  fail_if(ARKStepEvolve(mem_, tstop, y_, &t_, ARK_ONE_STEP), "ARKStepEvolve");
  return t_;
}

double* ImexIntegrator::state() { return N_VGetArrayPointer(y_); }

void ImexIntegrator::reset(double t) {
  check(ARKStepReset(mem_, t, y_), "ARKStepReset");
  t_ = t;
}

void ImexIntegrator::restart_at(double t, double h) {
  const ErkStats total = stats();
  check(ARKStepReInit(mem_, &ImexIntegrator::fe_cb, &ImexIntegrator::fi_cb, t, y_), "ARKStepReInit");
  t_ = t;
  offset_ = total;
  symbolic_ = jacobians_ = 0;
  last_J_ = nullptr;
  if (fixed_dt_ > 0) {
    check(ARKStepSetFixedStep(mem_, fixed_dt_), "ARKStepSetFixedStep");
    current_h_ = fixed_dt_;
  } else if (h > 0) {
    check(ARKStepSetInitStep(mem_, h), "ARKStepSetInitStep");
  }
}

double ImexIntegrator::next_step() const {
  double h = 0;
  ARKStepGetCurrentStep(mem_, &h);
  return h;
}

ErkStats ImexIntegrator::stats() const {
  ErkStats s;
  long nst_stab = 0, nacc = 0, natt = 0, nfe = 0, nfi = 0, nls = 0, netf = 0, nst = 0;
  ARKStepGetTimestepperStats(mem_, &nst_stab, &nacc, &natt, &nfe, &nfi, &nls, &netf);
  ARKStepGetNumSteps(mem_, &nst);
  long niters = 0, nfails = 0;
  ARKStepGetNumNonlinSolvIters(mem_, &niters);
  ARKStepGetNumNonlinSolvConvFails(mem_, &nfails);
  s.steps = nst + offset_.steps;
  s.rhs_evals = nfe + offset_.rhs_evals;
  s.implicit_rhs_evals = nfi + offset_.implicit_rhs_evals;
  s.attempts = natt + offset_.attempts;
  s.error_test_fails = netf + offset_.error_test_fails;
  s.linear_setups = nls + offset_.linear_setups;
  s.newton_iters = niters + offset_.newton_iters;
  s.newton_fails = nfails + offset_.newton_fails;
  s.jacobian_evals = jacobians_ + offset_.jacobian_evals;
  s.symbolic_analyses = symbolic_ + offset_.symbolic_analyses;
  ARKStepGetLastStep(mem_, &s.last_step);
  if (s.last_step == 0) s.last_step = offset_.last_step;
  return s;
}

}  // namespace arksph
