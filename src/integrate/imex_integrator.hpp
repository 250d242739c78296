// SUNDIALS 6.4 ARKStep as an additive (IMEX) Runge-Kutta method: y' = f_E(t, y) + f_I(t, y), f_E
// explicit (ERK table of the pair), f_I implicit (ESDIRK table of the pair). Stepping, restart,
// counters and callback exceptions are those of ArkodeIntegrator (arkode_integrator.hpp). The
// implicit stages z = a + gamma f_I(z) are solved by ARKODE's Newton iteration with SUNLinSol_KLU on
// the sparse Newton matrix M = I - gamma J, J = df_I/dy given by the caller in CSR form.
//
// Built for the viscous term of the run (time.imex, see integrate/viscous_split.hpp): f_I is zero outside
// the velocity block and affine in the velocities once positions and densities are frozen, which
// they are during a stage solve (their f_I rows vanish). J is therefore evaluated at the stage's
// frozen state (ARKStepGetNonlinearSystemData: zpred + sdata on those rows), and with `linear`
// (ARKStepSetLinear, time dependent) one Newton iteration per stage is exact. The KLU symbolic
// analysis is kept while the sparsity pattern of J is unchanged (SUNLinSol_KLUReInit when it changes).
//
// With ImexKrylov (a run over several MPI ranks, whose state vector spans the ranks) the stage
// system is solved matrix-free instead: SUNLinSol_SPGMR on M = I - gamma J with J v given by the
// caller at the stage's frozen state, left-preconditioned by Jacobi, 1 / (1 - gamma diag(J))
// (imex_krylov.cpp).
#pragma once
#include <functional>
#include <string>
#include <vector>

#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>
#include <sundials/sundials_nvector.h>

#include "integrate/arkode_integrator.hpp"
#include "integrate/step_options.hpp"

namespace arksph {

// A square sparse matrix in compressed sparse rows, columns sorted in each row, the diagonal
// present in every row. `pattern_version` changes whenever ptr or idx change.
struct SparseCsr {
  long n = 0;
  std::vector<long> ptr, idx;
  std::vector<double> val;
  long pattern_version = 0;
};

// J = df_I/dy as an operator, for the Krylov solve: `linearize` is called (collectively) at the
// frozen state of a stage before J v or diag(J) are asked for; both are J's at that state.
struct ImexKrylov {
  std::function<void(double t, const double* y)> linearize;
  std::function<void(const double* v, double* Jv)> times;  // Jv = J v (collective)
  std::function<void(double* diagonal)> diagonal;          // diag(J) (collective)
};

struct ImexFunctions {
  RhsFunction explicit_rhs;  // f_E
  RhsFunction implicit_rhs;  // f_I
  // J = df_I/dy at the state y (only its frozen, non-implicit rows matter).
  std::function<const SparseCsr&(double t, const double* y)> jacobian;
  ImexKrylov krylov;  // set: the Krylov solve (jacobian unused); empty: KLU on `jacobian`
};

// The step control (StepOptions::stability: the explicit part's limits), the pair and the Newton mode.
struct ImexOptions : StepOptions {
  std::string pair = "ARK324L2SA";  // ARKODE_<pair>_DIRK_* with ARKODE_<pair>_ERK_*
  bool linear = true;  // f_I linear at frozen positions: ARKStepSetLinear, one Newton iteration per stage
  // The Krylov solve (ImexFunctions::krylov): ARKStepSetEpsLin's factor (the linear residual's
  // bound as a fraction of the Newton tolerance) and SPGMR's Krylov dimension and restarts.
  double krylov_eps_lin = 0.05;
  int krylov_dimension = 30, krylov_restarts = 5;
};

// The ARK pairs of ARKODE 6.4 by short name ("ARK324L2SA", ...), their orders and table names.
std::vector<std::string> imex_pair_names();
int imex_pair_order(const std::string& pair);
std::string imex_pair_dirk_table(const std::string& pair);
std::string imex_pair_erk_table(const std::string& pair);

class ImexIntegrator final : public ArkodeIntegrator {
 public:
  ImexIntegrator(ImexFunctions f, const std::vector<double>& y0, double t0, const ImexOptions& opt);
  ~ImexIntegrator() override;

 private:
  static int fe_cb(double t, N_Vector y, N_Vector ydot, void* user_data) noexcept;
  static int fi_cb(double t, N_Vector y, N_Vector ydot, void* user_data) noexcept;
  static int linsys_cb(double t, N_Vector y, N_Vector fy, SUNMatrix A, SUNMatrix M, int jok, int* jcur,
                       double gamma, void* user_data, N_Vector, N_Vector, N_Vector) noexcept;
  int newton_matrix(double t, N_Vector y, SUNMatrix A, int jok, int* jcur, double gamma);
  int fill_newton_matrix(const SparseCsr& J, SUNMatrix A, double gamma, int* jcur, bool fresh);
  void reinit(double t) override;
  void resized() override;
  StepStats module_stats() const override;
  // The Krylov solve (imex_krylov.cpp).
  void attach_krylov();
  void freeze(double t, N_Vector y);
  static int jtimes_setup_cb(double t, N_Vector y, N_Vector fy, void* user_data) noexcept;
  static int jtimes_cb(N_Vector v, N_Vector Jv, double t, N_Vector y, N_Vector fy, void* user_data, N_Vector) noexcept;
  static int psetup_cb(double t, N_Vector y, N_Vector fy, int jok, int* jcur, double gamma, void* user_data) noexcept;
  static int psolve_cb(double t, N_Vector y, N_Vector fy, N_Vector r, N_Vector z, double gamma, double delta, int lr,
                       void* user_data) noexcept;
  ImexFunctions f_;
  ImexOptions opt_;
  bool krylov_ = false;
  N_Vector diagonal_ = nullptr;  // diag(J) of the last preconditioner set-up
  bool have_diagonal_ = false;
  long linear_iters_kept_ = 0;  // of the solvers replaced since the last reinit
  bool linear_ = true;
  const SparseCsr* last_J_ = nullptr;  // the last J handed over (stays valid: owned by the caller)
  N_Vector frozen_ = nullptr;
  SUNMatrix A_ = nullptr;
  SUNLinearSolver ls_ = nullptr;
  long pattern_version_ = -1, symbolic_ = 0, jacobians_ = 0;
};

}  // namespace arksph
