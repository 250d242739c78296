// `arksph study order STUDY.toml`: the observed temporal order of ARKODE tables on one scene.
//
// Each table runs the scene (same particle set) to time.end at a list of fixed steps dt_k. The
// error of each run is the max-norm difference of the whole ODE state (positions, velocities,
// densities) from a reference run of the same particles at a much smaller step, so the spatial
// error cancels and what remains is the time-integration error. The observed order is the
// least-squares slope of log(error) against log(dt); a table is flagged when it misses its nominal
// order by more than the tolerance. Under scheme isph every run projects after each step (as
// `arksph run` does), so the study measures what the projected scheme achieves.
//
//   [study]
//   scene = "../taylor_green/scene.toml"   # relative to the study file
//   set = ["time.end=0.05"]                 # --set values for every run (optional)
//   tables = ["ARKSPH_FORWARD_EULER_1_1", "ARKODE_HEUN_EULER_2_1_2"]
//   imex_pairs = ["ARK324L2SA"]            # ARKStep IMEX pairs, viscous term implicit (time.imex);
//                                           # listed as "imex:ARK324L2SA" (also in [dt_for] and
//                                           # reference_table)
//   dt = [2e-3, 1e-3, 5e-4]                 # fixed steps, every table
//   reference_table = ""                    # "" (default): each table is its own reference
//   reference_dt_divisor = 64               # reference step = smallest dt of the study (of the table
//                                           # when it is its own reference) / divisor
//   tolerance = 0.3                         # flag |observed - nominal| > tolerance
//   reference = "fine_step"                 # "fine_step" (default, above) or "analytic": the error is then
//   analytic_velocity = ["u(x,y,t)", "v(x,y,t)"]  # max_a |u_a - u_exact(r_a, t_end)| over the particles
//                                           # (velocity only; it includes the spatial error, so the observed
//                                           # order holds only while the time error dominates)
//   output = "runs/order_study"             # --out overrides
//
//   [dt_for]                                # optional per-table step lists
//   ARKSPH_FORWARD_EULER_1_1 = [5e-4, 2.5e-4, 1.25e-4]
#pragma once
#include "study/study_args.hpp"
#include <algorithm>
#include <map>
#include <string>
#include <vector>

namespace arksph {

struct OrderStudy {
  std::string source, scene, output;
  std::vector<std::string> sets, tables;
  std::vector<double> dt;
  std::map<std::string, std::vector<double>> dt_for;
  std::string reference_table;
  double reference_dt_divisor = 64;
  double tolerance = 0.3;
  std::string reference = "fine_step";         // or "analytic"
  std::vector<std::string> analytic_velocity;  // u, v expressions of x, y, t (reference = "analytic")
};

struct OrderPoint {
  double dt = 0, error = 0;
  long rhs_evals = 0;
  double velocity_error = 0;  // max-norm over the velocity block only
  double pressure_error = 0;  // max-norm of the pressure of the end state (fine_step reference only)
  double divergence = 0;      // r.m.s. of D u at the end (projection/divergence_operator.hpp)
};

struct OrderFit {
  std::string table;
  int nominal = 0;
  double observed = 0;  // least-squares slope (the whole state: the flag)
  double observed_velocity = 0, observed_pressure = 0;
  bool flagged = false;
  std::vector<OrderPoint> points;
};

// Reads and checks the study (InputError, one line): its keys, its steps (two different ones at
// least, none longer than time.end, each able to advance time within time.max_steps steps), every
// run's scene as `arksph run` reads it, and an analytic reference finite at the particles.
OrderStudy read_order_study(const std::string& path, const std::vector<std::string>& extra_sets);

// Runs the study after the same checks (nothing runs unless every run passes them); `log` true
// prints one line per run on stderr. An error that is NaN (a reference or end state that is not
// finite) stays NaN, and one line on stderr names its cause.
std::vector<OrderFit> run_order_study(const OrderStudy& study, bool log);

// Least-squares slope of log(y) against log(x).
double loglog_slope(const std::vector<double>& x, const std::vector<double>& y);

// arksph study order STUDY.toml [--out DIR] [--set KEY=VALUE ...] [--quiet]: writes
// <out>/order_errors.csv, <out>/order_fit.csv and, with python3 + matplotlib, <out>/order.png.
// Exit 0, or 4 when a table is flagged. The keys: docs/user-guide.md, "Studies".
int cmd_order_study(const StudyArgs& args);

}  // namespace arksph
