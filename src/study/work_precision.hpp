// `arksph study work-precision STUDY.toml`: error against wall time for schemes x resolutions.
//
// Every (scheme, resolution) pair is one run of the scene, executed by the batch runner
// (study/batch.hpp: child processes, one folder each, resumable), with the --set values
// study.set, then the resolution's set, then the scheme's set. Work is the run's wall time
// (summary.json); the error is measured at time.end against one of three references:
//   analytic  the velocity field given by study.analytic_velocity (expressions of x, y, t), at the
//             particles of the run's final checkpoint: L1, L2, Linf of |u - u_exact| (reference_error.hpp);
//   run       a reference run (study.set, then study.reference_set; e.g. a finer lattice), its
//             velocities interpolated onto the run's particles with its own kernel and h
//             (Shepard-normalised, C&R 1999 §3.4); no periodic images, so use analytic for periodic scenes;
//   ghia      the run's own Ghia comparison (scene [metrics] ghia_re): L1 is the mean of the u and v
//             centreline r.m.s. errors, L2 their r.m.s., Linf the larger L-infinity error.
// For each scheme, the curve (resolutions in the file's order) is interpolated log-log to find the
// wall time at which it reaches study.target_error; the command prints which scheme gets there soonest.
//
//   [study]
//   scene = "../spin_down/scene.toml"  # relative to the study file
//   set = ["time.end=0.5"]              # every run (optional)
//   output = "runs/wp"                  # --out overrides
//   jobs = 1                            # runs at a time (default 1: wall times are the measurement)
//   reference = "analytic"              # analytic | run | ghia
//   analytic_velocity = ["u(x,y,t)", "v(x,y,t)"]  # reference = "analytic"
//   reference_set = ["fluid.spacing=0.005"]       # reference = "run"
//   target_error = 1e-3                 # L2 level of the "soonest" line (default: geometric mean of the errors)
//   title = "spin-down, Re = 420"       # of the plot (default: the study file's name)
//
//   [[scheme]]                          # one or more
//   name = "isph+pw"
//   set = ["method.density_correction=pozorski_wawrenczuk"]
//
//   [[resolution]]                      # two or more
//   name = "27^2"                       # optional (default: r<index>)
//   set = ["fluid.spacing=0.037037037037037035", "time.dt=0.0714"]
//
// Output: <out>/work_precision.csv (scheme, resolution, particles, wall_seconds, steps, rhs_evals,
// error_l1, error_l2, error_linf, status, run), the runs' folders and batch.csv, and with
// /usr/bin/python3 + matplotlib <out>/work_precision.png (scripts/plot_work_precision.py).
// Exit 0; 3 when the reference run failed or no run finished with a finite error; 2 for a bad study
// file or a folder in use; 5 when the output cannot be written. The keys: docs/user-guide.md, "Studies".
#pragma once
#include "study/study_args.hpp"
#include <string>
#include <vector>

namespace arksph {

struct WorkPrecisionStudy {
  struct Entry {
    std::string name;
    std::vector<std::string> sets;
  };
  std::string source, scene, output, reference, title;
  std::vector<std::string> sets, reference_sets;
  std::vector<std::string> analytic_velocity;  // u, v
  std::vector<Entry> schemes, resolutions;
  double target_error = 0;  // 0: automatic
  int jobs = 1;
};

struct WorkPrecisionPoint {
  std::string scheme, resolution, status, run;
  long particles = 0, steps = 0, rhs_evals = 0;
  double wall_seconds = 0, l1 = 0, l2 = 0, linf = 0;  // errors NaN when the run did not finish
};

// Throws InputError "<file>: <key>: <reason>" (one line); checks every run's scene before anything runs.
WorkPrecisionStudy read_work_precision_study(const std::string& path, const std::vector<std::string>& extra_sets);

// Wall time at which a curve (points in resolution order) first reaches `target` (log-log
// interpolation between the two runs around it; the first run's time when it is already below);
// negative when the curve never reaches it.
double time_to_error(const std::vector<WorkPrecisionPoint>& curve, double target);

// arksph study work-precision STUDY.toml [--out DIR] [--jobs N] [--set KEY=VALUE ...] [--quiet]
int cmd_work_precision_study(const StudyArgs& args);

}  // namespace arksph
