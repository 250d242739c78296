#include "distributed/distributed_run.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>

#include <sys/resource.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif

#include "boundary/wall_reflection.hpp"
#include "core/errors.hpp"
#include "core/scheme.hpp"
#include "diagnostics/flow_metrics.hpp"
#include "diagnostics/frame_reduction.hpp"
#include "distributed/gather_state.hpp"
#include "distributed/halo_rhs.hpp"
#ifdef ARKSPH_WITH_HYPRE
#include "distributed/halo_projection.hpp"
#include "projection/ConstrainedPressure.hpp"
#endif
#include "distributed/mpi_state_vector.hpp"
#include "distributed/rank_particles.hpp"
#include "distributed/rank_frame.hpp"
#include "distributed/rank_verdict.hpp"
#include "integrate/erk_integrator.hpp"
#include "parallel/migration.hpp"
#include "parallel/rcb.hpp"
#include "io/checkpoint.hpp"
#include "io/pvtp_writer.hpp"
#include "run/checkpointing.hpp"
#include "run/cpu_time.hpp"
#include "run/interrupt.hpp"
#include "run/output_folder.hpp"
#include "run/output_resume.hpp"
#include "run/output_start.hpp"
#include "run/particle_reorder.hpp"
#include "run/progress.hpp"
#include "run/run_output.hpp"
#include "run/setup.hpp"
#include "run/state_check.hpp"

