#include "run/run_output.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <utility>

#include "core/errors.hpp"
#include "core/seconds_since.hpp"
#include "diagnostics/exact_velocity.hpp"
#include "diagnostics/frame_reduction.hpp"
#include "diagnostics/poiseuille.hpp"
#include "core/expression.hpp"
#include "io/frame_order.hpp"
#include "io/pvtp_writer.hpp"
#include "io/vtp_writer.hpp"
#include "run/wall_frame.hpp"

namespace arksph {

namespace {
using clock_type = std::chrono::steady_clock;
}  // namespace

RunOutput::RunOutput(const Scene& scene, Model& model, const RunOptions& options, std::string run_id, int pieces)
    : scene_(scene), model_(model), options_(options), run_id_(std::move(run_id)),
      steady_(scene.steady_tolerance, scene.steady_window, scene.steady_measure), pieces_(pieces) {
  if (options.write_frames) {
    pvd_ = std::make_unique<PvdCollection>(scene.directory, "particles.pvd");
    pvd_->set_run_id(run_id_);
    if (scene.walls) {
      walls_pvd_ = std::make_unique<PvdCollection>(scene.directory, "walls.pvd");
      walls_pvd_->set_run_id(run_id_);
    }
  }
  csv_.open(scene.directory + "/timeseries.csv", csv_columns());  // the folder exists (OutputFolder)
}

void RunOutput::restore_steady(const std::vector<double>& rows, int columns) {
  if (!steady_.enabled() || columns < 2) return;
  const std::size_t width = static_cast<std::size_t>(columns);
  for (std::size_t r = 0; r + width <= rows.size(); r += width)
    steady_.add({rows[r], rows[r + 1], std::vector<double>(rows.begin() + static_cast<long>(r) + 2,
                                                           rows.begin() + static_cast<long>(r + width))});
}

std::vector<std::string> RunOutput::csv_columns() const {
  // dt: the largest step taken since the previous row.
  std::vector<std::string> c = {"t", "dt", "steps", "kinetic_energy", "max_speed", "cv", "density_mean", "density_rms"};
  if (scene_.ghia_re) c.insert(c.end(), {"ghia_u_linf", "ghia_u_rms", "ghia_v_linf", "ghia_v_rms"});
  if (scene_.poiseuille) c.insert(c.end(), {"tstar", "poiseuille_eps"});
  if (scene_.interface) c.insert(c.end(), {"bubble_y", "spike_y", "upper_density_mean", "upper_density_rms"});
  if (ExactVelocity(scene_.exact_velocity).enabled()) c.insert(c.end(), {"velocity_l1_relative", "peak_speed_error", "amplitude_error"});
  if (steady_.enabled()) c.push_back("steady_rate");
  if (scene_.energy_budget)  // diagnostics/energy_budget.hpp
    c.insert(c.end(), {"potential_energy", "compressible_energy", "viscous_dissipation", "total_energy"});
  return c;
}

void RunOutput::record(const FrameDiagnostics& diag, const StepStats& stats, const Frame* whole, const Frame* walls) {
  auto t0 = clock_type::now();
  const double t = diag.t;
  if (whole && whole->dimension == 1) {  // 1D: the whole profile is small, write it (C&R Fig. 1)
    std::vector<std::vector<double>> rows;
    for (std::size_t a = 0; a < whole->n; ++a)
      rows.push_back({whole->x[a], whole->u[a], whole->pressure[a], whole->density[a]});
    write_csv(scene_.directory + "/profile_1d.csv", {"x", "u", "pressure", "density"}, rows);
  }
  last_ = diag.metrics;
  last_t_ = t;
  last_divergence_ = diag.divergence_rms;
  std::vector<double> row = {t, stats.last_step, static_cast<double>(stats.steps), last_.kinetic_energy,
                             last_.max_speed, last_.cv, last_.density_mean, last_.density_rms};
  SteadySample sample{t, last_.kinetic_energy, {}};
  if (scene_.ghia_re) {
    const GhiaErrors& g = diag.ghia;
    row.insert(row.end(), {g.u_linf, g.u_rms, g.v_linf, g.v_rms});
    sample.centreline = g.u_sph;
    sample.centreline.insert(sample.centreline.end(), g.v_sph.begin(), g.v_sph.end());
    case_metrics_.set("ghia_u_linf", g.u_linf).set("ghia_u_rms", g.u_rms);
    case_metrics_.set("ghia_v_linf", g.v_linf).set("ghia_v_rms", g.v_rms);
    std::vector<std::vector<double>> prof;
    for (std::size_t i = 0; i < g.u_coord.size(); ++i) prof.push_back({g.u_coord[i], g.u_ref[i], g.u_sph[i]});
    write_csv(scene_.directory + "/ghia_u.csv", {"y", "u_ghia", "u_sph"}, prof);
    prof.clear();
    for (std::size_t i = 0; i < g.v_coord.size(); ++i) prof.push_back({g.v_coord[i], g.v_ref[i], g.v_sph[i]});
    write_csv(scene_.directory + "/ghia_v.csv", {"x", "v_ghia", "v_sph"}, prof);
  }
  if (scene_.poiseuille) {
    const double d = 0.5 * (scene_.max[1] - scene_.min[1]);
    const double tstar = poiseuille_tstar(t, d, scene_.viscosity);
    const double eps = diag.poiseuille_eps;
    row.insert(row.end(), {tstar, eps});
    if (tstar >= 0.5 - 1e-9 && tstar <= 2.0 + 1e-9 && std::isfinite(eps))
      eps_max_window_ = std::max(eps_max_window_, eps);
    case_metrics_.set("poiseuille_rms", eps).set("poiseuille_tstar", tstar);
    std::vector<std::vector<double>> prof;  // per particle at the latest output time (Basa Fig. 4)
    const std::vector<double>& yu = diag.poiseuille_profile;
    for (std::size_t k = 0; k + 1 < yu.size(); k += 2) {
      const double exact = poiseuille_velocity(yu[k] - 0.5 * (scene_.min[1] + scene_.max[1]), t, d,
                                               scene_.viscosity, poiseuille_force(scene_));
      prof.push_back({yu[k], yu[k + 1], exact});
    }
    write_csv(scene_.directory + "/poiseuille_profile.csv", {"y", "u_sph", "u_exact"}, prof);
    case_metrics_.set("poiseuille_eps_max_tstar_0.5_2", eps_max_window_);
  }
  if (scene_.interface) {
    const PhaseInterface& pi = diag.interface;
    const PhaseDensity& pd = diag.upper_density;
    row.insert(row.end(), {pi.bubble_y, pi.spike_y, pd.mean, pd.rms});
    case_metrics_.set("bubble_y", pi.bubble_y).set("spike_y", pi.spike_y);
    case_metrics_.set("upper_density_mean", pd.mean).set("upper_density_rms", pd.rms);
    std::vector<std::vector<double>> seg;
    for (const auto& s : pi.segments) seg.push_back({s[0], s[1], s[2], s[3]});
    char name[64];
    std::snprintf(name, sizeof name, "/interface_%06d.csv", frames_);
    write_csv(scene_.directory + name, {"x0", "y0", "x1", "y1"}, seg);
  }
  if (ExactVelocity(scene_.exact_velocity).enabled()) {
    const ExactVelocityErrors& e = diag.exact;
    row.insert(row.end(), {e.l1_relative, e.peak_speed_error, e.amplitude_error});
    case_metrics_.set("velocity_l1_relative", e.l1_relative).set("peak_speed_error", e.peak_speed_error);
    case_metrics_.set("amplitude_error", e.amplitude_error);
  }
  if (steady_.enabled()) {
    if (steady_.add(std::move(sample)) && steady_time_ < 0) steady_time_ = t;
    row.push_back(steady_.rate());
  }
  if (scene_.energy_budget) {
    const double dissipation = dissipation_ ? dissipation_->total() : 0.0;
    const double total = last_.kinetic_energy + diag.potential_energy + diag.compressible_energy + dissipation;
    row.insert(row.end(), {diag.potential_energy, diag.compressible_energy, dissipation, total});
    case_metrics_.set("potential_energy", diag.potential_energy).set("compressible_energy", diag.compressible_energy);
    case_metrics_.set("viscous_dissipation", dissipation).set("total_energy", total);
  }
  {  // nearest-neighbour distances at the latest output time (Szewc Figs. 7, 18)
    const Histogram& hist = diag.nearest;
    std::vector<std::vector<double>> rows;
    for (std::size_t k = 0; k < hist.counts.size(); ++k)
      rows.push_back({k * hist.bin_width, (k + 1) * hist.bin_width, static_cast<double>(hist.counts[k])});
    write_csv(scene_.directory + "/nn_histogram.csv", {"r_over_dx_lo", "r_over_dx_hi", "count"}, rows);
  }
  diagnostic_seconds_ += seconds_since(t0);

  t0 = clock_type::now();
  csv_.row(row);
  if (pvd_ && pieces_ > 0) {
    char name[64];
    std::snprintf(name, sizeof name, "particles_%06d.pvtp", frames_);
    std::vector<std::string> pieces;
    for (int r = 0; r < pieces_; ++r) pieces.push_back(piece_file_name(frames_, r));
    write_pvtp(scene_.directory + "/" + name, pieces, !scene_.fluid_region.empty());
    pvd_->add(t, name);
    if (walls_pvd_) {
      std::snprintf(name, sizeof name, "walls_%06d.pvtp", frames_);
      pieces.clear();
      for (int r = 0; r < pieces_; ++r) pieces.push_back(piece_file_name(frames_, r, "walls"));
      write_pvtp(scene_.directory + "/" + name, pieces);
      walls_pvd_->add(t, name);
    }
  } else if (pvd_ && whole) {
    char name[64];
    std::snprintf(name, sizeof name, "particles_%06d.vtp", frames_);
    const FrameInIdOrder ordered(*whole);  // rows by id (io/frame_order.hpp)
    Frame rows = ordered.frame();
    rows.smoothing_length = model_.h;
    write_vtp(scene_.directory + "/" + name, rows);
    pvd_->add(t, name);
    if (walls_pvd_ && walls) {
      write_vtp(scene_.directory + "/" + wall_file_name(frames_), *walls);
      walls_pvd_->add(t, wall_file_name(frames_));
    }
  }
  ++frames_;
  output_seconds_ += seconds_since(t0);
}

void RunOutput::finish(const RunResult& result, const StepStats& stats, const RunTotals& totals) {
  const double wall_seconds = totals.wall_seconds;
  const RhsTiming& rt = model_.rhs->timing();
  Json j = Json::object();
  j.set("scene", scene_.name).set("scheme", scene_.scheme).set("run_id", run_id_);
  j.set("particles", model_.particles.n).set("dimension", scene_.dimension);
  j.set("final_time", result.final_time >= 0 ? result.final_time : last_t_).set("steps", stats.steps).set("rhs_evals", stats.rhs_evals);
  j.set("diagnostic_evals", totals.diagnostic_evals).set("step_attempts", stats.attempts);
  j.set("error_test_failures", stats.error_test_fails);
  j.set("wall_reflections", totals.wall_reflections).set("neighbor_rebuilds", totals.neighbor_rebuilds);
  j.set("wall_seconds", wall_seconds);
  if (totals.cpu_seconds >= 0) j.set("cpu_seconds", totals.cpu_seconds);
  j.set("status", result.exit_code == 0 ? "ok" : result.interrupted ? "interrupted" : "failed");
  if (result.exit_code != 0) j.set("failure", result.message);
  j.set("frames", frames_);
  j.set("mpi", totals.mpi);
  j.set("terms", Json(model_.terms));
  if (scene_.imex) {  // ARKStep IMEX counters (time.imex)
    Json im = Json::object();
    im.set("pair", scene_.imex_pair).set("implicit_rhs_evals", stats.implicit_rhs_evals);
    im.set("newton_iterations", stats.newton_iters).set("newton_failures", stats.newton_fails);
    im.set("linear_setups", stats.linear_setups).set("jacobian_evals", stats.jacobian_evals);
    im.set("klu_symbolic_analyses", stats.symbolic_analyses);
    im.set("linear_iterations", stats.linear_iters);  // SPGMR over ranks; 0 with KLU (one process)
    j.set("imex", im);
  }
  Json timing = Json::object();
  const double ppe = model_.projection ? model_.projection->stats().seconds : 0.0;
  timing.set("neighbors", rt.neighbors).set("rhs", rt.terms).set("ppe", ppe);
  timing.set("diagnostics", diagnostic_seconds_).set("output", output_seconds_);
  if (totals.stepping_seconds >= 0) timing.set("stepping", totals.stepping_seconds);
  if (totals.reorders >= 0) {
    timing.set("reorder", totals.reorder_seconds);
    j.set("reorders", totals.reorders);
  }
  // What is left: set-up, ARKODE's own vector work, state checks. (ppe includes its own neighbour
  // refresh, counted in neighbors and rhs too, so it is not subtracted.)
  timing.set("setup_and_integrator", wall_seconds - rt.neighbors - rt.terms - diagnostic_seconds_ - output_seconds_);
  if (model_.projection) {
    const ProjectionStats& ps = model_.projection->stats();
    Json ppe_json = Json::object();
    ppe_json.set("solver", model_.projection->solver_name()).set("solves", ps.solves);
    ppe_json.set("solve_seconds", ps.solve_seconds).set("assembly_seconds", ps.assembly_seconds);
    ppe_json.set("setup_seconds", ps.setup_seconds);
    ppe_json.set("seconds_per_solve", ps.solves ? ps.seconds / ps.solves : 0.0);
    ppe_json.set("last_residual", ps.last_residual).set("max_residual", ps.max_residual);
    ppe_json.set("iterations", ps.iterations).set("symbolic_analyses", ps.symbolic_analyses);
    if (const ConstrainedPressure* c = model_.projection->constraint()) {
      ppe_json.set("constraint_relaxation_rate", c->relaxation());
      if (c->free_surface()) {
        const ConstrainedPressure::SurfaceStats& st = c->surface_stats();
        ppe_json.set("surface_evaluations", st.evaluations).set("surface_solves", st.solves);
        ppe_json.set("surface_unconverged", st.unconverged);
      }
    }
    j.set("ppe", ppe_json);
    const DensityCorrection* c = model_.projection->correction();
    if (c) {
      const CorrectionStats& cs = c->stats();
      Json cj = Json::object();
      cj.set("applications", cs.applications).set("iterations", cs.iterations);
      cj.set("seconds", cs.seconds).set("first_history", Json(cs.first_history));
      j.set("density_correction", cj);
    }
  }
  j.set("timing", timing);
  Json metrics = Json::object();
  metrics.set("kinetic_energy", last_.kinetic_energy).set("max_speed", last_.max_speed).set("cv", last_.cv);
  metrics.set("density_mean", last_.density_mean).set("density_rms", last_.density_rms);
  metrics.set("divergence_rms", last_divergence_);
  for (const char* key : {"ghia_u_linf", "ghia_u_rms", "ghia_v_linf", "ghia_v_rms", "poiseuille_rms",
                          "poiseuille_tstar", "poiseuille_eps_max_tstar_0.5_2", "bubble_y", "spike_y",
                          "upper_density_mean", "upper_density_rms", "velocity_l1_relative", "peak_speed_error",
                          "amplitude_error", "potential_energy", "compressible_energy", "viscous_dissipation",
                          "total_energy"})
    if (const Json* v = case_metrics_.find(key)) metrics.set(key, *v);
  j.set("metrics", metrics);
  Json params = Json::object();
  params.set("h", model_.h).set("sound_speed", model_.sound_speed);
  if (model_.reference_speed > 0) params.set("flow_speed", model_.reference_speed);
  j.set("derived", params);
  Json automatic = Json::object();  // the keys given as "auto" and the values their rules chose
  for (const auto& [key, value] : scene_.automatic) automatic.set(key, value);
  if (steady_.enabled()) {  // time.steady_tolerance: whether and when the run stopped at steady state
    Json ss = Json::object();
    ss.set("tolerance", scene_.steady_tolerance).set("window", scene_.steady_window);
    ss.set("measure", steady_measures().name(scene_.steady_measure));
    ss.set("reached", steady_time_ >= 0).set("time", steady_time_ >= 0 ? Json(steady_time_) : Json());
    ss.set("rate", steady_.rate());
    j.set("steady_state", ss);
  }
  j.set("resolved", automatic);
  j.set("resolved_scene", scene_.resolved_toml);
  write_json_atomic(scene_.directory + "/summary.json", j);
}

}  // namespace arksph
