#include "projection/correction/correction_kinsol.hpp"
#include "integrate/callback_guard.hpp"
#include "integrate/serial_vector.hpp"

#include <kinsol/kinsol.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <cmath>
#include <exception>
#include <memory>
#include <numeric>
#include <string>

#include "core/errors.hpp"
#include "kernels/kernel.hpp"
#include "projection/correction/correction_newton.hpp"
#include "projection/correction/correction_solver.hpp"
#include "projection/ppe_assembly.hpp"

namespace arksph {

namespace {
struct Problem {
  ParticleDomain* domain;
  double t;
  std::vector<double> y_tilde;  // state at r~ (positions to shift)
  std::vector<double> y_work;
  SparseMatrix A;               // pinned, scaled Laplacian at r~
  SparseMatrix Gx, Gy;          // difference-form gradient at r~ (ghosts map to their source)
  std::vector<double> volume, rho0;
  std::exception_ptr error;     // thrown in a KINSOL callback, rethrown after KINSol
};

// s_a - mean s at the positions shifted by p.
void residual(Problem& P, const double* p, double* F) {
  const StateLayout L = P.domain->layout();
  const std::size_t n = L.n;
  const Eigen::Map<const Eigen::VectorXd> pv(p, static_cast<long>(n));
  const Eigen::VectorXd gx = P.Gx * pv, gy = P.Gy * pv;
  P.y_work = P.y_tilde;
  for (std::size_t a = 0; a < n; ++a) {
    P.y_work[L.pos(0) + a] -= gx(static_cast<long>(a)) / P.rho0[a];
    if (L.dim == 2) P.y_work[L.pos(1) + a] -= gy(static_cast<long>(a)) / P.rho0[a];
  }
  P.domain->refresh(P.t, P.y_work.data());
  const FluidFields& f = P.domain->fields();
  const double w0 = f.kernel->W(0.0);
  std::vector<double> s(n);
  for (std::size_t a = 0; a < n; ++a) {
    double d = w0;
    f.pairs.for_pairs(a, [&](std::uint32_t, double, double, double, double w, double) { d += w; });
    s[a] = 1.0 - f.m[a] * d / P.rho0[a];
  }
  const double mean = std::accumulate(s.begin(), s.end(), 0.0) / static_cast<double>(n);
  for (std::size_t a = 0; a < n; ++a) F[a] = -P.volume[a] * (s[a] - mean);
  F[0] = -p[0];
}

int kin_residual(N_Vector u, N_Vector fval, void* data) noexcept {
  Problem& P = *static_cast<Problem*>(data);
  return guarded_callback(P.error, [&] { residual(P, N_VGetArrayPointer(u), N_VGetArrayPointer(fval)); });
}

// J = -A in CSR (A is symmetric, so its CSC arrays are the CSR arrays of A^T = A).
int kin_jacobian(N_Vector, N_Vector, SUNMatrix J, void* data, N_Vector, N_Vector) noexcept {
  Problem& P = *static_cast<Problem*>(data);
  return guarded_callback(P.error, [&] {
    const SparseMatrix& A = P.A;
    sunindextype* ptr = SM_INDEXPTRS_S(J);
    sunindextype* idx = SM_INDEXVALS_S(J);
    sunrealtype* val = SM_DATA_S(J);
    for (long j = 0; j <= A.outerSize(); ++j) ptr[j] = A.outerIndexPtr()[j];
    for (long k = 0; k < A.nonZeros(); ++k) {
      idx[k] = A.innerIndexPtr()[k];
      val[k] = -A.valuePtr()[k];
    }
  });
}
}  // namespace

KinsolCorrectionResult correct_density_kinsol(ParticleDomain& domain, double t, double* y, int max_iterations,
                                              double ftol) {
  const StateLayout L = domain.layout();
  const std::size_t n = L.n;
  Problem P;
  P.domain = &domain;
  P.t = t;
  P.y_tilde.assign(y, y + L.size());
  domain.refresh(t, y);
  const FluidFields& f = domain.fields();
  P.A = assemble_ppe(f, std::vector<double>(n, 0.0), 1.0).A;
  P.volume.resize(n);
  P.rho0 = f.rho0;
  std::vector<Eigen::Triplet<double, int>> tx, ty;
  for (std::size_t a = 0; a < n; ++a) {
    P.volume[a] = f.m[a] / f.rho[a];
    f.pairs.for_pairs(a, [&](std::uint32_t b, double rx, double ry, double, double, double F) {
      const double c = f.m[b] / f.rho[b] * F;  // V_b (p_src(b) - p_a) grad_a W_ab
      const int ia = static_cast<int>(a), ib = static_cast<int>(f.src[b]);
      tx.emplace_back(ia, ib, c * rx);
      tx.emplace_back(ia, ia, -c * rx);
      ty.emplace_back(ia, ib, c * ry);
      ty.emplace_back(ia, ia, -c * ry);
    });
  }
  P.Gx.resize(static_cast<long>(n), static_cast<long>(n));
  P.Gy.resize(static_cast<long>(n), static_cast<long>(n));
  P.Gx.setFromTriplets(tx.begin(), tx.end());
  P.Gy.setFromTriplets(ty.begin(), ty.end());

  SUNContext ctx = nullptr;
  SUNContext_Create(nullptr, &ctx);
  N_Vector u = new_serial_vector(static_cast<sunindextype>(n), ctx);
  N_Vector scale = new_serial_vector(static_cast<sunindextype>(n), ctx);
  N_VConst(0.0, u);
  N_VConst(1.0, scale);
  SUNMatrix J = SUNSparseMatrix(static_cast<sunindextype>(n), static_cast<sunindextype>(n), P.A.nonZeros(), CSR_MAT, ctx);
  SUNLinearSolver LS = SUNLinSol_KLU(u, J, ctx);
  void* kin = KINCreate(ctx);
  KinsolCorrectionResult res;
  auto cleanup = [&] {
    KINFree(&kin);
    SUNLinSolFree(LS);
    SUNMatDestroy(J);
    N_VDestroy(u);
    N_VDestroy(scale);
    SUNContext_Free(&ctx);
  };
  KINInit(kin, kin_residual, u);
  KINSetUserData(kin, &P);
  KINSetLinearSolver(kin, LS, J);
  KINSetJacFn(kin, kin_jacobian);
  KINSetMaxSetupCalls(kin, 0);  // 0: KINSOL default (10); the Jacobian is frozen anyway
  KINSetNumMaxIters(kin, max_iterations);
  KINSetFuncNormTol(kin, ftol);
  KINSetMaxNewtonStep(kin, 1e6);
  KINSetPrintLevel(kin, 0);
  KINSetErrHandlerFn(kin, [](int, const char*, const char*, char*, void*) noexcept {}, nullptr);
  res.flag = KINSol(kin, u, KIN_NONE, scale, scale);
  if (P.error) {  // a callback threw: its exception, not KINSOL's flag for it
    cleanup();
    rethrow_callback_error(P.error);
  }
  long nni = 0, nfe = 0;
  KINGetNumNonlinSolvIters(kin, &nni);
  KINGetNumFuncEvals(kin, &nfe);
  res.iterations = nni;
  res.function_evals = nfe;
  // Apply the final p*: positions r~ - G p / rho0 (also when KINSOL stopped at its iteration cap).
  residual(P, N_VGetArrayPointer(u), std::vector<double>(n).data());
  std::copy(P.y_work.begin(), P.y_work.end(), y);
  cleanup();
  if (res.flag < 0 && res.flag != KIN_MAXITER_REACHED && res.flag != KIN_LINESEARCH_NONCONV)
    throw NumericalFailure("KINSOL density correction failed with flag " + std::to_string(res.flag));
  return res;
}

}  // namespace arksph

