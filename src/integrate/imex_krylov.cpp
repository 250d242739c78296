// The Krylov solve of ImexIntegrator's stage systems (imex_integrator.hpp): SUNLinSol_SPGMR on
// M = I - gamma J, matrix-free with the caller's J v (ARKStepSetJacTimes), left-preconditioned by
// Jacobi, P = diag(M) = 1 - gamma diag(J) (ARKStepSetPreconditioner). J and its diagonal are
// taken at the stage's frozen state zpred + sdata, as the KLU path takes its J (newton_matrix).
#include <arkode/arkode_arkstep.h>
#include <sunlinsol/sunlinsol_spgmr.h>

#include "core/errors.hpp"
#include "integrate/imex_integrator.hpp"

namespace arksph {

// The solver and its vectors at the state vector's current length (the constructor; after a
// resize, when the old ones have the old length): ARKODE takes the new solver in place of the old.
void ImexIntegrator::attach_krylov() {
  SUNLinearSolver old = ls_;
  if (ls_) {  // its iterations so far (a new solver counts from zero)
    long nli = 0;
    ARKStepGetNumLinIters(mem_, &nli);
    linear_iters_kept_ += nli;
  }
  for (N_Vector* v : {&frozen_, &diagonal_}) {
    if (*v) N_VDestroy(*v);
    *v = N_VClone(y_);
    if (!*v) throw NumericalFailure("SUNDIALS: cannot clone the state vector");
  }
  N_VConst(0.0, diagonal_);
  have_diagonal_ = false;
  ls_ = SUNLinSol_SPGMR(y_, SUN_PREC_LEFT, opt_.krylov_dimension, ctx_);
  if (!ls_) throw NumericalFailure("SUNDIALS: cannot create the SPGMR solver");
  if (SUNLinSol_SPGMRSetMaxRestarts(ls_, opt_.krylov_restarts) != 0)
    throw NumericalFailure("SUNDIALS: SUNLinSol_SPGMRSetMaxRestarts failed");
  check(ARKStepSetLinearSolver(mem_, ls_, nullptr), "SetLinearSolver");
  if (old) SUNLinSolFree(old);
  check(ARKStepSetJacTimes(mem_, &ImexIntegrator::jtimes_setup_cb, &ImexIntegrator::jtimes_cb), "SetJacTimes");
  check(ARKStepSetPreconditioner(mem_, &ImexIntegrator::psetup_cb, &ImexIntegrator::psolve_cb), "SetPreconditioner");
  check(ARKStepSetEpsLin(mem_, opt_.krylov_eps_lin), "SetEpsLin");
}

void ImexIntegrator::resized() {
  if (krylov_) attach_krylov();
}

// The caller's J at the stage's frozen state zpred + sdata (y outside a stage solve).
void ImexIntegrator::freeze(double t, N_Vector y) {
  double tcur = t, gam = 0;
  N_Vector zpred = nullptr, z = nullptr, Fi = nullptr, sdata = nullptr;
  void* ud = nullptr;
  if (ARKStepGetNonlinearSystemData(mem_, &tcur, &zpred, &z, &Fi, &gam, &sdata, &ud) == ARK_SUCCESS && zpred && sdata)
    N_VLinearSum(1.0, zpred, 1.0, sdata, frozen_);
  else
    N_VScale(1.0, y, frozen_);
  f_.krylov.linearize(t, N_VGetArrayPointer(frozen_));
}

int ImexIntegrator::jtimes_setup_cb(double t, N_Vector y, N_Vector, void* user_data) noexcept {
  auto& me = self<ImexIntegrator>(user_data);
  return me.guarded([&] {
    me.freeze(t, y);
    return 0;
  });
}

int ImexIntegrator::jtimes_cb(N_Vector v, N_Vector Jv, double, N_Vector, N_Vector, void* user_data, N_Vector) noexcept {
  auto& me = self<ImexIntegrator>(user_data);
  return me.guarded([&] {
    me.f_.krylov.times(N_VGetArrayPointer(v), N_VGetArrayPointer(Jv));
    return 0;
  });
}

// diag(J) anew unless ARKODE finds the last one recent enough (jok), as the KLU path reuses J.
int ImexIntegrator::psetup_cb(double t, N_Vector y, N_Vector, int jok, int* jcur, double, void* user_data) noexcept {
  auto& me = self<ImexIntegrator>(user_data);
  return me.guarded([&] {
    if (jok && me.have_diagonal_ && !me.linear_) {
      *jcur = 0;
      return 0;
    }
    me.freeze(t, y);
    me.f_.krylov.diagonal(N_VGetArrayPointer(me.diagonal_));
    me.have_diagonal_ = true;
    ++me.jacobians_;
    *jcur = 1;
    return 0;
  });
}

// z = r / (1 - gamma diag(J)), entry by entry on this process's part of the vectors.
int ImexIntegrator::psolve_cb(double, N_Vector, N_Vector, N_Vector r, N_Vector z, double gamma, double, int,
                              void* user_data) noexcept {
  auto& me = self<ImexIntegrator>(user_data);
  const double* d = N_VGetArrayPointer(me.diagonal_);
  const double* rr = N_VGetArrayPointer(r);
  double* zz = N_VGetArrayPointer(z);
  const std::size_t n = me.size();
  for (std::size_t i = 0; i < n; ++i) zz[i] = rr[i] / (1.0 - gamma * d[i]);
  return 0;
}

}  // namespace arksph
