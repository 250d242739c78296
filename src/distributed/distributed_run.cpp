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
#include "distributed/halo_domain.hpp"
#endif
#include "projection/correction/correction_solver.hpp"
#include "projection/projection.hpp"
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
#include "run/run_loop.hpp"
#include "run/run_output.hpp"
#include "run/setup.hpp"
#include "run/state_check.hpp"
#include "run/wall_frame.hpp"
#include "io/vtp_writer.hpp"

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
  // Projection schemes: isph and isph-gpps (projection/projection.hpp over halo_domain.hpp), with
  // hypre.
  if (!traits.weakly_compressible && !traits.projection)
    throw InputError(scene.source + ": scheme " + scene.scheme + on);
  if (traits.projection) {
#ifndef ARKSPH_WITH_HYPRE
    throw InputError(scene.source + ": scheme " + scene.scheme + " (this build has no hypre for the pressure solve)" + on);
#endif
    if (scene.projection_method() == ProjectionMethod::orthogonal)
      throw InputError(scene.source + ": method.projection = " + scene.projection + on);
    const auto* solver = correction_solvers().find(scene.correction_solver);
    if (density_corrections().at(scene.density_correction).traits.corrects_density && solver && solver->traits.one_process)
      throw InputError(scene.source + ": method.correction_solver = " + scene.correction_solver + on);
    if (projection_options().ppe_operator.at(scene.ppe_operator) != PpeOperator::approximate)
      throw InputError(scene.source + ": method.ppe_operator = " + scene.ppe_operator + on);
    if (!scene.fluid_region.empty())  // the surface's p = 0 rows are not in hypre's rows yet
      throw InputError(scene.source + ": fluid.region (a free surface) under scheme " + scene.scheme + on);
  }
  if (scene.imex) throw InputError(scene.source + ": time.imex" + on);
  if (scene.dimension != 2)
    throw InputError(scene.source + ": domain dimension " + std::to_string(scene.dimension) + on);
}

namespace {

using Clock = std::chrono::steady_clock;

// A run over the ranks of `comm`: each rank's particles with their halo, the projection over the
// ranks, migration at the sync points, frames reduced over the ranks and written by rank 0 (or as
// pieces), checkpoints of the state gathered on rank 0.
class DecomposedRun final : public RunStrategy {
 public:
  DecomposedRun(const Scene& scene, const RunOptions& options, const parallel::Communicator& comm);

  double start_time() const override { return checkpoints_->start_time(); }
  int first_frame() const override { return checkpoints_->first_frame(); }
  TimeIntegrator& integrator() override { return *integrator_; }
  void start() override {
    if (!restarting_) write_frame(0.0, integrator_->stats());
  }
  double step(double t, double stop) override {
    if (projection_) projection_->begin_step(t, integrator_->state());
    return integrator_->step(stop);
  }
  double limit(double t_stop) override { return checkpoints_->limit(t_stop); }
  Verdict reflect_and_check(double t, Verdict mine) override;
  Verdict agree_after_step(double t, const Verdict& mine) override;
  void sync_point(double t, long steps) override {
    if (scene_.reorder_every > 0 && steps % scene_.reorder_every == 0) migrate(t);
  }
  void write_frame(double t, const StepStats& stats) override;
  ViscousDissipation* viscous_dissipation() override { return dissipation_ ? &*dissipation_ : nullptr; }
  // The rank's own particles' power at a field refresh of the state, summed over the ranks.
  double viscous_power(double t) override {
    f_->eval(t, integrator_->state(), nullptr);
    ++diagnostic_evals_;
    return comm_.sum(f_->viscous_power(mine_->size()));
  }
  bool steady() override { return comm_.max(static_cast<std::int64_t>(root_ && out_->steady())) > 0; }
  double steady_rate() const override { return root_ ? out_->steady_rate() : 0.0; }
  void checkpoint_if_due(double t, int frame) override;
  std::string checkpoint_at_end(double t, int frame) override {  // unless the scheduled one was written at t
    return last_checkpoint_ == t ? checkpoints_->path() : checkpoint_now(t, frame);
  }
  std::string checkpoint_now(double t, int frame) override { return write_checkpoint(t, whole_state(false), frame); }
  std::string checkpoint_path() const override { return checkpoints_->path(); }
  // ARKODE gave up: on every rank alike (global norms, agreed flags).
  Verdict numerical_failure(double, const std::string& what) override {
    return agree(comm_, {3, what, integrator_->failure_names_entry()});
  }
  Verdict out_of_memory(double) override { throw; }
  void finish(RunResult& result, double wall, double stepping) override;