namespace arksph {

namespace {
// method.correction_solver = "kinsol": correct_density_kinsol with KINSOL's tolerance on max |F| at a
// tenth of the threshold times the mean particle volume (F ~ V x relative density fluctuation).
class KinsolCorrection : public CorrectionSolver {
 public:
  KinsolCorrection(const Scene& scene, ParticleDomain& domain)
      : domain_(domain), threshold_(scene.correction_threshold), max_iterations_(scene.correction_max_iterations) {}
  CorrectionOutcome correct(double t, double* y, std::vector<double>& s, double, std::vector<double>*) override {
    const FluidFields& f = domain_.fields();
    const std::size_t n = domain_.layout().n;
    double volume = 0;
    for (std::size_t a = 0; a < n; ++a) volume += f.m[a] / f.rho[a];
    volume /= static_cast<double>(n);
    const KinsolCorrectionResult r = correct_density_kinsol(domain_, t, y, max_iterations_, 0.1 * threshold_ * volume);
    domain_.refresh(t, y);
    return {density_fluctuation(domain_.fields(), domain_.correction_span(), s), r.iterations};
  }

 private:
  ParticleDomain& domain_;
  double threshold_;
  int max_iterations_;
};
}  // namespace

std::unique_ptr<CorrectionSolver> make_correction_kinsol(const Scene& scene, ParticleDomain& domain) {
  return std::make_unique<KinsolCorrection>(scene, domain);
}

}  // namespace arksph
