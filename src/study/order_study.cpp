// The temporal order study (see order_study.hpp).
#include "study/order_study.hpp"

#include <toml++/toml.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <set>
#include <sstream>

#include "run/output_folder.hpp"
#include "run/setup.hpp"
#include "run/time_stepper.hpp"
#include "core/errors.hpp"
#include "io/names.hpp"
#include "integrate/erk_integrator.hpp"
#include "integrate/time_params.hpp"
#include "io/scene_reader.hpp"
#include "io/scene_schema.hpp"
#include "projection/divergence_operator.hpp"
#include "study/plot_command.hpp"
#include "study/reference_error.hpp"
#include "study/study_file.hpp"

namespace fs = std::filesystem;

namespace arksph {

namespace {
std::vector<double> positive_list(const toml::node& v, const std::string& where) {
  const toml::array* a = v.as_array();
  if (!a || a->empty()) throw InputError(where + ": expected a non-empty array of positive numbers");
  std::vector<double> out;
  for (const auto& e : *a) {
    const auto x = e.value<double>();
    if (!x || !(*x > 0)) throw InputError(where + ": expected a non-empty array of positive numbers");
    out.push_back(*x);
  }
  return out;
}

// An IMEX pair in the study's table list: "imex:<pair>" (the [study] key imex_pairs).
constexpr const char* kImexPrefix = "imex:";
bool is_imex(const std::string& table) { return table.rfind(kImexPrefix, 0) == 0; }
std::string pair_of(const std::string& table) { return table.substr(std::string(kImexPrefix).size()); }

// The end of one run: the ODE state, the pressure of that state and the r.m.s. of D u.
struct RunEnd {
  std::vector<double> state;
  std::vector<double> pressure;
  double divergence = 0;
};

// The pressure at the end state: under the constrained projection the one f computes there (the
// split's f_E under IMEX, which sees the implicit partition), under C&R the last projection's, under
// WCSPH the equation of state's.
std::vector<double> end_pressure(Model& model, TimeStepper& stepper, double t, const double* y) {
  RhsEvaluator& rhs = *model.rhs;
  const std::size_t n = rhs.layout().n;
  Projection* proj = model.projection.get();
  if (proj && proj->constrained()) {
    std::vector<double> yd(rhs.layout().size());
    if (stepper.split) {
      stepper.split->forget();
      stepper.split->explicit_rhs(t, y, yd.data());
    } else {
      rhs.eval(t, y, yd.data());
      proj->constrain(y, yd.data(), nullptr, nullptr);
    }
    return proj->pressure();
  }
  if (proj) return proj->pressure();
  rhs.eval(t, y, nullptr);
  return {rhs.fields().p.begin(), rhs.fields().p.begin() + static_cast<long>(n)};
}

// The steps of a table, and the study key that lists them.
const std::vector<double>& steps_of(const OrderStudy& s, const std::string& table) {
  return s.dt_for.count(table) ? s.dt_for.at(table) : s.dt;
}
std::string steps_key(const OrderStudy& s, const std::string& table) {
  return s.dt_for.count(table) ? "dt_for." + table : "study.dt";
}

// The file the study's messages name: the study file, or the scene of a study built in code.
std::string study_path(const OrderStudy& s) { return s.source.empty() ? s.scene : s.source; }

// A step as a --set value that reads back exactly and stays a TOML float.
std::string step_text(double dt) {
  std::string t = scene_schema::format_number(dt);
  if (t.find_first_of(".eEn") == std::string::npos) t += ".0";
  return t;
}

// The scene of one run of the study, read as `arksph run` reads it (the same function, so it refuses
// what a run refuses): the study's scene with its --set values, then the table's (an ERK table
// explicitly, an IMEX pair with the viscous term implicit) and the fixed step. InputError with the
// reader's message, prefixed with the study file and the run.
Scene order_run_scene(const OrderStudy& s, const std::string& text, const std::string& table, double dt,
                      const std::string& what) {
  std::vector<std::string> sets = s.sets;
  if (is_imex(table)) sets.insert(sets.end(), {"time.imex=true", "time.imex_pair=" + pair_of(table)});
  else sets.insert(sets.end(), {"time.imex=false", "time.integrator=" + table});
  sets.push_back("time.dt=" + step_text(dt));
  std::ostringstream warnings;
  try {
    return read_scene_text(text, s.scene, sets, warnings);
  } catch (const InputError& e) {
    throw InputError(study_path(s) + ": " + what + " " + table + " at dt " + message_number(dt) +
                     " (as arksph run reads it): " + e.what());
  }
}

RunEnd run_scene(const Scene& scene, long* rhs_evals) {
  Model model = build_model(scene);
  std::vector<double> y0(model.rhs->layout().size());
  model.rhs->initial_state(y0.data());
  ErkOptions o;
  const double dt = scene.dt;
  o.table = scene.integrator;  // unused under time.imex
  o.fixed_dt = dt;
  const Tolerances tol = integrator_tolerances(scene, dt);  // fixed steps: the implicit solves' tolerances
  o.rtol = tol.rtol;
  o.atol = tol.atol;
  if (model.projection) model.projection->project_initial(0.0, y0.data());
  TimeStepper stepper = make_time_stepper(scene, *model.rhs, o, y0, 0.0, model.projection.get());
  TimeIntegrator& integ = *stepper.integrator;
  double t = 0;
  while (t < scene.end) {  // the run loop's step, projection included
    const double next = stepper.step(t, scene.end);
    if (!(next > t))
      throw NumericalFailure("order study: the step from t = " + message_number(t) + " did not advance (dt " +
                             message_number(dt) + ")");
    t = next;
  }
  if (rhs_evals) *rhs_evals = integ.stats().rhs_evals + integ.stats().implicit_rhs_evals;
  RunEnd end;
  end.state.assign(integ.state(), integ.state() + integ.size());
  end.pressure = end_pressure(model, stepper, t, end.state.data());
  const StateLayout& L = model.rhs->layout();
  model.rhs->eval(t, end.state.data(), nullptr);
  end.divergence = divergence_rms(model.rhs->fields(), end.state.data() + L.vel(0),
                                  L.dim == 2 ? end.state.data() + L.vel(1) : nullptr);
  return end;
}

int nominal_order(const std::string& table) {
  return is_imex(table) ? imex_pair_order(pair_of(table)) : erk_table_order(table);
}

// The largest |a_i - b_i| over [first, last); NaN if a difference is NaN (a state that is not finite).
double max_diff(const std::vector<double>& a, const std::vector<double>& b, std::size_t first = 0,
                std::size_t last = static_cast<std::size_t>(-1)) {
  double m = 0;
  for (std::size_t i = first; i < std::min({a.size(), b.size(), last}); ++i) {
    const double d = std::abs(a[i] - b[i]);
    if (std::isnan(d)) return d;
    m = std::max(m, d);
  }
  return m;
}

bool all_finite(const std::vector<double>& v) {
  for (const double x : v)
    if (!std::isfinite(x)) return false;
  return true;
}

// A number of the console table: NaN as "NaN" (printf gives "-nan" for some).
std::string table_number(double v, const char* format) {
  if (std::isnan(v)) return "NaN";
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

// A number of the CSV files: NaN as "nan" whatever its sign.
struct CsvNumber {
  double v;
};
std::ostream& operator<<(std::ostream& os, CsvNumber n) {
  if (std::isnan(n.v)) return os << "nan";
  return os << n.v;
}

// Checks of the study as a whole, before any run (InputError naming the study key): each table's
// steps (two different ones at least, none longer than time.end, each able to advance t at
// time.end within time.max_steps steps, the reference step too), then every run's scene as `arksph
// run` reads it, and an analytic reference that is finite at the particles. Returns the study's scene.
Scene check_order_study(const OrderStudy& s) {
  const std::string path = study_path(s);
  const auto bad = [&](const std::string& key, const std::string& why) { return InputError(path + ": " + key + ": " + why); };
  const std::string text = read_text_file(s.scene);
  std::ostringstream warnings;
  const Scene base = read_scene_text(text, s.scene, s.sets, warnings);
  using scene_schema::format_number;
  const double end = base.end, spacing_at_end = std::nextafter(end, INFINITY) - end;
  const auto check_step = [&](const std::string& key, double dt, const std::string& what) {
    if (!(dt >= spacing_at_end))
      throw bad(key, what + format_number(dt) + " is below the spacing of doubles at time.end = " + format_number(end) +
                         " (" + format_number(spacing_at_end) + "): t + dt == t, a run could not advance");
    const double steps = std::ceil(end / dt);
    if (steps > static_cast<double>(base.max_steps))
      throw bad(key, what + format_number(dt) + " takes " + format_number(steps) + " steps to time.end = " +
                         format_number(end) + ", more than time.max_steps = " + std::to_string(base.max_steps));
  };
  const bool analytic = s.reference == "analytic";
  double dt_min_all = std::numeric_limits<double>::infinity();
  for (const auto& table : s.tables) {
    const auto& steps = steps_of(s, table);
    const std::string key = steps_key(s, table);
    if (std::set<double>(steps.begin(), steps.end()).size() < 2)
      throw bad(key, "the steps are all equal (" + format_number(steps.front()) +
                         "): at least two different step sizes are needed for a slope");
    for (const double dt : steps) {
      if (dt > end)
        throw bad(key, format_number(dt) + " is longer than time.end = " + format_number(end) +
                           ": a run then takes a single step to time.end whatever the step, so its error cannot "
                           "show an order");
      check_step(key, dt, "");
    }
    const double dt_min = *std::min_element(steps.begin(), steps.end());
    dt_min_all = std::min(dt_min_all, dt_min);
    if (!analytic && s.reference_table.empty())
      check_step("study.reference_dt_divisor", dt_min / s.reference_dt_divisor,
                 "the reference step of " + table + " (" + key + " / divisor) ");
  }
  if (!analytic && !s.reference_table.empty())
    check_step("study.reference_dt_divisor", dt_min_all / s.reference_dt_divisor, "the reference step (smallest step / divisor) ");
  for (const auto& table : s.tables) {
    const auto& steps = steps_of(s, table);
    for (const double dt : steps) order_run_scene(s, text, table, dt, "table");
    if (!analytic && s.reference_table.empty())
      order_run_scene(s, text, table, *std::min_element(steps.begin(), steps.end()) / s.reference_dt_divisor,
                      "reference run of table");
  }
  if (!analytic && !s.reference_table.empty())
    order_run_scene(s, text, s.reference_table, dt_min_all / s.reference_dt_divisor, "reference table");
  if (analytic) check_analytic_velocity_finite(path, s.analytic_velocity, base);
  return base;
}

}  // namespace

double loglog_slope(const std::vector<double>& x, const std::vector<double>& y) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = static_cast<double>(x.size());
  for (std::size_t k = 0; k < x.size(); ++k) {
    const double lx = std::log(x[k]), ly = std::log(y[k]);
    sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

OrderStudy read_order_study(const std::string& path, const std::vector<std::string>& extra_sets) {
  const toml::table root = read_study_toml(path);
  const auto bad = [&](const std::string& key, const std::string& why) { return InputError(path + ": " + echo_value(key) + ": " + why); };
  for (const auto& [k, v] : root)
    if (k.str() != "study" && k.str() != "dt_for") throw bad(std::string(k.str()), "unknown key (expected [study], [dt_for])");
  const toml::table* st = root["study"].as_table();
  if (!st) throw bad("study", "missing table [study]");
  OrderStudy s;
  s.source = path;
  for (const auto& [k, v] : *st) {
    const std::string key = "study." + std::string(k.str()), name(k.str());
    if (name == "scene" || name == "output" || name == "reference_table" || name == "reference") {
      if (!v.is_string()) throw bad(key, "expected a string");
      (name == "scene" ? s.scene : name == "output" ? s.output : name == "reference" ? s.reference : s.reference_table) =
          v.as_string()->get();
    } else if (name == "analytic_velocity") {
      const toml::array* a = v.as_array();
      if (!a || a->size() != 2 || !(*a)[0].is_string() || !(*a)[1].is_string())
        throw bad(key, "expected two expressions [u, v] of x, y, t");
      s.analytic_velocity = {(*a)[0].as_string()->get(), (*a)[1].as_string()->get()};
    } else if (name == "set" || name == "tables" || name == "imex_pairs") {
      const toml::array* a = v.as_array();
      if (!a) throw bad(key, "expected an array of strings");
      for (const auto& e : *a) {
        if (!e.is_string()) throw bad(key, "expected an array of strings");
        const std::string item = e.as_string()->get();
        if (name == "imex_pairs") {
          if (!is_registered("imex_pair", item)) throw bad(key, "'" + item + "' is not an IMEX pair (see arksph list)");
          s.tables.push_back(kImexPrefix + item);
        } else {
          (name == "set" ? s.sets : s.tables).push_back(item);
        }
      }
    } else if (name == "dt") {
      s.dt = positive_list(v, path + ": " + key);
    } else if (name == "reference_dt_divisor" || name == "tolerance") {
      const auto x = v.value<double>();
      if (!x || !(*x > 0) || (name == "reference_dt_divisor" && *x < 2)) throw bad(key, "expected a positive number (divisor >= 2)");
      (name == "tolerance" ? s.tolerance : s.reference_dt_divisor) = *x;
    } else {
      throw bad(key, "unknown key");
    }
  }
  if (s.reference != "fine_step" && s.reference != "analytic")
    throw bad("study.reference", "'" + s.reference + "': expected fine_step or analytic");
  if (s.reference == "analytic") {
    if (s.analytic_velocity.empty()) throw bad("study.analytic_velocity", "missing (needed by reference = \"analytic\")");
    check_analytic_velocity(path, s.analytic_velocity);
  } else if (!s.analytic_velocity.empty()) {
    throw bad("study.analytic_velocity", "only with reference = \"analytic\"");
  }
  if (s.scene.empty()) throw bad("study.scene", "missing (the scene file)");
  if (fs::path(s.scene).is_relative()) s.scene = (fs::path(path).parent_path() / s.scene).lexically_normal().string();
  if (!fs::is_regular_file(s.scene))
    throw bad("study.scene", s.scene + (fs::is_directory(s.scene) ? ": is a directory, not a scene file"
                                        : fs::exists(s.scene)     ? ": not a regular file"
                                                                  : ": no such file"));
  if (s.tables.empty()) throw bad("study.tables", "missing (a list of ARKODE table names, or study.imex_pairs)");
  const auto known = erk_table_names();
  const auto check_table = [&](const std::string& key, const std::string& t) {
    if (is_imex(t) && is_registered("imex_pair", pair_of(t))) return;
    if (std::find(known.begin(), known.end(), t) == known.end()) throw bad(key, "'" + t + "' is not an ERK table (see arksph list)");
  };
  for (const auto& t : s.tables) check_table("study.tables", t);
  if (!s.reference_table.empty()) check_table("study.reference_table", s.reference_table);
  if (const toml::table* per = root["dt_for"].as_table())
    for (const auto& [k, v] : *per) {
      const std::string t(k.str());
      if (std::find(s.tables.begin(), s.tables.end(), t) == s.tables.end()) throw bad("dt_for." + t, "not in study.tables");
      s.dt_for[t] = positive_list(v, path + ": dt_for." + t);
    }
  for (const auto& t : s.tables) {
    const auto& list = s.dt_for.count(t) ? s.dt_for.at(t) : s.dt;
    if (list.size() < 2) throw bad(s.dt_for.count(t) ? "dt_for." + t : "study.dt", "at least two step sizes are needed for a slope");
  }
  s.sets.insert(s.sets.end(), extra_sets.begin(), extra_sets.end());
  if (s.output.empty()) s.output = "runs/" + fs::path(path).stem().string();
  check_order_study(s);  // bad scene, set or step, or a run that `arksph run` refuses: exit 2 before any run
  return s;
}

std::vector<OrderFit> run_order_study(const OrderStudy& study, bool log) {
  const Scene scene = check_order_study(study);  // every run checked before the first starts
  const std::string text = read_text_file(study.scene);
  const auto scene_of = [&](const std::string& table, double dt) { return order_run_scene(study, text, table, dt, "table"); };
  std::vector<OrderFit> fits;
  // A common reference table runs once, at the smallest step of the whole study / divisor.
  double dt_min_all = 1e300;
  for (const auto& table : study.tables)
    for (double dt : steps_of(study, table)) dt_min_all = std::min(dt_min_all, dt);
  const bool analytic = study.reference == "analytic";
  std::unique_ptr<AnalyticVelocity> exact;
  const StateLayout layout = build_model(scene).rhs->layout();
  if (analytic) exact = std::make_unique<AnalyticVelocity>(study.analytic_velocity[0], study.analytic_velocity[1]);
  // The analytic mode's error: max over the particles of |u_a - u_exact(r_a, t_end)|.
  const auto analytic_error = [&](const std::vector<double>& y) {
    const std::vector<double> ones(layout.n, 1.0);
    return errors_against_analytic(velocities_of(layout, y.data(), ones, ones), *exact, scene.end).linf;
  };
  {  // every run has a fixed step: say how far its implicit stages are solved (integrate/time_params.hpp)
    const Tolerances tol = integrator_tolerances(scene, dt_min_all);
    std::printf("order study: fixed steps; IMEX stages solved to rtol %g, atol %g (min of time.rtol/atol and %g/%g)\n",
                tol.rtol, tol.atol, kFixedStepRtol, kFixedStepAtol);
  }
  // Why an error is NaN: the reference (the analytic field at the run's end positions, or the
  // reference run's end state) or the run's own end state is not finite.
  const auto nan_cause = [&](const std::vector<double>& y, const RunEnd& ref) -> std::string {
    if (analytic) {
      for (std::size_t a = 0; a < layout.n; ++a) {
        const double x = y[layout.pos(0) + a], z = layout.dim > 1 ? y[layout.pos(1) + a] : 0.0;
        double u = 0, v = 0;
        exact->eval(x, z, scene.end, u, v);
        if (std::isfinite(x) && std::isfinite(z) && !(std::isfinite(u) && std::isfinite(v)))
          return "study.analytic_velocity is not finite at the end position (" + message_number(x) + ", " +
                 message_number(z) + "), t = " + message_number(scene.end) + ": the reference is not finite";
      }
    } else if (!all_finite(ref.state)) {
      return "the reference run's end state is not finite";
    }
    return all_finite(y) ? "the error is not finite" : "the run's end state is not finite (an unstable step?)";
  };
  RunEnd shared_ref;
  if (!study.reference_table.empty() && !analytic) {
    shared_ref = run_scene(scene_of(study.reference_table, dt_min_all / study.reference_dt_divisor), nullptr);
    if (log)
      std::fprintf(stderr, "order: reference %s at dt %.4g\n", study.reference_table.c_str(),
                   dt_min_all / study.reference_dt_divisor);
  }
  for (const auto& table : study.tables) {
    OrderFit fit;
    fit.table = table;
    fit.nominal = nominal_order(table);
    const auto& steps = steps_of(study, table);
    const double dt_min = *std::min_element(steps.begin(), steps.end());
    const RunEnd ref =  // else each table is its own reference at its smallest step / divisor
        analytic                        ? RunEnd{}
        : study.reference_table.empty() ? run_scene(scene_of(table, dt_min / study.reference_dt_divisor), nullptr)
                                        : shared_ref;
    bool told = false;  // one line per table about errors that are not finite
    std::vector<double> xs, ys, yu, yp;
    const std::size_t v0 = layout.vel(0), v1 = layout.vel(0) + static_cast<std::size_t>(layout.dim) * layout.n;
    for (double dt : steps) {
      OrderPoint p;
      p.dt = dt;
      const RunEnd end = run_scene(scene_of(table, dt), &p.rhs_evals);
      p.error = analytic ? analytic_error(end.state) : max_diff(end.state, ref.state);
      p.velocity_error = analytic ? p.error : max_diff(end.state, ref.state, v0, v1);
      p.pressure_error = analytic ? 0.0 : max_diff(end.pressure, ref.pressure);
      p.divergence = end.divergence;
      if (log)
        std::fprintf(stderr, "order: %-32s dt %-10.4g error %s  velocity %s  pressure %s  |Du| %s\n", table.c_str(),
                     dt, table_number(p.error, "%.4e").c_str(), table_number(p.velocity_error, "%.4e").c_str(),
                     table_number(p.pressure_error, "%.4e").c_str(), table_number(p.divergence, "%.3e").c_str());
      if (std::isnan(p.error) && !told) {  // reported whatever `log` says: the table's order is NaN
        std::fprintf(stderr, "arksph: study order: %s at dt %s: the error is NaN: %s\n", table.c_str(),
                     message_number(dt).c_str(), nan_cause(end.state, ref).c_str());
        told = true;
      }
      fit.points.push_back(p);
      xs.push_back(dt), ys.push_back(std::max(p.error, 1e-300));
      yu.push_back(std::max(p.velocity_error, 1e-300)), yp.push_back(std::max(p.pressure_error, 1e-300));
    }
    fit.observed = loglog_slope(xs, ys);
    fit.observed_velocity = loglog_slope(xs, yu);
    fit.observed_pressure = analytic ? 0.0 : loglog_slope(xs, yp);
    fit.flagged = !(std::abs(fit.observed - fit.nominal) <= study.tolerance);
    if (log)
      std::fprintf(stderr, "order: %-32s nominal %d observed %s%s\n", table.c_str(), fit.nominal,
                   table_number(fit.observed, "%.3f").c_str(), fit.flagged ? "  FLAG" : "");
    fits.push_back(std::move(fit));
  }
  return fits;
}

int cmd_order_study(const StudyArgs& args) {
  OrderStudy study = read_order_study(args.path, args.sets);
  if (!args.out.empty()) study.output = args.out;
  // The folder, created and locked before any run, as `arksph run` and `arksph batch` lock theirs:
  // a second study, batch or run into it is refused (exit 2), a folder that cannot be made gives exit 5.
  const OutputFolder folder(study.output, args.path, args.out.empty() ? "study.output" : "--out");
  const auto fits = run_order_study(study, !args.quiet);
  const std::string err_csv = (fs::path(study.output) / "order_errors.csv").string();
  const std::string fit_csv = (fs::path(study.output) / "order_fit.csv").string();
  {
    std::ofstream e(err_csv), f(fit_csv);
    if (!e || !f) throw OutputError("cannot write " + (e ? fit_csv : err_csv) + ": " + std::strerror(errno ? errno : EIO));
    e << "table,nominal_order,dt,error,rhs_evals,velocity_error,pressure_error,divergence_rms\n";
    f << "table,nominal_order,observed_order,tolerance,flag,fsal_bug_workaround,velocity_order,pressure_order,"
         "divergence_rms\n";
    e.precision(10), f.precision(6);
    for (const auto& fit : fits) {
      for (const auto& p : fit.points)
        e << fit.table << "," << fit.nominal << "," << p.dt << "," << CsvNumber{p.error} << "," << p.rhs_evals << ","
          << CsvNumber{p.velocity_error} << "," << CsvNumber{p.pressure_error} << "," << CsvNumber{p.divergence} << "\n";
      f << fit.table << "," << fit.nominal << "," << CsvNumber{fit.observed} << "," << study.tolerance << ","
        << (fit.flagged ? "FLAG" : "ok") << "," << (!is_imex(fit.table) && erk_table_has_fsal_bug(fit.table) ? 1 : 0)
        << "," << CsvNumber{fit.observed_velocity} << "," << CsvNumber{fit.observed_pressure} << ","
        << CsvNumber{fit.points.empty() ? 0.0 : fit.points.back().divergence} << "\n";
    }
  }
  std::printf("%-32s %8s %9s %9s %9s %10s  %s\n", "table", "nominal", "observed", "velocity", "pressure", "|Du| end",
              "flag");
  int flagged = 0;
  for (const auto& fit : fits) {
    std::printf("%-32s %8d %9s %9s %9s %10s  %s\n", fit.table.c_str(), fit.nominal,
                table_number(fit.observed, "%.3f").c_str(), table_number(fit.observed_velocity, "%.3f").c_str(),
                table_number(fit.observed_pressure, "%.3f").c_str(),
                table_number(fit.points.empty() ? 0.0 : fit.points.back().divergence, "%.3e").c_str(),
                fit.flagged ? "FLAG" : "ok");
    flagged += fit.flagged;
  }
  std::printf("errors: %s\nfit: %s\n", err_csv.c_str(), fit_csv.c_str());
  // The plot: scripts/plot_order.py next to the binary's source, if python3 and matplotlib are
  // present, within the plot time limit (study/plot_command.hpp).
  std::fflush(stdout);
  const char* plot = std::getenv("ARKSPH_PLOT_ORDER");
  const std::string script = plot ? plot : std::string(ARKSPH_SOURCE_DIR_STR) + "/scripts/plot_order.py";
  const std::string png = (fs::path(study.output) / "order.png").string();
  std::vector<std::string> plot_args = {err_csv, fit_csv, png};
  if (study.reference == "analytic") plot_args.push_back("max velocity error against the analytic solution");
  run_study_plot("order", script, plot_args, png);
  std::fflush(stdout);
  return flagged ? 4 : 0;
}

}  // namespace arksph