namespace arksph::distributed {

namespace {

// Raises on every rank what the ranks agreed on (all ranks hold the same verdict).
void raise(const Verdict& v) {
  if (v.code == 2) throw InputError(v.message);
  if (v.code == 3) throw NumericalFailure(v.message);
  if (v.code == 5) throw OutputError(v.message);
  if (v.code != 0) throw std::runtime_error(v.message);
}

// Runs body on this rank; its InputError, OutputError or NumericalFailure becomes this rank's
// verdict (2, 5, 3), which every rank then learns.
template <class Body>
void together(const parallel::Communicator& comm, Body&& body) {
  Verdict mine;
  try {
    body();
  } catch (const InputError& e) {
    mine = {2, e.what()};
  } catch (const OutputError& e) {
    mine = {5, e.what()};
  } catch (const NumericalFailure& e) {
    mine = {3, e.what()};
  }
  raise(agree(comm, mine));
}

parallel::Domain domain_of(const Scene& scene) {
  parallel::Domain d;
  d.dim = scene.dimension;
  for (int k = 0; k < scene.dimension; ++k) {
    d.box.lo[k] = scene.min[k];
    d.box.hi[k] = scene.max[k];
    d.periodic[k] = scene.sides[2 * k].kind == SideKind::periodic;
  }
  return d;
}

// Hands the heap's free memory back to the system (glibc), after a rank has held the output's
// buffers: freed blocks below glibc's mmap threshold stay in the heap, where the evaluator's
// storage, built anew after them, cannot always reuse them, and the resident set would keep both.
void return_free_memory() {
#ifdef __GLIBC__
  malloc_trim(0);
#endif
}

parallel::Decomposition bisect(const parallel::CellGrid& grid, const std::vector<std::int64_t>& counts, int ranks,
                               const Scene& scene) {
  try {
    return parallel::Decomposition::rcb(grid, counts, ranks);
  } catch (const std::exception& e) {  // fewer cells of side R than ranks
    throw InputError(scene.source + ": " + std::to_string(ranks) +
                     " ranks: the box cannot be split into that many blocks of cells of the kernel support (" +
                     e.what() + ")");
  }
}

// The bisection of a whole state y (the model's layout): every position wrapped into the box and
// counted per cell (the same counts on every rank, which all hold y).
parallel::Decomposition bisect_state(const parallel::CellGrid& grid, const StateLayout& layout, const double* y,
                                     int ranks, const Scene& scene) {
  const int dim = layout.dim;
  parallel::ParticleFields positions(dim, dim);
  positions.resize(layout.n);
  for (std::size_t a = 0; a < layout.n; ++a) {
    double x[3] = {0, 0, 0};
    for (int k = 0; k < dim; ++k) x[k] = y[layout.pos(k) + a];
    grid.domain().wrap(x);
    for (int k = 0; k < dim; ++k) positions.field[static_cast<std::size_t>(k)][a] = x[k];
  }
  return bisect(grid, parallel::count_per_cell(grid, positions), ranks, scene);
}

}  // namespace

void check_distributable(const Scene& scene, int ranks) {
  const std::string on =
      " is not supported on several MPI ranks (" + std::to_string(ranks) + "); run it as one process";
  const SchemeTraits& traits = scheme_traits(scene.scheme);
  // Projection schemes: isph and isph-gpps with the projection after each step (halo_projection.hpp),
  // with hypre.
  if (!traits.weakly_compressible && !traits.projection)
    throw InputError(scene.source + ": scheme " + scene.scheme + on);
  if (traits.projection) {
#ifndef ARKSPH_WITH_HYPRE
    throw InputError(scene.source + ": scheme " + scene.scheme + " (this build has no hypre for the pressure solve)" + on);
#endif
    if (scene.projection == "orthogonal")
      throw InputError(scene.source + ": method.projection = " + scene.projection + on);
    if (scene.density_correction != "none" && scene.correction_solver == "kinsol")
      throw InputError(scene.source + ": method.correction_solver = " + scene.correction_solver + on);
    if (scene.ppe_operator != "approximate")
      throw InputError(scene.source + ": method.ppe_operator = " + scene.ppe_operator + on);
  }
  if (scene.imex) throw InputError(scene.source + ": time.imex" + on);
  if (scene.dimension != 2)
    throw InputError(scene.source + ": domain dimension " + std::to_string(scene.dimension) + on);
}

RunResult run_distributed(const Scene& scene, const RunOptions& options, const parallel::Communicator& comm) {
  using clock = std::chrono::steady_clock;
  const auto wall_start = clock::now();
  const int ranks = comm.size();
  const bool root = comm.rank() == 0;
  check_distributable(scene, ranks);

  // Set-up: the whole model on every rank; the output folder on rank 0.
  std::optional<Model> built;
  together(comm, [&] { built.emplace(build_model(scene)); });
  Model& model = *built;
  std::unique_ptr<OutputFolder> folder;
  std::string run_id;
  together(comm, [&] {
    if (!root) return;
    folder = std::make_unique<OutputFolder>(scene.directory, scene.source);
    if (!options.overwrite) folder->refuse_foreign_files();
    run_id = start_output_folder(*folder, scene, options);
  });
  RhsEvaluator& rhs = *model.rhs;
  const StateLayout& layout = rhs.layout();
  if (root) {
    std::printf("arksph: scene '%s' (%s) on %d MPI ranks\n", scene.name.c_str(), scene.source.c_str(), ranks);
    std::printf("  scheme %s, %zu particles, dimension %d, dx %.6g, h %.6g, kernel %s, integrator %s\n",
                scene.scheme.c_str(), model.particles.n, scene.dimension, scene.spacing, model.h, scene.kernel.c_str(),
                scene.integrator.c_str());
    std::printf("  output: %s (%s)\n", scene.directory.c_str(),
                scene.pieces ? "a frame piece per rank" : "frames joined on rank 0");
    std::fflush(stdout);
  }
  std::vector<double> y0(layout.size());
  rhs.initial_state(y0.data());
  // The particles dealt to the ranks from a whole state y (at t = 0, a restart and every checkpoint),
  // sorted by cell as one process sorts its own at t = 0 and at its re-sorts (method.reorder_every >
  // 0; 0 keeps the dealt order, as one process keeps its own). No rank evaluates the whole model.
  const parallel::CellGrid grid(domain_of(scene), rhs.kernel().radius());
  std::optional<parallel::Decomposition> decomposition;
  together(comm, [&] { decomposition.emplace(bisect_state(grid, layout, y0.data(), ranks, scene)); });
  RankParticles mine(model.particles, layout, y0.data(), *decomposition, comm.rank());
  const auto sort_mine = [&] {
    if (scene.reorder_every > 0) mine.sort_by_cell(scene.min.data(), rhs.kernel().radius());
  };
  sort_mine();
  // The whole model is never evaluated: the initial state, its evaluator's particle data and the
  // model's initial positions go now (a new deal reads only masses, densities, phases and ids; the
  // initial velocities stay until the state checker has read them).
  std::vector<double>().swap(y0);
  // The constrained projection's rates read the whole model's initial speeds.
  const double flow = scene.pressure_in_f() ? flow_rate(scene, rhs) : 0.0;
  rhs.release_particles();
  for (auto* v : {&model.particles.init_pos[0], &model.particles.init_pos[1]}) std::vector<double>().swap(*v);
  HaloRhs f(scene, model, comm, mine);
  f.set_decomposition(*decomposition);
  // The initial state's fields on the ranks: the number density d0 of every particle by id (C&R's
  // CV, and the frames' reference), and the largest acceleration, which every rank's state checker
  // takes for its speed bound. The rank's evaluator storage is freed before d0 is shared (the next
  // evaluation, at the same state, builds the same neighbour list anew).
  long diagnostic_evals = 1;
  std::vector<double> d0_by_id;
  double accel0 = 0;
  {
    std::vector<double> y = mine.state(), ydot(y.size());
    f.eval(0.0, y.data(), ydot.data());
    accel0 = comm.max(f.local_max_acceleration());
    f.eval(0.0, y.data(), nullptr);  // the fields with their pair list, as a frame's
    std::vector<double> d0 = number_density(f.evaluator().fields());
    d0.resize(mine.size());
    f.release_storage();
    d0_by_id = spread_by_id(comm, mine.ids(), d0, model.particles.n);
    return_free_memory();
  }
  // Restart: the model's particles in the checkpoint's order (every rank read the checkpoint), checked
  // against the scene; rank 0 reads the earlier output before RunOutput truncates it.
  if (options.restart) adopt_particle_order(model, options.restart->id);
  std::optional<Checkpointer> checkpoints;
  together(comm, [&] { checkpoints.emplace(scene, model, options.restart, options.restart_path); });
  checkpoints->set_run_id(run_id);
  const bool restarting = checkpoints->restarting();
  OutputHistory earlier;
  together(comm, [&] {
    if (root && restarting)
      earlier = read_output_history(scene.directory, checkpoints->start_time(), checkpoints->restart().output_frame,
                                    scene.every);
  });
  const StateChecker checker(scene, model, accel0);
  for (auto* v : {&model.particles.init_vel[0], &model.particles.init_vel[1]}) std::vector<double>().swap(*v);
  if (restarting) {  // the checkpoint's state, dealt anew
    const std::vector<double>& yr = checkpoints->restart().state;
    together(comm, [&] { checker.check(checkpoints->start_time(), yr.data()); });  // NaN, blow-up, escape in the file
    together(comm, [&] { decomposition.emplace(bisect_state(grid, layout, yr.data(), ranks, scene)); });
    mine = RankParticles(model.particles, layout, yr.data(), *decomposition, comm.rank());
    sort_mine();
    f.set_decomposition(*decomposition);
  }
  const StateGather gather(model.particles.id, layout);
#ifdef ARKSPH_WITH_HYPRE
  // ISPH: the projection after each step over the ranks, its pressure pinned at the first particle
  // of rank 0's model for the whole run: the set-up's first, or the checkpoint's, which is the
  // set-up's again for a checkpoint written on ranks (so a restart pins the same particle).
  std::unique_ptr<HaloProjection> projection;
  if (model.projection) {
    projection = std::make_unique<HaloProjection>(scene, comm, f, mine, model.particles.id[0], flow);
    for (std::string& term : model.terms)
      if (term == "projection:ppe-" + scene.ppe_solver) term = "projection:ppe-hypre";
      else if (term == "projection:constrained-ppe-" + scene.ppe_solver) term = "projection:constrained-ppe-hypre";
    if (root && scheme_traits(scene.scheme).grid) {
      std::printf("  pressure Poisson equation: on the grid (KLU), the cell sums of every rank's particles all-reduced\n");
      std::fflush(stdout);
    } else if (root) {
      std::printf("  pressure Poisson equation: hypre PCG + BoomerAMG over the ranks, tolerance %g "
                  "(method.ppe_solver = %s applies to one process)\n", scene.ppe_tolerance, scene.ppe_solver.c_str());
      std::fflush(stdout);
    }
  }
#endif
  // The rank's particles changed (migration, a new deal): the projection numbers its rows anew.
  const auto moved = [&] {
#ifdef ARKSPH_WITH_HYPRE
    if (projection) projection->particles_moved();
#endif
  };

  ErkOptions eo = integrator_options(scene);
  eo.state_vector = mpi_state_vector(comm.comm());
  eo.any_rank = [&comm](bool local) { return comm.max(static_cast<std::int64_t>(local)) > 0; };
  eo.describe_entry = [&](std::size_t i, double v) { return describe_rhs_entry(mine.layout(), mine.ids(), i, v); };
  // The largest speed (of y) and acceleration (of the last f) over the ranks: one all-reduce.
  const auto stable = [&](const double* yl) {
    std::vector<double> largest{max_speed(mine.layout(), yl), f.local_max_acceleration()};
    comm.max_in_place(largest);
    return stable_step(scene, model, largest[0], largest[1]);
  };
  eo.stability = [&](double, const double* yl) { return stable(yl); };
#ifdef ARKSPH_WITH_HYPRE
  if (projection && !projection->constrained()) {
    eo.postprocess = [&projection](double tt, double* yl) { projection->project(tt, yl); };
    if (scene.projection_points == "stages")
      eo.postprocess_stage = [&projection](double tt, double* yl) { projection->project_stage(tt, yl); };
  }
#endif
  // A new integrator at (t, the rank's state) with first step h (0: the stability limit) and the
  // counters of the run so far: at the start, on restart, and after each scheduled checkpoint, so
  // that a restart from that checkpoint continues as the run that wrote it (see the header).
  std::unique_ptr<ErkIntegrator> integrator;
  const auto start_integrator = [&](double t, double h, const ErkStats& counters) {
    std::vector<double> y = mine.state();
    {
      std::vector<double> ydot(y.size());
      f.eval(t, y.data(), ydot.data());  // the halo, and the acceleration for the stability limit
    }
    eo.initial_dt = h > 0 ? h : stable(y.data());
    RhsFunction rhs_fn = [&f](double tt, const double* yl, double* yd) { f.eval(tt, yl, yd); };
#ifdef ARKSPH_WITH_HYPRE
    if (projection && projection->constrained())  // the pressure inside f (halo_constrained_pressure.hpp)
      rhs_fn = [&f, &projection](double tt, const double* yl, double* yd) {
        f.eval(tt, yl, yd);
        projection->constrain(yl, yd);
      };
#endif
    integrator = std::make_unique<ErkIntegrator>(std::move(rhs_fn), y, t, eo);
    integrator->set_counter_offset(counters);
  };
#ifdef ARKSPH_WITH_HYPRE
  // A constrained projection starts from a divergence-free velocity (a restart already is).
  if (projection && projection->constrained() && !restarting) {
    std::vector<double> y = mine.state();
    projection->project_initial(0.0, y.data());
    mine.load(y.data());
  }
#endif
  start_integrator(checkpoints->start_time(), restarting ? checkpoints->restart().next_step : 0.0,
                   checkpoints->counters());

  std::unique_ptr<RunOutput> out;
  together(comm, [&] {
    if (!root) return;
    out = std::make_unique<RunOutput>(scene, model, options, run_id);
    if (restarting) {
      out->resume(earlier);
      out->restore_steady(checkpoints->restart().steady_samples, checkpoints->restart().steady_columns);
    }
    checkpoints->set_steady_monitor(&out->steady_monitor());
  });
  if (root && integrator->workaround_installed()) out->add_term("erkstep:fsal_bug_workaround");
  // The whole state on rank 0 (on every rank with `everywhere`), from the integrator's state. A rank
  // that receives it frees its evaluator's storage first (rebuilt at the next evaluation; after a
  // scheduled checkpoint the particles are dealt anew, which rebuilds it anyway).
  const auto whole_state = [&](bool everywhere) {
    mine.load(integrator->state());
    if (everywhere || root) f.release_storage();
    return everywhere ? gather.allgather(comm, mine) : gather.gather(comm, mine);
  };
  // A frame: every rank refreshes its fields at the state and adds its particles and sample points
  // to the frame's diagnostics, which the ranks reduce (diagnostics/frame_reduction.hpp); rank 0
  // writes the CSV row. The particles' rows go to each rank's piece (output.pieces, rank 0 writing
  // the index naming them), or are joined on rank 0 into one file. At the first frame (the next
  // evaluation is at the same state) and the last (none follows), rank 0 frees its evaluator's
  // storage before the join, so that it holds either, not both: a list built anew at the same
  // positions sums the same pairs in the same order, whereas a rebuild at another time would not.
  const bool pieces = scene.pieces && options.write_frames;
  if (root && pieces) out->set_pieces(ranks);
  // The frame's diagnostics at the state the ranks' fields were last refreshed at.
  const auto reduce_diagnostics = [&](double at, FrameReduction& reduction) {
    std::vector<double> d0(mine.size());
    for (std::size_t a = 0; a < mine.size(); ++a) d0[a] = d0_by_id[static_cast<std::size_t>(mine.ids()[a])];
    const parallel::Decomposition& boxes = *decomposition;
    const int me = comm.rank();
    reduction.add({&f.evaluator().fields(), mine.size(), d0.data(), f.evaluator().particles().phase.data()},
                  [&](double x, double y) {
                    double q[3] = {x, y, 0.0};
                    grid.domain().wrap(q);
                    return boxes.owner(q) == me;
                  });
    comm.sum_in_place(reduction.sums());
    comm.max_in_place(reduction.maxima());
    std::vector<double> fluctuations = reduction.fluctuations();
    comm.sum_in_place(fluctuations);
    FrameDiagnostics diag = reduction.finish(at, fluctuations);
    if (scene.poiseuille) diag.poiseuille_profile = comm.gatherv(reduction.profile());
    return diag;
  };
  const auto write_frame = [&](double at, const ErkStats& st) {
    f.eval(at, integrator->state(), nullptr);
    ++diagnostic_evals;
    FrameReduction reduction(scene);
    const FrameDiagnostics diag = reduce_diagnostics(at, reduction);
    std::optional<JoinedFrame> whole;
    if (options.write_frames) {
      std::vector<double> pressure;  // isph: the last projection's, as one process's frame carries it
#ifdef ARKSPH_WITH_HYPRE
      if (projection && projection->stats().solves > 0) pressure = projection->pressure_at(mine.ids(), model.particles.n);
#endif
      const RankFrame rows(at, f, mine, grid.domain(), pressure.empty() ? nullptr : pressure.data(),
                           reduction.number_density());
      if (pieces) {
        const int number = static_cast<int>(comm.max(static_cast<std::int64_t>(root ? out->frames() : 0)));
        together(comm, [&] { rows.write_piece(scene.directory + "/" + piece_file_name(number, comm.rank())); });
      } else if (root && (at <= 0 || at >= scene.end)) {
        const std::vector<FrameRow> own = frame_rows(rows.frame());
        f.release_storage();
        return_free_memory();
        whole.emplace(comm, own, scene.dimension, at, model.particles.n);
      } else {
        whole.emplace(comm, rows.frame(), model.particles.n);
      }
    }
    together(comm, [&] {
      if (root) out->record(diag, st, whole ? &whole->frame() : nullptr);
    });
    if (whole && root) {
      whole.reset();
      return_free_memory();
    }
  };
  if (!restarting) write_frame(0.0, integrator->stats());

  Progress progress(scene.end, options.quiet || !root);
  // Wall reflections: the run's before a restart, and this rank's since (summed over the ranks at
  // each checkpoint and at the end, not at every step).
  const long reflections_before = restarting ? checkpoints->restart().wall_reflections : 0;
  long reflections_here = 0;
  const auto reflections = [&] {
    return reflections_before + static_cast<long>(comm.sum(static_cast<std::int64_t>(reflections_here)));
  };
  long migrations = 0;
  // The fewest particles a rank owned after a deal or a migration (summary.json mpi.fewest_particles).
  std::int64_t fewest = -comm.max(-static_cast<std::int64_t>(mine.size()));
  const auto count_fewest = [&] { fewest = std::min(fewest, -comm.max(-static_cast<std::int64_t>(mine.size()))); };
  double migration_seconds = 0;
  double t = checkpoints->start_time();
  int frame = checkpoints->first_frame();
  int tiny_steps = 0;
  double last_checkpoint = -1;  // time of the last checkpoint written
  RunResult result;
  // At a sync point: the particles to the owners of their positions by a new bisection, the
  // integrator re-initialised on the new local states.
  const auto migrate = [&](double at) {
    const auto t0 = clock::now();
    const double h = integrator->next_step();
    mine.load(integrator->state());
    parallel::ParticleFields& F = mine.fields();
    const RankFieldIndex& ix = mine.index();
    for (std::size_t a = 0; a < F.size(); ++a) {
      double x[3] = {0, 0, 0};
      for (int k = 0; k < ix.dim; ++k) x[k] = F.field[static_cast<std::size_t>(ix.state_pos(k))][a];
      grid.domain().wrap(x);
      for (int k = 0; k < ix.dim; ++k) F.field[static_cast<std::size_t>(ix.seen(k))][a] = x[k];
    }
    std::vector<std::int64_t> counts = parallel::count_per_cell(grid, F);
    comm.sum_in_place(counts);
    decomposition.emplace(bisect(grid, counts, ranks, scene));
    parallel::migrate(comm, *decomposition, F);
    mine.refresh_ids();
    sort_mine();
    f.set_decomposition(*decomposition);
    moved();
    integrator->resize(mine.state(), at, h);
    count_fewest();
    ++migrations;
    migration_seconds += std::chrono::duration<double>(clock::now() - t0).count();
  };
  // The checkpoint of the whole state at t, written by rank 0. Returns the path.
  const auto write_checkpoint_at = [&](double at, const std::vector<double>& all) {
    const long reflected = reflections();
    const double cpu = comm.sum(process_cpu_seconds());  // all ranks' CPU time so far
    together(comm, [&] {
      if (root)
        checkpoints->write_state(at, all.data(), integrator->stats(), integrator->next_step(), frame, reflected, cpu);
    });
    last_checkpoint = at;
    return checkpoints->path();
  };
  // A scheduled checkpoint, when due at t. The run then continues as a restart from it does: the
  // particles dealt anew from the whole state as at a restart (the same bisection and order on any
  // run), and a new integrator at t (no FSAL value or step-size history survives).
  const auto checkpoint_if_due = [&](double at) {
    if (!checkpoints->take_due(at)) return;
    const double h = integrator->next_step();
    const ErkStats counters = integrator->stats();
    const std::vector<double> all = whole_state(true);
    write_checkpoint_at(at, all);
    decomposition.emplace(bisect_state(grid, layout, all.data(), ranks, scene));
    mine = RankParticles(model.particles, layout, all.data(), *decomposition, comm.rank());
    sort_mine();
    f.set_decomposition(*decomposition);
    moved();
    start_integrator(at, h, counters);
    count_fewest();
  };
  double stepping = 0;  // the steps alone (summary.json timing.stepping)
  try {
    while (t < scene.end) {
      double t_next = scene.every > 0 ? scheduled_time(frame, scene.every) : scene.end;
      if (t_next > scene.end * (1 - 1e-12)) t_next = scene.end;
      double dt_max = 0;
      while (t < t_next) {
        const auto step_start = clock::now();
#ifdef ARKSPH_WITH_HYPRE
        if (projection) projection->begin_step(t, integrator->state());
#endif
        t = integrator->step(checkpoints->limit(t_next));  // checkpoint times are stop times too
        const ErkStats st = integrator->stats();
        dt_max = std::max(dt_max, st.last_step);
        Verdict v;
        try {
          if (scene.dt == 0) check_step_size(t, st.last_step, scene.end, tiny_steps);  // the same on every rank
        } catch (const NumericalFailure& e) {
          v = {3, e.what()};
        }
        // This rank's reflections and state check (the reflected state: a migration moves it
        // unchanged), then one all-reduce: the verdict, and whether any rank reflected.
        const long r = static_cast<long>(WallReflection(scene, mine.layout()).apply(integrator->state()));
        reflections_here += r;
        try {
          checker.check(t, integrator->state(), mine.layout(), mine.ids());
        } catch (const NumericalFailure& e) {
          if (!v.code) v = {3, e.what()};
        }
        if (!v.code && st.steps >= scene.max_steps)
          v = {3, "time.max_steps = " + std::to_string(scene.max_steps) + " reached at t = " + std::to_string(t) +
                      " before time.end"};
        if (const int sig = pending_interrupt(); sig && !v.code)
          v = {128 + sig, std::string("interrupted by ") + interrupt_name(sig) + " at t = " + std::to_string(t)};
        std::int64_t reflected = r > 0 ? 1 : 0;
        v = agree(comm, v, reflected);
        if (reflected) integrator->reset(t);  // sync point: every rank re-initialises
        if (v.code) {
          result.exit_code = v.code;
          result.message = v.message;
          break;
        }
        if (scene.reorder_every > 0 && st.steps % scene.reorder_every == 0) migrate(t);
        progress.step(t, st.steps, st.last_step);
        stepping += std::chrono::duration<double>(clock::now() - step_start).count();
        if (t < t_next) checkpoint_if_due(t);
      }
      if (result.exit_code) break;
      ErkStats st = integrator->stats();
      st.last_step = dt_max;
      write_frame(t, st);
      progress.frame(t, st.steps, dt_max);
      ++frame;
      const bool steady = comm.max(static_cast<std::int64_t>(root && out->steady())) > 0;
      if (steady && t < scene.end) {
        if (root) {
          result.steady_time = t;
          result.steady_rate = out->steady_rate();
        }
        break;
      }
      checkpoint_if_due(t);
    }
    if (result.exit_code > 128) {  // a signal: the checkpoint at the last completed step, as one process
      result.interrupted = true;
      result.checkpoint = write_checkpoint_at(t, whole_state(false));
    } else if (!result.exit_code) {  // the last checkpoint, unless the scheduled one was written at t
      result.checkpoint = last_checkpoint == t ? checkpoints->path() : write_checkpoint_at(t, whole_state(false));
    }
  } catch (const NumericalFailure& e) {  // ARKODE gave up: on every rank alike (global norms, agreed flags)
    const Verdict v = agree(comm, {3, e.what(), integrator->failure_names_entry()});
    result.exit_code = v.code;
    result.message = v.message;
  } catch (const OutputError& e) {  // raised on every rank alike (together): keep what still fits, exit 5
    result.exit_code = 5;
    result.message = e.what();
    if (result.message.rfind("cannot write " + checkpoints->path() + ":", 0) != 0) {
      try {
        result.checkpoint = write_checkpoint_at(t, whole_state(false));
      } catch (const OutputError& again) {
        result.message += std::string("; ") + again.what();
      }
    }
  }
  progress.finish();
  const ErkStats st = integrator->stats();
  const double wall = std::chrono::duration<double>(clock::now() - wall_start).count();
  Verdict last{result.exit_code, result.message};
  const long reflected = reflections();
  const double cpu = checkpoints->earlier_cpu_seconds() + comm.sum(process_cpu_seconds());
  // The peak resident memory of every rank (getrusage; kB on Linux), for summary.json.
  std::vector<std::int64_t> peak_kb;
  {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    peak_kb = comm.gatherv(std::vector<std::int64_t>{static_cast<std::int64_t>(usage.ru_maxrss)});
  }
  if (root) {
    Json mpi = Json::object();
    mpi.set("ranks", ranks).set("halo_exchanges", f.exchanges()).set("migrations", migrations);
    mpi.set("fewest_particles", static_cast<long>(fewest));
    Json seconds = Json::object();  // rank 0's wall time in f (distributed/halo_rhs.hpp)
    seconds.set("halo_exchange", f.seconds().exchange).set("halo_update", f.seconds().update);
    seconds.set("evaluator", f.seconds().evaluator);
    mpi.set("seconds", seconds);
    Json peaks = Json::array();
    for (std::int64_t kb : peak_kb) peaks.push(static_cast<long>(kb));
    mpi.set("max_rss_kb", peaks);  // per rank, in rank order
    out->set_mpi(mpi);
    if (scene.reorder_every > 0) out->set_reorders(migrations, migration_seconds);
    out->set_stepping_seconds(stepping);
    out->set_cpu_seconds(cpu);
#ifdef ARKSPH_WITH_HYPRE
    if (projection) out->set_projection_report(projection->stats(), projection->solver_name());
    if (projection && projection->correction()) out->set_correction_report(projection->correction()->stats());
#endif
    try {
      out->finish(result, st, wall, diagnostic_evals, reflected, f.exchanges());
    } catch (const OutputError& e) {
      last = {result.exit_code ? result.exit_code : 5,
              result.message.empty() ? e.what() : result.message + "; " + e.what()};
    }
  }
  last = agree(comm, last);
  if (last.code != result.exit_code) result.checkpoint.clear();
  result.exit_code = last.code;
  result.message = last.message;
  return result;
}

}  // namespace arksph::distributed
