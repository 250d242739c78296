#include "integrate/imex_integrator.hpp"
#include "integrate/erk_integrator.hpp"
#include "integrate/serial_vector.hpp"

#include <arkode/arkode_arkstep.h>
#include <arkode/arkode_butcher_dirk.h>
#include <arkode/arkode_butcher_erk.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <algorithm>

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

// The ARKStep functions of ArkodeIntegrator.
const ArkodeStepModule kArkStep = {"ARKStep",
                                   ARKStepSetUserData,
                                   ARKStepSetErrHandlerFn,
                                   ARKStepSetMaxNumSteps,
                                   ARKStepSStolerances,
                                   ARKStepSetFixedStep,
                                   ARKStepSetStabilityFn,
                                   ARKStepSetCFLFraction,
                                   ARKStepSetFixedStepBounds,
                                   ARKStepSetInitStep,
                                   ARKStepSetStopTime,
                                   ARKStepEvolve,
                                   ARKStepReset,
                                   ARKStepResize,
                                   ARKStepGetCurrentStep,
                                   ARKStepGetLastStep,
                                   ARKStepGetReturnFlagName,
                                   ARKStepFree};
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
    : ArkodeIntegrator(kArkStep, y0, t0, opt), f_(std::move(f)), opt_(opt), linear_(opt.linear) {
  const PairInfo& pair = pair_info(opt.pair);
  const auto n = static_cast<sunindextype>(size());
  krylov_ = static_cast<bool>(f_.krylov.times);
  if (!krylov_) frozen_ = new_serial_vector(n, ctx_);
  adopt(ARKStepCreate(&ImexIntegrator::fe_cb, &ImexIntegrator::fi_cb, t0, y_, ctx_));
  check(ARKStepSetTableName(mem_, pair.dirk, pair.erk), "SetTableName");
  if (krylov_) {
    attach_krylov();  // imex_krylov.cpp
  } else {
    // Newton matrix: CSR, KLU with AMD ordering; the size grows in the linsys callback.
    A_ = SUNSparseMatrix(n, n, std::max<sunindextype>(n, 1), CSR_MAT, ctx_);
    ls_ = SUNLinSol_KLU(y_, A_, ctx_);
    if (!A_ || !ls_) throw NumericalFailure("SUNDIALS: cannot create the sparse matrix or KLU solver");
    if (SUNLinSol_KLUSetOrdering(ls_, 0) < 0) throw NumericalFailure("SUNDIALS: SUNLinSol_KLUSetOrdering failed");
    check(ARKStepSetLinearSolver(mem_, ls_, A_), "SetLinearSolver");
    check(ARKStepSetLinSysFn(mem_, &ImexIntegrator::linsys_cb), "SetLinSysFn");
  }
  if (opt.linear) check(ARKStepSetLinear(mem_, 1), "SetLinear");  // 1: J changes with the positions
  // The SUNDIALS 6.4.1 FSAL bug of ERKStep (erk_integrator.hpp) does not show here: the IMEX order
  // study (cases/studies/order_imex.toml) measures the same orders, to 4 digits, with and without
  // ERKStep's workaround (a no-op post-processing step function), so none is installed.
  // The tolerances set the error control (adaptive) and, in both modes, the Newton tolerance.
  apply_step_options(opt, true);
}

ImexIntegrator::~ImexIntegrator() {
  free_memory();  // ARKStep first: it refers to the linear solver and the matrix
  if (ls_) SUNLinSolFree(ls_);
  if (A_) SUNMatDestroy(A_);
  if (frozen_) N_VDestroy(frozen_);
  if (diagonal_) N_VDestroy(diagonal_);
}

int ImexIntegrator::fe_cb(double t, N_Vector y, N_Vector ydot, void* user_data) noexcept {
  auto& me = self<ImexIntegrator>(user_data);
  return me.evaluate_rhs(me.f_.explicit_rhs, t, y, ydot);
}

int ImexIntegrator::fi_cb(double t, N_Vector y, N_Vector ydot, void* user_data) noexcept {
  auto& me = self<ImexIntegrator>(user_data);
  return me.evaluate_rhs(me.f_.implicit_rhs, t, y, ydot);
}

int ImexIntegrator::linsys_cb(double t, N_Vector y, N_Vector, SUNMatrix A, SUNMatrix, int jok, int* jcur, double gamma,
                              void* user_data, N_Vector, N_Vector, N_Vector) noexcept {
  auto& me = self<ImexIntegrator>(user_data);
  return me.guarded([&] { return me.newton_matrix(t, y, A, jok, jcur, gamma); });
}

// A = I - gamma J. J is evaluated at the stage's frozen state zpred + sdata: on every row where f_I
// vanishes the stage equation z - gamma f_I(z) = zpred + sdata fixes z exactly.
// Without `linear`, ARKODE's hint jok (J recent enough) is honoured: the last J with the new gamma.
int ImexIntegrator::newton_matrix(double t, N_Vector y, SUNMatrix A, int jok, int* jcur, double gamma) {
  if (!linear_ && jok && last_J_) return fill_newton_matrix(*last_J_, A, gamma, jcur, false);
  double tcur = t, gam = gamma;
  N_Vector zpred = nullptr, z = nullptr, Fi = nullptr, sdata = nullptr;
  void* ud = nullptr;
  const double* frozen = N_VGetArrayPointer(y);
  if (ARKStepGetNonlinearSystemData(mem_, &tcur, &zpred, &z, &Fi, &gam, &sdata, &ud) == ARK_SUCCESS && zpred && sdata) {
    N_VLinearSum(1.0, zpred, 1.0, sdata, frozen_);
    frozen = N_VGetArrayPointer(frozen_);
  }
  const SparseCsr& J = f_.jacobian(t, frozen);
  ++jacobians_;
  last_J_ = &J;
  return fill_newton_matrix(J, A, gamma, jcur, true);
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

void ImexIntegrator::reinit(double t) {
  check(ARKStepReInit(mem_, &ImexIntegrator::fe_cb, &ImexIntegrator::fi_cb, t, y_), "ReInit");
  symbolic_ = jacobians_ = linear_iters_kept_ = 0;
  last_J_ = nullptr;
  have_diagonal_ = false;
}

StepStats ImexIntegrator::module_stats() const {
  StepStats s;
  long nst_stab = 0, nacc = 0, natt = 0, nfe = 0, nfi = 0, nls = 0, netf = 0, nst = 0;
  ARKStepGetTimestepperStats(mem_, &nst_stab, &nacc, &natt, &nfe, &nfi, &nls, &netf);
  ARKStepGetNumSteps(mem_, &nst);
  long niters = 0, nfails = 0;
  ARKStepGetNumNonlinSolvIters(mem_, &niters);
  ARKStepGetNumNonlinSolvConvFails(mem_, &nfails);
  s.steps = nst;
  s.rhs_evals = nfe;
  s.implicit_rhs_evals = nfi;
  s.attempts = natt;
  s.error_test_fails = netf;
  s.linear_setups = nls;
  s.newton_iters = niters;
  s.newton_fails = nfails;
  s.jacobian_evals = jacobians_;
  s.symbolic_analyses = symbolic_;
  long nli = 0;
  ARKStepGetNumLinIters(mem_, &nli);  // 0 with KLU
  s.linear_iters = linear_iters_kept_ + nli;
  return s;
}

}  // namespace arksph
