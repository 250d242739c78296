#include "run/model_run.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "core/errors.hpp"
#include "integrate/time_params.hpp"
#include "projection/ppe_assembly.hpp"
#include "run/cpu_time.hpp"
#include "run/failure_diagnosis.hpp"
#include "run/output_resume.hpp"
#include "run/output_start.hpp"
#include "run/particle_reorder.hpp"
#include "run/wall_frame.hpp"

namespace arksph {

void raise(const Verdict& v) {
  if (v.code == 2) throw InputError(v.message);
  if (v.code == 3) throw NumericalFailure(v.message);
  if (v.code == 5) throw OutputError(v.message);
  if (v.code != 0) throw std::runtime_error(v.message);
}

namespace {

void print_run_header(const Scene& scene, const Model& model, const RunProcess& process) {
  std::printf("arksph: scene '%s' (%s)%s\n", scene.name.c_str(), scene.source.c_str(), process.where().c_str());
  std::printf("  scheme %s, %zu particles, dimension %d, dx %.6g, h %.6g, kernel %s\n", scene.scheme.c_str(),
              model.particles.n, scene.dimension, scene.spacing, model.h, scene.kernel.c_str());
  std::string chosen;  // the keys given as "auto" that this run uses, and what their rules chose
  for (const auto& [key, value] : scene.automatic)
    if (std::find(scene.automatic_unused.begin(), scene.automatic_unused.end(), key) == scene.automatic_unused.end())
      chosen += (chosen.empty() ? " " : ", ") + key + " = " + value;
  if (!chosen.empty()) std::printf("  auto:%s\n", chosen.c_str());
  if (model.sound_speed > 0) std::printf("  sound speed %.6g\n", model.sound_speed);
  if (model.reference_speed > 0) std::printf("  flow speed U %.6g (scale of the regularisation velocity)\n", model.reference_speed);
  if (model.projection && model.projection->constrained()) {
    const ConstrainedPressure& c = *model.projection->constraint();
    std::printf("  %s projection, divergence relaxation rate %.6g", projection_methods().name(scene.projection).c_str(), c.relaxation());
    if (c.density_relaxation())  // the P-W correction as a velocity in dr/dt
      std::printf(", density relaxation rate %.6g", c.density_relaxation()->rate());
    std::printf("\n");
  }
  const std::string method = scene.imex ? "ARKStep IMEX " + scene.imex_pair + " (viscosity implicit)" : scene.integrator;
  std::string stepping = "adaptive dt (stability limited)";
  if (scene.dt > 0) {
    const Tolerances tol = integrator_tolerances(scene, scene.dt);
    char text[160];
    std::snprintf(text, sizeof text, scene.imex ? "fixed dt %g (implicit stages solved to rtol %g, atol %g)" : "fixed dt %g",
                  scene.dt, tol.rtol, tol.atol);
    stepping = text;
  }
  std::printf("  integrator %s, %s, end time %g\n", method.c_str(), stepping.c_str(), scene.end);
  if (scene.steady_tolerance > 0) {  // diagnostics/steady_state.hpp
    char window[96] = "the latest output interval";
    if (scene.steady_window > 0 && scene.steady_measure == SteadyMeasure::window_means)
      std::snprintf(window, sizeof window, "the means of two windows of %g of simulated time", scene.steady_window);
    else if (scene.steady_window > 0)
      std::snprintf(window, sizeof window, "every output interval of the last %g of simulated time", scene.steady_window);
    std::printf("  stops at steady state: change rate of the kinetic energy%s below %g per unit time over %s\n",
                scene.ghia_re ? " and the Ghia centreline velocities" : "", scene.steady_tolerance, window);
  }
  std::printf("  terms:");
  for (const auto& t : model.terms) std::printf(" %s", t.c_str());
  std::printf("\n  output: %s%s\n", scene.directory.c_str(), process.frame_form().c_str());
  std::fflush(stdout);
}

}  // namespace

ModelRun::ModelRun(const Scene& scene, const RunOptions& options, RunProcess& process)
    : scene_(scene), process_(process), root_(process.root()), write_frames_(options.write_frames) {
  process_.refuse_unsupported(scene);
  process_.together([&] { model_.emplace(build_model(scene)); });
  process_.built(*model_);
  open_output_folder(options);
  process_.initial_state(*model_);
  // Restart: the particles in the checkpoint's order (re-sorts, method.reorder_every); the
  // checkpoint checked against the scene, the earlier output read before RunOutput truncates it.
  if (options.restart) process_.adopted_order(adopt_particle_order(*model_, options.restart->id));
  process_.together([&] { checkpoints_.emplace(scene, *model_, options.restart, options.restart_path); });
  checkpoints_->set_run_id(run_id_);
  const bool restarting = checkpoints_->restarting();
  OutputHistory earlier;
  process_.together([&] {
    if (root_ && restarting)
      earlier = read_output_history(scene.directory, checkpoints_->start_time(), checkpoints_->restart().output_frame,
                                    scene.every);
  });
  open_output(options, earlier);
  if (scene.energy_budget) {  // every process read the checkpoint: each continues the same total
    dissipation_.emplace(checkpoints_->earlier_viscous_dissipation());
    checkpoints_->set_viscous_dissipation(&*dissipation_);
    if (out_) out_->set_viscous_dissipation(&*dissipation_);
  }
  const double t0 = checkpoints_->start_time();
  if (restarting)  // NaN, blow-up, escape in the file
    process_.together([&] {
      StateChecker(scene, *model_, process_.initial_acceleration()).check(t0, checkpoints_->restart().state.data());
    });
  diagnostic_evals_ =
      process_.start_stepping(t0, restarting ? &checkpoints_->restart() : nullptr, checkpoints_->counters());
  checker_.emplace(scene, *model_, process_.initial_acceleration());
  if (out_ && integrator().workaround_installed()) out_->add_term("erkstep:fsal_bug_workaround");
  reflections_before_ = restarting ? checkpoints_->restart().wall_reflections : 0;
}

void ModelRun::open_output_folder(const RunOptions& options) {
  process_.together([&] {
    if (!root_) return;
    folder_ = std::make_unique<OutputFolder>(scene_.directory, scene_.source);
    if (!options.overwrite) folder_->refuse_foreign_files();
    run_id_ = start_output_folder(*folder_, scene_, options);
  });
  if (root_) print_run_header(scene_, *model_, process_);
}

void ModelRun::open_output(const RunOptions& options, const OutputHistory& earlier) {
  process_.together([&] {
    if (!root_) return;
    out_.emplace(scene_, *model_, options, run_id_, process_.pieces());  // truncates timeseries.csv
    if (checkpoints_->restarting()) {
      out_->resume(earlier);
      out_->restore_steady(checkpoints_->restart().steady_samples, checkpoints_->restart().steady_columns);
    }
    checkpoints_->set_steady_monitor(&out_->steady_monitor());
  });
}

void ModelRun::start() {
  process_.poll_interrupt();
  if (!checkpoints_->restarting()) write_frame(0.0, integrator().stats());
  process_.poll_interrupt();
  process_.started();
}

// A frame: every process refreshes its fields at the state and adds its particles and sample
// points to the frame's diagnostics, which the processes reduce (diagnostics/frame_reduction.hpp);
// the root writes the CSV row, the process the rows (RunProcess::write_rows).
void ModelRun::write_frame(double t, const StepStats& stats) {
  const FrameSource src = process_.frame_source(t);
  ++diagnostic_evals_;
  FrameReduction reduction(scene_, model_->sound_speed);
  reduction.add(src.particles, src.owns);
  process_.sum_in_place(reduction.sums());
  process_.max_in_place(reduction.maxima());
  std::vector<double> fluctuations = reduction.fluctuations();
  process_.sum_in_place(fluctuations);
  FrameDiagnostics diag = reduction.finish(t, fluctuations);
  if (scene_.poiseuille) diag.poiseuille_profile = process_.gather(reduction.profile());
  const FluidFields& f = *src.particles.f;
  const std::size_t n = src.particles.n;
  std::vector<double> rho_sum = reduction.number_density();  // Szewc eq. 21: m_a sum_b W_ab
  for (std::size_t a = 0; a < n; ++a) rho_sum[a] *= f.m[a];
  Frame mine;
  mine.dimension = scene_.dimension;
  mine.n = n;
  mine.time = t;
  mine.x = src.x;
  mine.y = src.y;
  mine.u = f.u.data();
  mine.v = scene_.dimension == 2 ? f.v.data() : nullptr;
  mine.pressure = src.pressure;
  mine.density = f.rho.data();
  mine.summation_density = rho_sum.data();
  mine.mass = f.m.data();
  mine.id = src.id;
  mine.phase = src.particles.phase;
  mine.smoothing_length = model_->h;
  std::vector<std::uint8_t> surface;  // fluid.region: the free-surface particles (Lind et al. 2012)
  if (!scene_.fluid_region.empty() && write_frames_) {  // the process's particles first in f, its halo copies after
    const std::vector<char> s = free_surface_particles(f, free_surface_threshold(scene_.dimension));
    surface.assign(s.begin(), s.begin() + static_cast<long>(n));
    mine.free_surface = surface.data();
  }
  std::optional<WallFrame> walls;  // output.walls: the wall points of the process's particles
  if (scene_.walls && write_frames_) walls.emplace(scene_, f, mine, src.support, src.halo_copies);
  process_.write_rows(diag, stats, mine, walls ? &walls->frame() : nullptr, out_ ? &*out_ : nullptr);
}

// This process's reflections and state check (the reflected state: a migration moves it unchanged).
Verdict ModelRun::reflect_and_check(double t, Verdict mine) {
  reflected_ = false;
  if (mine.code) return mine;
  const long r = process_.reflect();
  reflections_here_ += static_cast<double>(r);
  reflected_ = r > 0;
  try {
    process_.check(*checker_, t);
  } catch (const NumericalFailure& e) {
    return {3, e.what()};
  }
  return mine;
}

// One agreement: the verdict, and whether any process reflected (then every one re-initialises).
Verdict ModelRun::agree_after_step(double t, const Verdict& mine) {
  std::int64_t reflected = reflected_ ? 1 : 0;
  const Verdict v = process_.agree(mine, reflected);
  if (reflected) integrator().reset(t);
  return v;
}

// The checkpoint of the whole state y at t, written by the root. Returns the path.
std::string ModelRun::write_checkpoint(double t, const double* y, int frame) {
  const long reflected = reflections();
  const double cpu = process_.sum(process_cpu_seconds());  // all processes' CPU time so far
  const StepStats st = integrator().stats();
  const double next = integrator().next_step();
  process_.together([&] {
    if (root_) checkpoints_->write_state(t, y, st, next, frame, reflected, cpu);
  });
  last_checkpoint_ = t;
  return checkpoints_->path();
}

std::string ModelRun::checkpoint_now(double t, int frame) {
  process_.with_whole_state(false, [&](const double* y) { write_checkpoint(t, y, frame); });
  return checkpoints_->path();
}

// A scheduled checkpoint, when due at t. The run then continues as a restart from it does
// (run/checkpointing.hpp).
void ModelRun::checkpoint_if_due(double t, int frame) {
  if (!checkpoints_->take_due(t)) return;
  const double h = integrator().next_step();
  const StepStats counters = integrator().stats();
  process_.with_whole_state(true, [&](const double* y) {
    write_checkpoint(t, y, frame);
    process_.continue_from_checkpoint(t, h, counters, y);
  });
}

// summary.json on the root; then the processes agree on the outcome.
void ModelRun::finish(RunResult& result, double wall, double stepping) {
  RunTotals totals;
  totals.wall_seconds = wall;
  totals.stepping_seconds = stepping;
  totals.cpu_seconds = checkpoints_->earlier_cpu_seconds() + process_.sum(process_cpu_seconds());
  totals.diagnostic_evals = diagnostic_evals_;
  totals.wall_reflections = reflections();
  process_.report(totals);
  if (result.exit_code == 3) result.message += known_limit(scene_);
  Verdict last{result.exit_code, result.message};
  if (out_) {
    try {
      out_->finish(result, integrator().stats(), totals);
    } catch (const OutputError& e) {  // the summary not written: exit 5 unless the run failed otherwise
      last = {result.exit_code && result.exit_code != 5 ? result.exit_code : 5,
              result.message.empty() ? e.what() : result.message + "; " + e.what()};
    }
  }
  last = process_.agree(last);
  if (last.code != result.exit_code || (last.code == 5 && last.message != result.message)) result.checkpoint.clear();
  result.exit_code = last.code;
  result.message = last.message;
}

RunResult run_model(const Scene& scene, const RunOptions& options, RunProcess& process,
                    std::chrono::steady_clock::time_point wall_start) {
  ModelRun run(scene, options, process);
  return run_loop(scene, run, options.quiet || !process.root(), options.progress_every, wall_start);
}

}  // namespace arksph
