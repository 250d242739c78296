// The work-precision study (see work_precision.hpp).
#include "study/work_precision.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

#include "core/errors.hpp"
#include "io/checkpoint.hpp"
#include "io/scene_reader.hpp"
#include "run/output_folder.hpp"
#include "study/batch.hpp"
#include "study/plot_command.hpp"
#include "study/reference_error.hpp"
#include "study/study_file.hpp"

namespace fs = std::filesystem;

namespace arksph {

namespace {
const double kNaN = std::numeric_limits<double>::quiet_NaN();


std::string folder_name(const std::string& s) {
  std::string out = s;
  for (char& c : out)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-')) c = '_';
  return out;
}

std::vector<std::string> strings(const toml::node& v, const std::string& where) {
  const toml::array* a = v.as_array();
  if (!a) throw InputError(where + ": expected an array of strings");
  std::vector<std::string> out;
  for (const auto& e : *a) {
    if (!e.is_string()) throw InputError(where + ": expected an array of strings");
    out.push_back(e.as_string()->get());
  }
  return out;
}

// [[scheme]] or [[resolution]]: an array of tables with name (optional) and set.
std::vector<WorkPrecisionStudy::Entry> entries(const toml::node* node, const std::string& path, const std::string& what) {
  std::vector<WorkPrecisionStudy::Entry> out;
  if (!node) return out;
  const toml::array* a = node->as_array();
  if (!a) throw InputError(path + ": " + what + ": expected [[" + what + "]] tables");
  for (std::size_t i = 0; i < a->size(); ++i) {
    const toml::table* t = (*a)[i].as_table();
    const std::string where = path + ": " + what + "[" + std::to_string(i) + "]";
    if (!t) throw InputError(where + ": expected a table");
    WorkPrecisionStudy::Entry e;
    e.name = (what == "scheme" ? "s" : "r") + std::to_string(i);
    for (const auto& [k, v] : *t) {
      const std::string key(k.str());
      if (key == "name") {
        if (!v.is_string() || v.as_string()->get().empty()) throw InputError(where + ".name: expected a non-empty string");
        e.name = v.as_string()->get();
      } else if (key == "set") {
        e.sets = strings(v, where + ".set");
      } else {
        throw InputError(where + "." + key + ": unknown key (expected name, set)");
      }
    }
    for (const auto& o : out)
      if (folder_name(o.name) == folder_name(e.name)) throw InputError(where + ".name: '" + e.name + "' repeats a name");
    out.push_back(e);
  }
  return out;
}

std::vector<std::string> run_sets(const WorkPrecisionStudy& s, const WorkPrecisionStudy::Entry& scheme,
                                  const WorkPrecisionStudy::Entry& res) {
  std::vector<std::string> sets = s.sets;
  sets.insert(sets.end(), res.sets.begin(), res.sets.end());
  sets.insert(sets.end(), scheme.sets.begin(), scheme.sets.end());
  return sets;
}

std::vector<std::string> reference_run_sets(const WorkPrecisionStudy& s) {
  std::vector<std::string> sets = s.sets;
  sets.insert(sets.end(), s.reference_sets.begin(), s.reference_sets.end());
  return sets;
}

double metric(const BatchRunResult& r, const std::string& name) {
  for (const auto& [k, v] : r.metrics)
    if (k == name) return std::strtod(v.c_str(), nullptr);
  return kNaN;
}

ParticleVelocities final_velocities(const std::string& dir, double* time, long* particles) {
  const Checkpoint c = read_checkpoint((fs::path(dir) / "checkpoint.h5").string());
  if (time) *time = c.time;
  if (particles) *particles = static_cast<long>(c.n);
  return velocities_of(c.layout(), c.state.data(), c.mass, c.rho0);
}
}  // namespace

WorkPrecisionStudy read_work_precision_study(const std::string& path, const std::vector<std::string>& extra_sets) {
  const toml::table root = read_study_toml(path);
  const auto bad = [&](const std::string& key, const std::string& why) { return InputError(path + ": " + echo_value(key) + ": " + why); };
  for (const auto& [k, v] : root) {
    const std::string key(k.str());
    if (key != "study" && key != "scheme" && key != "resolution")
      throw bad(key, "unknown key (expected [study], [[scheme]], [[resolution]])");
  }
  const toml::table* st = root["study"].as_table();
  if (!st) throw bad("study", "missing table [study]");
  WorkPrecisionStudy s;
  s.source = path;
  for (const auto& [k, v] : *st) {
    const std::string name(k.str()), key = "study." + name;
    if (name == "scene" || name == "output" || name == "reference" || name == "title") {
      if (!v.is_string()) throw bad(key, "expected a string");
      (name == "scene" ? s.scene : name == "output" ? s.output : name == "title" ? s.title : s.reference) =
          v.as_string()->get();
    } else if (name == "set" || name == "reference_set" || name == "analytic_velocity") {
      (name == "set" ? s.sets : name == "reference_set" ? s.reference_sets : s.analytic_velocity) =
          strings(v, path + ": " + key);
    } else if (name == "target_error") {
      const auto x = v.value<double>();
      if (!x || !(*x > 0)) throw bad(key, "expected a positive number");
      s.target_error = *x;
    } else if (name == "jobs") {
      const auto n = v.value<int64_t>();
      if (!n || *n < 1 || *n > 256) throw bad(key, "expected an integer in [1, 256]");
      s.jobs = static_cast<int>(*n);
    } else {
      throw bad(key, "unknown key");
    }
  }
  if (s.scene.empty()) throw bad("study.scene", "missing (the scene file)");
  if (fs::path(s.scene).is_relative()) s.scene = (fs::path(path).parent_path() / s.scene).lexically_normal().string();
  if (!fs::is_regular_file(s.scene))
    throw bad("study.scene", s.scene + (fs::is_directory(s.scene) ? ": is a directory, not a scene file"
                                        : fs::exists(s.scene)     ? ": not a regular file"
                                                                  : ": no such file"));
  if (s.reference != "analytic" && s.reference != "run" && s.reference != "ghia")
    throw bad("study.reference", "'" + s.reference + "': expected analytic, run or ghia");
  if (s.reference == "analytic") {
    check_analytic_velocity(path, s.analytic_velocity);
  } else if (!s.analytic_velocity.empty()) {
    throw bad("study.analytic_velocity", "only with reference = \"analytic\"");
  }
  if (s.reference == "run" && s.reference_sets.empty())
    throw bad("study.reference_set", "missing (the --set values of the reference run, e.g. a finer fluid.spacing)");
  if (s.reference != "run" && !s.reference_sets.empty()) throw bad("study.reference_set", "only with reference = \"run\"");
  s.schemes = entries(root.get("scheme"), path, "scheme");
  s.resolutions = entries(root.get("resolution"), path, "resolution");
  if (s.schemes.empty()) throw bad("scheme", "missing (one or more [[scheme]] tables)");
  if (s.resolutions.size() < 2) throw bad("resolution", "at least two [[resolution]] tables are needed for a curve");
  s.sets.insert(s.sets.end(), extra_sets.begin(), extra_sets.end());
  if (s.output.empty()) s.output = "runs/" + fs::path(path).stem().string();
  // Every run's scene must read, and an analytic reference be finite at its particles (exit 2 before
  // anything runs).
  const std::string scene_text = read_text_file(s.scene);
  std::ostringstream warnings;
  for (const auto& res : s.resolutions)
    for (const auto& sch : s.schemes) {
      const std::string run = "scheme " + sch.name + ", resolution " + res.name;
      const Scene scene = [&] {
        try {
          return read_scene_text(scene_text, s.scene, run_sets(s, sch, res), warnings);
        } catch (const InputError& e) {
          throw InputError(path + ": " + run + ": " + e.what());
        }
      }();
      if (s.reference == "ghia" && scene.ghia_re == 0)
        throw bad("study.reference", "ghia needs a scene with [metrics] ghia_re (" + run + ")");
      if (s.reference == "analytic") check_analytic_velocity_finite(path, s.analytic_velocity, scene, run);
    }
  if (s.reference == "run") {
    try {
      read_scene_text(scene_text, s.scene, reference_run_sets(s), warnings);
    } catch (const InputError& e) {
      throw InputError(path + ": reference run: " + e.what());
    }
  }
  return s;
}

double time_to_error(const std::vector<WorkPrecisionPoint>& curve, double target) {
  std::vector<const WorkPrecisionPoint*> ok;
  for (const auto& p : curve)
    if (p.status == "ok" && p.l2 > 0 && p.wall_seconds > 0) ok.push_back(&p);
  if (ok.empty()) return -1;
  if (ok.front()->l2 <= target) return ok.front()->wall_seconds;
  for (std::size_t k = 1; k < ok.size(); ++k) {
    const WorkPrecisionPoint &a = *ok[k - 1], &b = *ok[k];
    if (b.l2 <= target) {
      const double f = std::log(target / a.l2) / std::log(b.l2 / a.l2);
      return std::exp(std::log(a.wall_seconds) + f * (std::log(b.wall_seconds) - std::log(a.wall_seconds)));
    }
  }
  return -1;
}

namespace {
Sweep make_sweep(const WorkPrecisionStudy& s) {
  Sweep sw;
  sw.source = s.source;
  sw.scene = s.scene;
  sw.output = s.output;
  sw.jobs = s.jobs;
  sw.common_sets = s.sets;
  sw.columns = {"scheme", "resolution"};
  if (s.reference == "run") sw.runs.push_back({"reference", {"reference", "reference"}, reference_run_sets(s)});
  for (const auto& sch : s.schemes)
    for (const auto& res : s.resolutions)
      sw.runs.push_back({folder_name(sch.name + "_" + res.name), {sch.name, res.name}, run_sets(s, sch, res)});
  return sw;
}

void write_csv(const std::string& path, const std::vector<WorkPrecisionPoint>& pts) {
  std::ofstream f(path);
  if (!f) throw OutputError("cannot write " + path + ": " + std::strerror(errno ? errno : EIO));
  f.precision(8);
  f << "scheme,resolution,particles,wall_seconds,steps,rhs_evals,error_l1,error_l2,error_linf,status,run\n";
  for (const auto& p : pts)
    f << p.scheme << "," << p.resolution << "," << p.particles << "," << p.wall_seconds << "," << p.steps << ","
      << p.rhs_evals << "," << p.l1 << "," << p.l2 << "," << p.linf << "," << p.status << "," << p.run << "\n";
}

// The plot (scripts/plot_work_precision.py), within the plot time limit (study/plot_command.hpp).
void plot(const std::string& csv, const std::string& png, double target, const std::string& title) {
  const char* env = std::getenv("ARKSPH_PLOT_WORK_PRECISION");
  const std::string script = env ? env : std::string(ARKSPH_SOURCE_DIR_STR) + "/scripts/plot_work_precision.py";
  std::fflush(stdout);
  run_study_plot("work-precision", script, {csv, png, "--target", std::to_string(target), "--title", title}, png);
}

// Why a finished run has no finite error: the reference at its particles, its own velocities, or its
// Ghia errors are not finite.
std::string nan_cause(const WorkPrecisionStudy& study, const ParticleVelocities& run, const ParticleVelocities& ref,
                      const AnalyticVelocity* exact, double t) {
  const auto finite = [](const std::vector<double>& v) {
    return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
  };
  if (!finite(run.u) || !finite(run.v)) return "its final velocities are not finite";
  if (study.reference == "analytic" && exact)
    for (std::size_t a = 0; a < run.x.size(); ++a) {
      double u = 0, v = 0;
      exact->eval(run.x[a], run.y[a], t, u, v);
      if (!std::isfinite(u) || !std::isfinite(v))
        return "study.analytic_velocity is not finite at its particle (" + message_number(run.x[a]) + ", " +
               message_number(run.y[a]) + "), t = " + message_number(t) + ": the reference is not finite";
    }
  if (study.reference == "run" && (!finite(ref.u) || !finite(ref.v))) return "the reference run's velocities are not finite";
  if (study.reference == "ghia") return "its Ghia centreline errors (summary.json metrics) are not finite";
  return "its error is not finite";
}
}  // namespace

int cmd_work_precision_study(const StudyArgs& args) {
  WorkPrecisionStudy study = read_work_precision_study(args.path, args.sets);
  if (!args.out.empty()) study.output = args.out;
  if (args.jobs) study.jobs = args.jobs;
  // The folder is locked for the whole study (the batch, the errors, the CSV, the plot), as `arksph
  // run` and `arksph batch` lock theirs: a second study, batch or run into it is refused (exit 2).
  const OutputFolder folder(study.output, args.path, args.out.empty() ? "study.output" : "--out");
  const Sweep sweep = make_sweep(study);
  BatchOptions bo;
  bo.quiet = args.quiet;
  bo.folder_locked = true;
  const BatchResult batch = run_batch(sweep, bo);

  std::size_t first = 0;
  ParticleVelocities ref;
  double ref_h = 0;
  std::string ref_kernel;
  if (study.reference == "run") {
    first = 1;
    const BatchRunResult& r = batch.runs[0];
    if (r.status != "ok") {
      std::fprintf(stderr, "arksph: study work-precision: the reference run %s did not finish (%s)\n", r.dir.c_str(),
                   r.status.c_str());
      return 3;
    }
    std::ostringstream warnings;
    const Scene rs = read_scene_text(read_text_file(study.scene), study.scene, reference_run_sets(study), warnings);
    ref_h = rs.h_over_dx * rs.spacing;
    ref_kernel = rs.kernel;
    ref = final_velocities(r.dir, nullptr, nullptr);
  }
  std::unique_ptr<AnalyticVelocity> exact;
  if (study.reference == "analytic")
    exact = std::make_unique<AnalyticVelocity>(study.analytic_velocity[0], study.analytic_velocity[1]);

  std::vector<WorkPrecisionPoint> pts;
  std::vector<std::string> not_finite;  // "run DIR: cause" of each finished run without a finite error
  for (std::size_t i = first; i < batch.runs.size(); ++i) {
    const BatchRunResult& r = batch.runs[i];
    WorkPrecisionPoint p;
    p.scheme = r.values[0], p.resolution = r.values[1], p.status = r.status, p.run = r.dir;
    p.wall_seconds = r.wall_seconds, p.steps = r.steps, p.rhs_evals = r.rhs_evals;
    p.l1 = p.l2 = p.linf = kNaN;
    if (r.status == "ok") {
      try {
        double t = 0;
        const ParticleVelocities run = final_velocities(r.dir, &t, &p.particles);
        VelocityErrors e;
        if (study.reference == "analytic") {
          e = errors_against_analytic(run, *exact, t);
        } else if (study.reference == "run") {
          e = errors_against_reference(run, ref, ref_kernel, ref_h);
        } else {  // ghia: the run's own centreline errors
          const double ur = metric(r, "ghia_u_rms"), vr = metric(r, "ghia_v_rms");
          e = {0.5 * (ur + vr), std::sqrt(0.5 * (ur * ur + vr * vr)),
               std::max(metric(r, "ghia_u_linf"), metric(r, "ghia_v_linf"))};
        }
        p.l1 = e.l1, p.l2 = e.l2, p.linf = e.linf;
        if (!std::isfinite(p.l2)) not_finite.push_back(r.dir + ": " + nan_cause(study, run, ref, exact.get(), t));
      } catch (const InputError& e) {
        p.status = "no_checkpoint";
      }
    }
    pts.push_back(p);
  }
  const std::string csv = (fs::path(study.output) / "work_precision.csv").string();
  write_csv(csv, pts);

  std::printf("%-16s %-12s %9s %10s %12s  %s\n", "scheme", "resolution", "particles", "wall [s]", "L2 error", "status");
  double lo = 1e300, hi = 0;
  for (const auto& p : pts) {
    char l2[32];
    if (std::isnan(p.l2)) std::snprintf(l2, sizeof l2, "NaN");  // printf gives "-nan" for some
    else std::snprintf(l2, sizeof l2, "%.4e", p.l2);
    std::printf("%-16s %-12s %9ld %10.3f %12s  %s\n", p.scheme.c_str(), p.resolution.c_str(), p.particles,
                p.wall_seconds, l2, p.status.c_str());
    if (p.status == "ok" && p.l2 > 0) lo = std::min(lo, p.l2), hi = std::max(hi, p.l2);
  }
  std::size_t finished = 0;
  for (const auto& p : pts) finished += p.status == "ok";
  if (!not_finite.empty() && hi > 0)
    std::fprintf(stderr, "arksph: study work-precision: %zu finished run(s) have no finite error (left out); %s\n",
                 not_finite.size(), not_finite.front().c_str());
  if (hi == 0) {
    if (finished == 0)
      std::fprintf(stderr, "arksph: study work-precision: no run finished\n");
    else if (!not_finite.empty())
      std::fprintf(stderr, "arksph: study work-precision: %zu run(s) finished but none has a finite error: %s\n",
                   finished, not_finite.front().c_str());
    else
      std::fprintf(stderr, "arksph: study work-precision: %zu run(s) finished but none has an error above 0\n", finished);
    return 3;
  }
  const double target = study.target_error > 0 ? study.target_error : std::sqrt(lo * hi);
  std::string best, others;
  double best_t = -1;
  for (const auto& sch : study.schemes) {
    std::vector<WorkPrecisionPoint> curve;
    for (const auto& p : pts)
      if (p.scheme == sch.name) curve.push_back(p);
    const double t = time_to_error(curve, target);
    char buf[128];
    if (t < 0) std::snprintf(buf, sizeof buf, "%s never", sch.name.c_str());
    else std::snprintf(buf, sizeof buf, "%s %.3g s", sch.name.c_str(), t);
    others += (others.empty() ? "" : ", ") + std::string(buf);
    if (t >= 0 && (best_t < 0 || t < best_t)) best_t = t, best = sch.name;
  }
  // What the line below measures: the target and how each scheme's time to it is found.
  std::printf("target: L2 error %.3g (%s); a scheme's time to reach it is interpolated log-log between the wall "
              "times of its two resolutions around it\n",
              target, study.target_error > 0 ? "study.target_error"
                                              : "no study.target_error: the geometric mean of the smallest and "
                                                "largest L2 error of the finished runs");
  if (best_t < 0)
    std::printf("soonest to L2 error %.3g: no scheme reaches it (%s)\n", target, others.c_str());
  else
    std::printf("soonest to L2 error %.3g: %s, %.3g s (%s)\n", target, best.c_str(), best_t, others.c_str());
  std::printf("results: %s\n", csv.c_str());
  const std::string title = study.title.empty() ? fs::path(study.source).stem().string() : study.title;
  plot(csv, (fs::path(study.output) / "work_precision.png").string(), target, title);
  std::fflush(stdout);
  return 0;
}

}  // namespace arksph