 private:
  void open_output_folder(const RunOptions& options);
  void deal_initial_state();
  void initial_fields();
  void read_restart(const RunOptions& options);
  void make_projection();
  void set_up_stepping();
  void start_integrator(double t, double h, const StepStats& counters);
  void open_output(const RunOptions& options);
  void sort_mine() {
    if (scene_.reorder_every > 0) mine_->sort_by_cell(scene_.min.data(), model_->rhs->kernel().radius());
  }
  void deal(const double* y);  // the particles of a whole state y dealt to the ranks anew
  void particles_moved();
  double stable(const double* y_local);
  std::vector<double> whole_state(bool everywhere);
  FrameDiagnostics reduce_diagnostics(double at, FrameReduction& reduction);
  void migrate(double at);
  std::string write_checkpoint(double at, const std::vector<double>& all, int frame);
  long reflections() const {
    return reflections_before_ + static_cast<long>(comm_.sum(static_cast<std::int64_t>(reflections_here_)));
  }
  void count_fewest() { fewest_ = std::min(fewest_, -comm_.max(-static_cast<std::int64_t>(mine_->size()))); }

  const Scene& scene_;
  const parallel::Communicator& comm_;
  const int ranks_;
  const bool root_;
  const bool write_frames_;
  const bool pieces_;
  std::optional<Model> model_;
  std::unique_ptr<OutputFolder> folder_;
  std::string run_id_;
  std::optional<parallel::CellGrid> grid_;
  std::optional<parallel::Decomposition> decomposition_;
  std::optional<RankParticles> mine_;
  std::optional<HaloRhs> f_;
  double flow_ = 0;               // the flow rate the constrained projection's rates scale with
  std::vector<double> d0_by_id_;  // number density at t = 0 of every particle, by id
  double accel0_ = 0;             // the largest acceleration at t = 0 over the ranks
  long diagnostic_evals_ = 1;
  std::optional<Checkpointer> checkpoints_;
  bool restarting_ = false;
  OutputHistory earlier_;
  std::optional<StateChecker> checker_;
  std::optional<StateGather> gather_;
  Projection* projection_ = nullptr;  // the model's, over the rank's HaloDomain (with hypre)
  std::vector<std::int64_t> pressure_ids_;  // the ids of the rank's particles at the last projection
  ErkOptions eo_;
  std::unique_ptr<ErkIntegrator> integrator_;
  std::unique_ptr<RunOutput> out_;
  long reflections_before_ = 0;  // the run's before a restart
  long reflections_here_ = 0;    // this rank's since (summed at checkpoints and at the end)
  bool reflected_ = false;       // this rank reflected a particle at the last step
  long migrations_ = 0;
  // The fewest particles a rank owned after a deal or a migration (summary.json mpi.fewest_particles).
  std::int64_t fewest_ = 0;
  double migration_seconds_ = 0;
  double last_checkpoint_ = -1;  // time of the last checkpoint written
  std::optional<ViscousDissipation> dissipation_;  // metrics.energy_budget: the same on every rank
};

DecomposedRun::DecomposedRun(const Scene& scene, const RunOptions& options, const parallel::Communicator& comm)
    : scene_(scene),
      comm_(comm),
      ranks_(comm.size()),
      root_(comm.rank() == 0),
      write_frames_(options.write_frames),
      pieces_(scene.pieces && options.write_frames) {
  check_distributable(scene, ranks_);
  // Set-up: the whole model on every rank; the output folder on rank 0.
  together(comm_, [&] { model_.emplace(build_model(scene)); });
  open_output_folder(options);
  deal_initial_state();
  initial_fields();
  read_restart(options);
  gather_.emplace(model_->particles.id, model_->rhs->layout());
  make_projection();
  set_up_stepping();
  open_output(options);
  reflections_before_ = restarting_ ? checkpoints_->restart().wall_reflections : 0;
  if (scene_.energy_budget) {  // every rank read the checkpoint: each continues the same total
    dissipation_.emplace(checkpoints_->earlier_viscous_dissipation());
    checkpoints_->set_viscous_dissipation(&*dissipation_);
    if (root_) out_->set_viscous_dissipation(&*dissipation_);
  }
}

void DecomposedRun::open_output_folder(const RunOptions& options) {
  together(comm_, [&] {
    if (!root_) return;
    folder_ = std::make_unique<OutputFolder>(scene_.directory, scene_.source);
    if (!options.overwrite) folder_->refuse_foreign_files();
    run_id_ = start_output_folder(*folder_, scene_, options);
  });
  if (root_) {
    std::printf("arksph: scene '%s' (%s) on %d MPI ranks\n", scene_.name.c_str(), scene_.source.c_str(), ranks_);
    std::printf("  scheme %s, %zu particles, dimension %d, dx %.6g, h %.6g, kernel %s, integrator %s\n",
                scene_.scheme.c_str(), model_->particles.n, scene_.dimension, scene_.spacing, model_->h,
                scene_.kernel.c_str(), scene_.integrator.c_str());
    std::printf("  output: %s (%s)\n", scene_.directory.c_str(),
                scene_.pieces ? "a frame piece per rank" : "frames joined on rank 0");
    std::fflush(stdout);
  }
}

// The particles dealt to the ranks from the whole initial state, sorted by cell as one process
// sorts its own at t = 0 and at its re-sorts (method.reorder_every > 0; 0 keeps the dealt order, as
// one process keeps its own). No rank evaluates the whole model: the initial state, its
// evaluator's particle data and the model's initial positions go now (a new deal reads only masses,
// densities, phases and ids; the initial velocities stay until the state checker has read them).
void DecomposedRun::deal_initial_state() {
  RhsEvaluator& rhs = *model_->rhs;
  const StateLayout& layout = rhs.layout();
  std::vector<double> y0(layout.size());
  rhs.initial_state(y0.data());
  grid_.emplace(domain_of(scene_), rhs.kernel().radius());
  together(comm_, [&] { decomposition_.emplace(bisect_state(*grid_, layout, y0.data(), ranks_, scene_)); });
  mine_.emplace(model_->particles, layout, y0.data(), *decomposition_, comm_.rank());
  sort_mine();
  std::vector<double>().swap(y0);
  // The constrained projection's rates read the whole model's initial speeds.
  flow_ = scene_.pressure_in_f() ? flow_rate(scene_, rhs) : 0.0;
  rhs.release_particles();
  for (auto* v : {&model_->particles.init_pos[0], &model_->particles.init_pos[1]}) std::vector<double>().swap(*v);
  f_.emplace(scene_, *model_, comm_, *mine_);
  f_->set_decomposition(*decomposition_);
}

// The initial state's fields on the ranks: the number density d0 of every particle by id (C&R's CV,
// and the frames' reference), and the largest acceleration, which every rank's state checker takes
// for its speed bound. The rank's evaluator storage is freed before d0 is shared (the next
// evaluation, at the same state, builds the same neighbour list anew).
void DecomposedRun::initial_fields() {
  std::vector<double> y = mine_->state(), ydot(y.size());
  f_->eval(0.0, y.data(), ydot.data());
  accel0_ = comm_.max(f_->local_max_acceleration());
  f_->eval(0.0, y.data(), nullptr);  // the fields with their pair list, as a frame's
  std::vector<double> d0 = number_density(f_->evaluator().fields());
  d0.resize(mine_->size());
  f_->release_storage();
  d0_by_id_ = spread_by_id(comm_, mine_->ids(), d0, model_->particles.n);
  return_free_memory();
}

// Restart: the model's particles in the checkpoint's order (every rank read the checkpoint), checked
// against the scene; rank 0 reads the earlier output before RunOutput truncates it. The
// checkpoint's state is dealt anew.
void DecomposedRun::read_restart(const RunOptions& options) {
  if (options.restart) adopt_particle_order(*model_, options.restart->id);
  together(comm_, [&] { checkpoints_.emplace(scene_, *model_, options.restart, options.restart_path); });
  checkpoints_->set_run_id(run_id_);
  restarting_ = checkpoints_->restarting();
  together(comm_, [&] {
    if (root_ && restarting_)
      earlier_ = read_output_history(scene_.directory, checkpoints_->start_time(), checkpoints_->restart().output_frame,
                                     scene_.every);
  });
  checker_.emplace(scene_, *model_, accel0_);
  for (auto* v : {&model_->particles.init_vel[0], &model_->particles.init_vel[1]}) std::vector<double>().swap(*v);
  if (!restarting_) return;
  const std::vector<double>& yr = checkpoints_->restart().state;
  together(comm_, [&] { checker_->check(checkpoints_->start_time(), yr.data()); });  // NaN, blow-up, escape in the file
  together(comm_, [&] { decomposition_.emplace(bisect_state(*grid_, model_->rhs->layout(), yr.data(), ranks_, scene_)); });
  *mine_ = RankParticles(model_->particles, model_->rhs->layout(), yr.data(), *decomposition_, comm_.rank());
  sort_mine();
  f_->set_decomposition(*decomposition_);
}

// ISPH: the projection after each step over the ranks, its pressure pinned at the first particle
// of rank 0's model for the whole run: the set-up's first, or the checkpoint's, which is the
// set-up's again for a checkpoint written on ranks (so a restart pins the same particle).
void DecomposedRun::make_projection() {
#ifdef ARKSPH_WITH_HYPRE
  if (!model_->projection) return;
  // The model's projection becomes the rank's: summary.json reports it as one process's.
  model_->projection = std::make_unique<Projection>(
      scene_, std::make_unique<HaloDomain>(comm_, *f_, *mine_, model_->particles.id[0]), flow_);
  projection_ = model_->projection.get();
  for (std::string& term : model_->terms)
    if (term == "projection:ppe-" + scene_.ppe_solver) term = "projection:ppe-hypre";
    else if (term == "projection:constrained-ppe-" + scene_.ppe_solver) term = "projection:constrained-ppe-hypre";
  if (root_ && scheme_traits(scene_.scheme).grid) {
    std::printf("  pressure Poisson equation: on the grid (KLU), the cell sums of every rank's particles all-reduced\n");
    std::fflush(stdout);
  } else if (root_) {
    std::printf("  pressure Poisson equation: hypre PCG + BoomerAMG over the ranks, tolerance %g "
                "(method.ppe_solver = %s applies to one process)\n", scene_.ppe_tolerance, scene_.ppe_solver.c_str());
    std::fflush(stdout);
  }
#endif
}

// The rank's particles changed (migration, a new deal): the projection numbers its rows anew.
void DecomposedRun::particles_moved() {
  if (projection_) projection_->particles_moved();
}

// The largest speed (of y) and acceleration (of the last f) over the ranks: one all-reduce.
double DecomposedRun::stable(const double* y_local) {
  std::vector<double> largest{max_speed(mine_->layout(), y_local), f_->local_max_acceleration()};
  comm_.max_in_place(largest);
  return stable_step(scene_, *model_, largest[0], largest[1]);
}

void DecomposedRun::set_up_stepping() {
  eo_ = integrator_options(scene_);
  eo_.state_vector = mpi_state_vector(comm_.comm());
  eo_.any_rank = [this](bool local) { return comm_.max(static_cast<std::int64_t>(local)) > 0; };
  eo_.describe_entry = [this](std::size_t i, double v) { return describe_rhs_entry(mine_->layout(), mine_->ids(), i, v); };
  eo_.stability = [this](double, const double* yl) { return stable(yl); };
  if (projection_ && !projection_->constrained()) {
    eo_.postprocess = [this](double tt, double* yl) {
      projection_->project(tt, yl);
      pressure_ids_ = mine_->ids();
    };
    if (projection_options().projection_points.at(scene_.projection_points) == ProjectionPoints::stages)
      eo_.postprocess_stage = [this](double tt, double* yl) {
        projection_->project_stage(tt, yl);
        pressure_ids_ = mine_->ids();
      };
  }
  // A constrained projection starts from a divergence-free velocity (a restart already is).
  if (projection_ && projection_->constrained() && !restarting_) {
    std::vector<double> y = mine_->state();
    projection_->project_initial(0.0, y.data());
    mine_->load(y.data());
  }
  start_integrator(checkpoints_->start_time(), restarting_ ? checkpoints_->restart().next_step : 0.0,
                   checkpoints_->counters());
}

// A new integrator at (t, the rank's state) with first step h (0: the stability limit) and the
// counters of the run so far: at the start, on restart, and after each scheduled checkpoint, so
// that a restart from that checkpoint continues as the run that wrote it (distributed_run.hpp).
void DecomposedRun::start_integrator(double t, double h, const StepStats& counters) {
  std::vector<double> y = mine_->state();
  {
    std::vector<double> ydot(y.size());
    f_->eval(t, y.data(), ydot.data());  // the halo, and the acceleration for the stability limit
  }
  eo_.initial_dt = h > 0 ? h : stable(y.data());
  HaloRhs& f = *f_;
  RhsFunction rhs_fn = [&f](double tt, const double* yl, double* yd) { f.eval(tt, yl, yd); };
  if (projection_ && projection_->constrained())  // the pressure inside f (projection/ConstrainedPressure.hpp)
    rhs_fn = [&f, this](double tt, const double* yl, double* yd) {
      f.eval(tt, yl, yd);
      projection_->constrain(yl, yd);
      pressure_ids_ = mine_->ids();
    };
  integrator_ = std::make_unique<ErkIntegrator>(std::move(rhs_fn), y, t, eo_);
  integrator_->set_counter_offset(counters);
}

void DecomposedRun::open_output(const RunOptions& options) {
  together(comm_, [&] {
    if (!root_) return;
    out_ = std::make_unique<RunOutput>(scene_, *model_, options, run_id_);
    if (restarting_) {
      out_->resume(earlier_);
      out_->restore_steady(checkpoints_->restart().steady_samples, checkpoints_->restart().steady_columns);
    }
    checkpoints_->set_steady_monitor(&out_->steady_monitor());
  });
  if (root_ && integrator_->workaround_installed()) out_->add_term("erkstep:fsal_bug_workaround");
  if (root_ && pieces_) out_->set_pieces(ranks_);
  fewest_ = -comm_.max(-static_cast<std::int64_t>(mine_->size()));
}

// The whole state on rank 0 (on every rank with `everywhere`), from the integrator's state. A rank
// that receives it frees its evaluator's storage first (rebuilt at the next evaluation; after a
// scheduled checkpoint the particles are dealt anew, which rebuilds it anyway).
std::vector<double> DecomposedRun::whole_state(bool everywhere) {
  mine_->load(integrator_->state());
  if (everywhere || root_) f_->release_storage();
  return everywhere ? gather_->allgather(comm_, *mine_) : gather_->gather(comm_, *mine_);
}

// The frame's diagnostics at the state the ranks' fields were last refreshed at.
FrameDiagnostics DecomposedRun::reduce_diagnostics(double at, FrameReduction& reduction) {
  std::vector<double> d0(mine_->size());
  for (std::size_t a = 0; a < mine_->size(); ++a) d0[a] = d0_by_id_[static_cast<std::size_t>(mine_->ids()[a])];
  const parallel::Decomposition& boxes = *decomposition_;
  const parallel::Domain& domain = grid_->domain();
  const int me = comm_.rank();
  reduction.add({&f_->evaluator().fields(), mine_->size(), d0.data(), f_->evaluator().particles().phase.data()},
                [&](double x, double y) {
                  double q[3] = {x, y, 0.0};
                  domain.wrap(q);
                  return boxes.owner(q) == me;
                });
  comm_.sum_in_place(reduction.sums());
  comm_.max_in_place(reduction.maxima());
  std::vector<double> fluctuations = reduction.fluctuations();
  comm_.sum_in_place(fluctuations);
  FrameDiagnostics diag = reduction.finish(at, fluctuations);
  if (scene_.poiseuille) diag.poiseuille_profile = comm_.gatherv(reduction.profile());
  return diag;
}

// A frame: every rank refreshes its fields at the state and adds its particles and sample points
// to the frame's diagnostics, which the ranks reduce (diagnostics/frame_reduction.hpp); rank 0
// writes the CSV row. The particles' rows go to each rank's piece (output.pieces, rank 0 writing
// the index naming them), or are joined on rank 0 into one file. At the first frame (the next
// evaluation is at the same state) and the last (none follows), rank 0 frees its evaluator's
// storage before the join, so that it holds either, not both: a list built anew at the same
// positions sums the same pairs in the same order, whereas a rebuild at another time would not.
void DecomposedRun::write_frame(double at, const StepStats& st) {
  f_->eval(at, integrator_->state(), nullptr);
  ++diagnostic_evals_;
  FrameReduction reduction(scene_, model_->sound_speed);
  const FrameDiagnostics diag = reduce_diagnostics(at, reduction);
  std::optional<JoinedFrame> whole;
  std::optional<JoinedWalls> walls;  // output.walls, joined on rank 0 (without pieces)
  if (write_frames_) {
    std::vector<double> pressure;  // isph: the last projection's, as one process's frame carries it
    if (projection_ && projection_->stats().solves > 0) {  // by id: the particles may have migrated since
      const std::vector<double> by_id = spread_by_id(comm_, pressure_ids_, projection_->pressure(), model_->particles.n);
      for (std::int64_t id : mine_->ids()) pressure.push_back(by_id[static_cast<std::size_t>(id)]);
    }
    const RankFrame rows(at, *f_, *mine_, grid_->domain(), pressure.empty() ? nullptr : pressure.data(),
                         reduction.number_density(), !scene_.fluid_region.empty());
    std::optional<WallFrame> my_walls;  // the wall points of the rank's particles (run/wall_frame.hpp)
    if (scene_.walls)
      my_walls.emplace(scene_, f_->evaluator().fields(), rows.frame(), f_->evaluator().kernel().radius(), true);
    if (pieces_) {
      const int number = static_cast<int>(comm_.max(static_cast<std::int64_t>(root_ ? out_->frames() : 0)));
      together(comm_, [&] {
        rows.write_piece(scene_.directory + "/" + piece_file_name(number, comm_.rank()));
        if (my_walls) write_vtp(scene_.directory + "/" + piece_file_name(number, comm_.rank(), "walls"), my_walls->frame());
      });
    } else {
      if (my_walls) walls.emplace(comm_, my_walls->frame());
      if (root_ && (at <= 0 || at >= scene_.end)) {
        const std::vector<FrameRow> own = frame_rows(rows.frame());
        f_->release_storage();
        return_free_memory();
        whole.emplace(comm_, own, scene_.dimension, at, model_->particles.n, !scene_.fluid_region.empty());
      } else {
        whole.emplace(comm_, rows.frame(), model_->particles.n);
      }
    }
  }
  together(comm_, [&] {
    if (root_) out_->record(diag, st, whole ? &whole->frame() : nullptr, walls ? &walls->frame() : nullptr);
  });
  if (whole && root_) {
    whole.reset();
    return_free_memory();
  }
}

// This rank's reflections and state check (the reflected state: a migration moves it unchanged).
Verdict DecomposedRun::reflect_and_check(double t, Verdict v) {
  const long r = static_cast<long>(WallReflection(scene_, mine_->layout()).apply(integrator_->state()));
  reflections_here_ += r;
  reflected_ = r > 0;
  try {
    checker_->check(t, integrator_->state(), mine_->layout(), mine_->ids());
  } catch (const NumericalFailure& e) {
    if (!v.code) v = {3, e.what()};
  }
  return v;
}

// One all-reduce: the verdict, and whether any rank reflected (then every rank re-initialises).
Verdict DecomposedRun::agree_after_step(double t, const Verdict& mine) {
  std::int64_t reflected = reflected_ ? 1 : 0;
  const Verdict v = agree(comm_, mine, reflected);
  if (reflected) integrator_->reset(t);
  return v;
}

// At a sync point: the particles to the owners of their positions by a new bisection, the
// integrator re-initialised on the new local states.
void DecomposedRun::migrate(double at) {
  const auto t0 = Clock::now();
  const double h = integrator_->next_step();
  mine_->load(integrator_->state());
  parallel::ParticleFields& F = mine_->fields();
  const RankFieldIndex& ix = mine_->index();
  for (std::size_t a = 0; a < F.size(); ++a) {
    double x[3] = {0, 0, 0};
    for (int k = 0; k < ix.dim; ++k) x[k] = F.field[static_cast<std::size_t>(ix.state_pos(k))][a];
    grid_->domain().wrap(x);
    for (int k = 0; k < ix.dim; ++k) F.field[static_cast<std::size_t>(ix.seen(k))][a] = x[k];
  }
  std::vector<std::int64_t> counts = parallel::count_per_cell(*grid_, F);
  comm_.sum_in_place(counts);
  decomposition_.emplace(bisect(*grid_, counts, ranks_, scene_));
  parallel::migrate(comm_, *decomposition_, F);
  mine_->refresh_ids();
  sort_mine();
  f_->set_decomposition(*decomposition_);
  particles_moved();
  integrator_->resize(mine_->state(), at, h);
  count_fewest();
  ++migrations_;
  migration_seconds_ += std::chrono::duration<double>(Clock::now() - t0).count();
}

// The checkpoint of the whole state at t, written by rank 0. Returns the path.
std::string DecomposedRun::write_checkpoint(double at, const std::vector<double>& all, int frame) {
  const long reflected = reflections();
  const double cpu = comm_.sum(process_cpu_seconds());  // all ranks' CPU time so far
  together(comm_, [&] {
    if (root_)
      checkpoints_->write_state(at, all.data(), integrator_->stats(), integrator_->next_step(), frame, reflected, cpu);
  });
  last_checkpoint_ = at;
  return checkpoints_->path();
}

// A scheduled checkpoint, when due at t. The run then continues as a restart from it does: the
// particles dealt anew from the whole state as at a restart (the same bisection and order on any
// run), and a new integrator at t (no FSAL value or step-size history survives).
void DecomposedRun::checkpoint_if_due(double at, int frame) {
  if (!checkpoints_->take_due(at)) return;
  const double h = integrator_->next_step();
  const StepStats counters = integrator_->stats();
  const std::vector<double> all = whole_state(true);
  write_checkpoint(at, all, frame);
  const StateLayout& layout = model_->rhs->layout();
  decomposition_.emplace(bisect_state(*grid_, layout, all.data(), ranks_, scene_));
  *mine_ = RankParticles(model_->particles, layout, all.data(), *decomposition_, comm_.rank());
  sort_mine();
  f_->set_decomposition(*decomposition_);
  particles_moved();
  start_integrator(at, h, counters);
  count_fewest();
}

// summary.json on rank 0, with what the decomposition did; then the ranks agree on the outcome.
void DecomposedRun::finish(RunResult& result, double wall, double stepping) {
  const StepStats st = integrator_->stats();
  Verdict last{result.exit_code, result.message};
  const long reflected = reflections();
  const double cpu = checkpoints_->earlier_cpu_seconds() + comm_.sum(process_cpu_seconds());
  // The peak resident memory of every rank (getrusage; kB on Linux), for summary.json.
  std::vector<std::int64_t> peak_kb;
  {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    peak_kb = comm_.gatherv(std::vector<std::int64_t>{static_cast<std::int64_t>(usage.ru_maxrss)});
  }
  if (root_) {
    Json mpi = Json::object();
    mpi.set("ranks", ranks_).set("halo_exchanges", f_->exchanges()).set("migrations", migrations_);
    mpi.set("fewest_particles", static_cast<long>(fewest_));
    Json seconds = Json::object();  // rank 0's wall time in f (distributed/halo_rhs.hpp)
    seconds.set("halo_exchange", f_->seconds().exchange).set("halo_update", f_->seconds().update);
    seconds.set("evaluator", f_->seconds().evaluator);
    mpi.set("seconds", seconds);
    Json peaks = Json::array();
    for (std::int64_t kb : peak_kb) peaks.push(static_cast<long>(kb));
    mpi.set("max_rss_kb", peaks);  // per rank, in rank order
    out_->set_mpi(mpi);
    if (scene_.reorder_every > 0) out_->set_reorders(migrations_, migration_seconds_);
    out_->set_stepping_seconds(stepping);
    out_->set_cpu_seconds(cpu);
    try {
      out_->finish(result, st, wall, diagnostic_evals_, reflected, f_->exchanges());
    } catch (const OutputError& e) {
      last = {result.exit_code ? result.exit_code : 5,
              result.message.empty() ? e.what() : result.message + "; " + e.what()};
    }
  }
  last = agree(comm_, last);
  if (last.code != result.exit_code) result.checkpoint.clear();
  result.exit_code = last.code;
  result.message = last.message;
}

}  // namespace

RunResult run_distributed(const Scene& scene, const RunOptions& options, const parallel::Communicator& comm) {
  const auto wall_start = Clock::now();
  DecomposedRun run(scene, options, comm);
  return run_loop(scene, run, options.quiet || comm.rank() != 0, options.progress_every, wall_start);
}

}  // namespace arksph::distributed
