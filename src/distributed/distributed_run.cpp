#include "distributed/distributed_run.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>

#include <sys/resource.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif

#include "boundary/wall_reflection.hpp"
#include "core/errors.hpp"
#include "core/scheme.hpp"
#include "core/seconds_since.hpp"
#include "diagnostics/flow_metrics.hpp"
#include "distributed/halo_rhs.hpp"
#ifdef ARKSPH_WITH_HYPRE
#include "distributed/halo_domain.hpp"
#endif
#include "distributed/mpi_state_vector.hpp"
#include "distributed/rank_frame.hpp"
#include "distributed_ppe/rank_poisson_solver.hpp"
#include "integrate/erk_integrator.hpp"
#include "integrate/imex_integrator.hpp"
#include "io/frame_order.hpp"
#include "io/pvtp_writer.hpp"
#include "io/vtp_writer.hpp"
#include "parallel/agreement.hpp"
#include "parallel/join_by_id.hpp"
#include "parallel/migration.hpp"
#include "parallel/rank_particles.hpp"
#include "parallel/rcb.hpp"
#include "projection/correction/correction_solver.hpp"
#include "projection/projection.hpp"
#include "run/model_run.hpp"
#include "run/time_stepper.hpp"

namespace arksph::distributed {

namespace {

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
  std::vector<std::int64_t> counts(grid.cells(), 0);
  for (std::size_t a = 0; a < layout.n; ++a) {
    double x[3] = {0, 0, 0};
    for (int k = 0; k < layout.dim; ++k) x[k] = y[layout.pos(k) + a];
    grid.domain().wrap(x);
    ++counts[grid.cell_of(x)];
  }
  return bisect(grid, counts, ranks, scene);
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
    const std::vector<std::string> rank_solvers = distributed_ppe::rank_poisson_solver_names();
    if (std::find(rank_solvers.begin(), rank_solvers.end(), scene.rank_ppe_solver) == rank_solvers.end())
      throw InputError(scene.source + ": method.rank_ppe_solver = \"" + scene.rank_ppe_solver +
                       "\" is not built in (this build has no hypre)");
    if (scene.projection == ProjectionMethod::orthogonal)
      throw InputError(scene.source + ": method.projection = " + projection_methods().name(scene.projection) + on);
    const auto* solver = correction_solvers().find(scene.correction_solver);
    if (density_corrections().at(scene.density_correction).traits.corrects_density && solver && solver->traits.one_process)
      throw InputError(scene.source + ": method.correction_solver = " + scene.correction_solver + on);
    if (scene.ppe_operator != PpeOperator::approximate)
      throw InputError(scene.source + ": method.ppe_operator = " + projection_options().ppe_operator.name(scene.ppe_operator) + on);
  }
  // time.imex: ARKStep with the Krylov solve (KrylovViscousSplit, integrate/viscous_split.hpp); a projection
  // is inside f_E there (the scene reader admits time.imex only with one).
  if (scene.dimension != 2)
    throw InputError(scene.source + ": domain dimension " + std::to_string(scene.dimension) + on);
}

namespace {

using Clock = std::chrono::steady_clock;

// time.imex: the Krylov solve of the stage systems (integrate/imex_krylov.cpp). ARKODE ends SPGMR
// when the preconditioned residual's WRMS norm is below eps_lin times the Newton tolerance (0.1 of
// the step's error tolerance); 1e-6 (ARKODE's default 0.05) leaves a stage error of the order of
// 1e-7 rtol, so that the ranks' run follows one process's (KLU, a direct solve) to about 1e-10
// relative. Jacobi-preconditioned GMRES needs tens of iterations at the steps implicit viscosity
// allows (gamma nu / dx^2 of order 100): a Krylov space of 50 with up to 10 restarts.
constexpr double kKrylovEpsLin = 1e-6;
constexpr int kKrylovDimension = 50, kKrylovRestarts = 10;

// One rank of a decomposed run: its particles with their halo, the projection over the ranks,
// migration at the sync points, frames reduced over the ranks and written by rank 0 (or as pieces),
// checkpoints of the state gathered on rank 0.
class RankProcess final : public RunProcess {
 public:
  RankProcess(const Scene& scene, const RunOptions& options, const parallel::Communicator& comm)
      : scene_(scene),
        comm_(comm),
        ranks_(comm.size()),
        root_(comm.rank() == 0),
        write_frames_(options.write_frames),
        pieces_(scene.pieces && options.write_frames) {}

  int ranks() const override { return ranks_; }
  bool root() const override { return root_; }
  Verdict agree(const Verdict& mine, std::int64_t& flag) const override { return parallel::agree(comm_, mine, flag); }
  double sum(double x) const override { return comm_.sum(x); }
  std::int64_t max(std::int64_t x) const override { return comm_.max(x); }
  void sum_in_place(std::vector<double>& v) const override { comm_.sum_in_place(v); }
  void max_in_place(std::vector<double>& v) const override { comm_.max_in_place(v); }
  std::vector<double> gather(const std::vector<double>& v) const override { return comm_.gatherv(v); }

  void refuse_unsupported(const Scene& scene) const override { check_distributable(scene, ranks_); }
  void built(Model& model) override;
  std::string where() const override { return " on " + std::to_string(ranks_) + " MPI ranks"; }
  std::string frame_form() const override {
    return scene_.pieces ? " (a frame piece per rank)" : " (frames joined on rank 0)";
  }
  void initial_state(Model&) override;
  double initial_acceleration() const override { return accel0_; }
  long start_stepping(double t0, const Checkpoint* restart, const StepStats& counters) override;
  int pieces() const override { return pieces_ ? ranks_ : 0; }
  void started() override {  // the state checker has read the initial velocities
    for (auto* v : {&model_->particles.init_vel[0], &model_->particles.init_vel[1]}) std::vector<double>().swap(*v);
  }

  TimeIntegrator& integrator() override { return *stepper_.integrator; }
  double step(double t, double stop) override { return stepper_.step(t, stop); }
  long reflect() override {
    return static_cast<long>(WallReflection(scene_, mine_->layout()).apply(integrator().state()));
  }
  void check(const StateChecker& checker, double t) override {
    checker.check(t, integrator().state(), mine_->layout(), mine_->ids());
  }
  void sync_point(double t, long steps) override {
    if (scene_.reorder_every > 0 && steps % scene_.reorder_every == 0) migrate(t);
  }
  // The rank's own particles' power at a field refresh of the state.
  double viscous_power(double t) override {
    f_->eval(t, integrator().state(), nullptr);
    return f_->evaluator().viscous_power(mine_->size());
  }
  FrameSource frame_source(double t) override;
  void write_rows(const FrameDiagnostics& diag, const StepStats& stats, const Frame& mine, const Frame* walls,
                  RunOutput* out) override;

  void with_whole_state(bool everywhere, const std::function<void(const double*)>& use) override {
    const std::vector<double> all = whole_state(everywhere);
    use(all.empty() ? nullptr : all.data());
  }
  // The particles dealt anew from the whole state as at a restart (the same bisection and order on
  // any run), and a new integrator at t (no FSAL value or step-size history survives).
  void continue_from_checkpoint(double t, double h, const StepStats& counters, const double* y) override {
    deal(y);
    start_integrator(t, h, counters);
    count_fewest();
  }

  // ARKODE gave up: on every rank alike (global norms, agreed flags).
  Verdict numerical_failure(double, const std::string& what) override {
    return parallel::agree(comm_, {3, what, arkode().failure_names_entry()});
  }
  Verdict out_of_memory(double) override { throw; }
  void report(RunTotals& totals) override;

 private:
  void initial_fields();
  void make_projection();
  void start_integrator(double t, double h, const StepStats& counters);
  void sort_mine() {
    if (scene_.reorder_every > 0) mine_->sort_by_cell(scene_.min.data(), model_->rhs->kernel().radius());
  }
  void deal(const double* y);  // the particles of a whole state y dealt to the ranks anew
  double stable(const double* y_local);
  std::vector<double> whole_state(bool everywhere);
  void migrate(double at);
  void count_fewest() { fewest_ = std::min(fewest_, -comm_.max(-static_cast<std::int64_t>(mine_->size()))); }

  const Scene& scene_;
  const parallel::Communicator& comm_;
  const int ranks_;
  const bool root_;
  const bool write_frames_;
  const bool pieces_;
  // The solver of the projection's Poisson equation over the ranks (method.rank_ppe_solver).
  const std::string rank_solver_ = distributed_ppe::resolved_rank_poisson_solver(scene_.rank_ppe_solver);
  Model* model_ = nullptr;
  std::optional<parallel::CellGrid> grid_;
  std::optional<parallel::Decomposition> decomposition_;
  std::optional<parallel::RankParticles> mine_;
  std::optional<HaloRhs> f_;
  double flow_ = 0;               // the flow rate the constrained projection's rates scale with
  std::vector<double> d0_by_id_;  // number density at t = 0 of every particle, by id
  double accel0_ = 0;             // the largest acceleration at t = 0 over the ranks
  std::vector<std::size_t> place_;  // id -> index in the model (its particle order, the checkpoints')
  Projection* projection_ = nullptr;  // the model's, over the rank's HaloDomain (with hypre)
  std::vector<std::int64_t> pressure_ids_;  // the ids of the rank's particles at the last projection
  std::vector<double> frame_d0_, frame_x_, frame_y_, frame_p_;  // the frame's (frame_source)
  ErkOptions eo_;
  std::optional<KrylovViscousSplit> split_;  // time.imex
  TimeStepper stepper_;  // ERKStep, or ARKStep over split_ with time.imex
  ArkodeIntegrator& arkode() { return static_cast<ArkodeIntegrator&>(*stepper_.integrator); }
  long migrations_ = 0;
  // The fewest particles a rank owned after a deal or a migration (summary.json mpi.fewest_particles).
  std::int64_t fewest_ = 0;
  double migration_seconds_ = 0;
};

// The model's projection terms name the solve over the ranks (summary.json reports the rank's
// projection as one process's), and so does the IMEX term (SPGMR for KLU).
void RankProcess::built(Model& model) {
  model_ = &model;
  const std::string imex_klu = "imex:viscosity_implicit+klu";
  for (std::string& term : model.terms)
    if (term.compare(0, imex_klu.size(), imex_klu) == 0) term = "imex:viscosity_implicit+spgmr_jacobi" + term.substr(imex_klu.size());
#ifdef ARKSPH_WITH_HYPRE
  for (std::string& term : model.terms)
    if (term == "projection:ppe-" + scene_.ppe_solver) term = "projection:ppe-" + rank_solver_;
    else if (term == "projection:constrained-ppe-" + scene_.ppe_solver) term = "projection:constrained-ppe-" + rank_solver_;
#endif
}

// The particles dealt to the ranks from the whole initial state, and their fields at t = 0 (below).
// No rank evaluates the whole model: the initial state, its evaluator's particle data (the evaluator
// gives way to one without, halo_rhs.hpp, and the one-process projection over it goes: the ranks'
// own is built by make_projection) and the model's initial positions go now (a new deal reads only
// masses, densities, phases and ids; the initial velocities stay until the state checker has read
// them).
void RankProcess::initial_state(Model&) {
  RhsEvaluator& rhs = *model_->rhs;
  std::vector<double> y0(rhs.layout().size());
  rhs.initial_state(y0.data());
  grid_.emplace(domain_of(scene_), rhs.kernel().radius());
  deal(y0.data());
  std::vector<double>().swap(y0);
  // The constrained projection's rates read the whole model's initial speeds.
  flow_ = scene_.pressure_in_f() ? flow_rate(scene_, rhs) : 0.0;
  model_->projection.reset();
  model_->rhs = without_particles(scene_, *model_);
  for (auto* v : {&model_->particles.init_pos[0], &model_->particles.init_pos[1]}) std::vector<double>().swap(*v);
  f_.emplace(scene_, *model_, comm_, *mine_);
  f_->set_decomposition(*decomposition_);
  initial_fields();
}

// The initial state's fields on the ranks: the number density d0 of every particle by id (C&R's CV,
// and the frames' reference), and the largest acceleration, which every rank's state checker takes
// for its speed bound. The rank's evaluator storage is freed before d0 is shared (the next
// evaluation, at the same state, builds the same neighbour list anew).
void RankProcess::initial_fields() {
  std::vector<double> y = mine_->state(), ydot(y.size());
  f_->eval(0.0, y.data(), ydot.data());
  accel0_ = comm_.max(f_->local_max_acceleration());
  f_->eval(0.0, y.data(), nullptr);  // the fields with their pair list, as a frame's
  std::vector<double> d0 = number_density(f_->evaluator().fields());
  d0.resize(mine_->size());
  f_->release_storage();
  d0_by_id_ = parallel::spread_by_id(comm_, mine_->ids(), d0, model_->particles.n);
  return_free_memory();
}

// ISPH: the projection after each step over the ranks, its pressure pinned at the first particle
// of rank 0's model for the whole run: the set-up's first, or the checkpoint's, which is the
// set-up's again for a checkpoint written on ranks (so a restart pins the same particle).
void RankProcess::make_projection() {
#ifdef ARKSPH_WITH_HYPRE
  if (!scheme_traits(scene_.scheme).projection) return;
  model_->projection = std::make_unique<Projection>(
      scene_, std::make_unique<HaloDomain>(comm_, *f_, *mine_, model_->particles.id[0]), flow_);
  projection_ = model_->projection.get();
  if (!root_) return;
  if (scheme_traits(scene_.scheme).grid)
    std::printf("  pressure Poisson equation: on the grid (KLU), the cell sums of every rank's particles all-reduced\n");
  else
    std::printf("  pressure Poisson equation: %s over the ranks, tolerance %g "
                "(method.ppe_solver = %s applies to one process)\n",
                rank_solver_ == "hypre" ? "hypre PCG + BoomerAMG" : "CG + smoothed-aggregation AMG",
                scene_.ppe_tolerance, scene_.ppe_solver.c_str());
  std::fflush(stdout);
#endif
}

// The largest speed (of y) and acceleration (of the last f) over the ranks: one all-reduce.
double RankProcess::stable(const double* y_local) {
  std::vector<double> largest{max_speed(mine_->layout(), y_local), f_->local_max_acceleration()};
  comm_.max_in_place(largest);
  return stable_step(scene_, *model_, largest[0], largest[1]);
}

// The particles from the checkpoint's state on restart, the projection and the integrator.
long RankProcess::start_stepping(double t0, const Checkpoint* restart, const StepStats& counters) {
  if (restart) deal(restart->state.data());
  place_.resize(model_->particles.n);
  for (std::size_t i = 0; i < place_.size(); ++i) place_[static_cast<std::size_t>(model_->particles.id[i])] = i;
  make_projection();
  eo_ = integrator_options(scene_);
  eo_.state_vector = mpi_state_vector(comm_.comm());
  eo_.any_rank = [this](bool local) { return comm_.max(static_cast<std::int64_t>(local)) > 0; };
  eo_.describe_entry = [this](std::size_t i, double v) { return describe_rhs_entry(mine_->layout(), mine_->ids(), i, v); };
  eo_.stability = [this](double, const double* yl) { return stable(yl); };
  // A constrained projection starts from a divergence-free velocity (a restart already is).
  if (projection_ && projection_->constrained() && !restart) {
    std::vector<double> y = mine_->state();
    projection_->project_initial(0.0, y.data());
    mine_->load(y.data());
  }
  start_integrator(t0, restart ? restart->next_step : 0.0, counters);
  fewest_ = -comm_.max(-static_cast<std::int64_t>(mine_->size()));
  return 1;  // the evaluation at t = 0 for the number density
}

// The particles of a whole state y (the model's layout) dealt to the ranks anew: a new bisection,
// the rank's particles sorted by cell as one process sorts its own at t = 0 and at its re-sorts
// (method.reorder_every > 0; 0 keeps the dealt order, as one process keeps its own); the projection
// numbers its rows anew.
void RankProcess::deal(const double* y) {
  const StateLayout& layout = model_->rhs->layout();
  together([&] { decomposition_.emplace(bisect_state(*grid_, layout, y, ranks_, scene_)); });
  mine_.emplace(model_->particles, layout, y, *decomposition_, comm_.rank());  // in place: f_ keeps it
  sort_mine();
  if (f_) f_->set_decomposition(*decomposition_);
  if (projection_) projection_->particles_moved();
}

// A new integrator at (t, the rank's state) with first step h (0: the stability limit) and the
// counters of the run so far: at the start, on restart, and after each scheduled checkpoint, so
// that a restart from that checkpoint continues as the run that wrote it (distributed_run.hpp).
void RankProcess::start_integrator(double t, double h, const StepStats& counters) {
  std::vector<double> y = mine_->state();
  {
    std::vector<double> ydot(y.size());
    f_->eval(t, y.data(), ydot.data());  // the halo, and the acceleration for the stability limit
  }
  eo_.initial_dt = h > 0 ? h : stable(y.data());
  if (scene_.imex) {  // after the evaluation above, whose acceleration is the whole f's, as one process's at t = 0
    if (!split_) {
      split_.emplace(scene_, split_source(*f_, *mine_, comm_), PeriodicAxes{});
      if (projection_ && projection_->constrained())  // the constrained projection inside f_E
        split_->set_constraint([this](const double* yy, double* fe, const double* au, const double* av) {
          projection_->constrain(yy, fe, au, av);
          pressure_ids_ = mine_->ids();
        });
    }
    split_->forget();
    ImexOptions io = imex_options(scene_, eo_);
    io.krylov_eps_lin = kKrylovEpsLin;
    io.krylov_dimension = kKrylovDimension;
    io.krylov_restarts = kKrylovRestarts;
    stepper_ = TimeStepper{};
    stepper_.integrator = std::make_unique<ImexIntegrator>(split_->functions(), y, t, io);
  } else {
    HaloRhs& f = *f_;
    stepper_ = make_time_stepper(
        scene_, [&f](double tt, const double* yl, double* yd) { f.eval(tt, yl, yd); }, eo_, y, t, projection_,
        [this] { pressure_ids_ = mine_->ids(); });
  }
  integrator().set_counter_offset(counters);
}

// The whole state in the model's layout and particle order on rank 0 (on every rank with
// `everywhere`), from the ranks' integrator states. A rank that receives it frees its evaluator's
// storage first (rebuilt at the next evaluation; after a scheduled checkpoint the particles are
// dealt anew, which rebuilds it anyway).
std::vector<double> RankProcess::whole_state(bool everywhere) {
  if (everywhere || root_) f_->release_storage();
  const StateLayout whole = model_->rhs->layout(), mine = mine_->layout();
  const std::size_t per = whole.size() / whole.n;  // entries per particle, block b at b * n
  const double* y = integrator().state();
  std::vector<double> all(everywhere || root_ ? whole.size() : 0);
  parallel::join_by_id(
      comm_, mine_->ids().data(), mine.n, per, whole.n, everywhere ? -1 : 0,
      [&](std::size_t a, double* record) {
        for (std::size_t b = 0; b < per; ++b) record[b] = y[b * mine.n + a];
      },
      [&](std::size_t id, const double* record) {
        for (std::size_t b = 0; b < per; ++b) all[b * whole.n + place_[id]] = record[b];
      });
  return all;
}

// A frame's particles: the rank's own, their positions wrapped into the box along the periodic
// axes (as one process writes them), the sample points in the rank's block.
FrameSource RankProcess::frame_source(double t) {
  f_->eval(t, integrator().state(), nullptr);
  const FluidFields& ff = f_->evaluator().fields();
  const std::size_t n = mine_->size();
  frame_d0_.resize(n);
  frame_x_.resize(n);
  frame_y_.resize(n);
  for (std::size_t a = 0; a < n; ++a) {
    frame_d0_[a] = d0_by_id_[static_cast<std::size_t>(mine_->ids()[a])];
    double q[3] = {ff.x[a], ff.y[a], 0.0};
    grid_->domain().wrap(q);
    frame_x_[a] = q[0];
    frame_y_[a] = q[1];
  }
  frame_p_.clear();  // isph: the last projection's, as one process's frame carries it
  if (write_frames_ && projection_ && projection_->stats().solves > 0) {  // by id: the particles may have migrated since
    const std::vector<double> by_id =
        parallel::spread_by_id(comm_, pressure_ids_, projection_->pressure(), model_->particles.n);
    for (std::int64_t id : mine_->ids()) frame_p_.push_back(by_id[static_cast<std::size_t>(id)]);
  }
  FrameSource s;
  s.particles = {&ff, n, frame_d0_.data(), f_->evaluator().particles().phase.data()};
  s.owns = [this](double x, double y) {
    double q[3] = {x, y, 0.0};
    grid_->domain().wrap(q);
    return decomposition_->owner(q) == comm_.rank();
  };
  s.x = frame_x_.data();
  s.y = frame_y_.data();
  s.pressure = frame_p_.empty() ? ff.p.data() : frame_p_.data();
  s.id = mine_->ids().data();
  s.support = f_->evaluator().kernel().radius();
  s.halo_copies = true;
  return s;
}

// The rows go to each rank's piece (output.pieces, rank 0 writing the index naming them), or are
// joined on rank 0 into one file; the wall points (output.walls) likewise. At the first frame (the
// next evaluation is at the same state) and the last (none follows), the rank that writes rows
// (every rank with pieces, rank 0 otherwise) copies its own and frees its evaluator's storage
// before it writes or joins them, so that it holds either, not both: a list built anew at the same
// positions sums the same pairs in the same order, whereas a rebuild at another time would not.
void RankProcess::write_rows(const FrameDiagnostics& diag, const StepStats& st, const Frame& mine, const Frame* walls,
                             RunOutput* out) {
  std::optional<JoinedFrame> whole;
  std::optional<JoinedWalls> all_walls;  // output.walls, joined on rank 0 (without pieces)
  const bool first_or_last = mine.time <= 0 || mine.time >= scene_.end;
  if (write_frames_ && pieces_) {
    const int number = static_cast<int>(comm_.max(static_cast<std::int64_t>(out ? out->frames() : 0)));
    if (walls)
      together([&] { write_vtp(scene_.directory + "/" + piece_file_name(number, comm_.rank(), "walls"), *walls); });
    const FrameInIdOrder rows(mine, first_or_last);
    if (first_or_last) {
      f_->release_storage();
      return_free_memory();
    }
    together([&] { write_vtp(scene_.directory + "/" + piece_file_name(number, comm_.rank()), rows.frame()); });
  } else if (write_frames_) {
    if (walls) all_walls.emplace(comm_, *walls);
    if (root_ && first_or_last) {
      const JoinedFrame::Copy own(mine);
      f_->release_storage();
      return_free_memory();
      whole.emplace(comm_, own, model_->particles.n);
    } else {
      whole.emplace(comm_, mine, model_->particles.n);
    }
  }
  together([&] {
    if (out) out->record(diag, st, whole ? &whole->frame() : nullptr, all_walls ? &all_walls->frame() : nullptr);
  });
  if (whole && root_) {
    whole.reset();
    return_free_memory();
  }
}

// At a sync point: the particles to the owners of their positions by a new bisection, the
// integrator re-initialised on the new local states.
void RankProcess::migrate(double at) {
  const auto t0 = Clock::now();
  const double h = integrator().next_step();
  mine_->load(integrator().state());
  mine_->wrap_seen(grid_->domain());
  parallel::ParticleFields& F = mine_->fields();
  std::vector<std::int64_t> counts = parallel::count_per_cell(*grid_, F);
  comm_.sum_in_place(counts);
  decomposition_.emplace(bisect(*grid_, counts, ranks_, scene_));
  parallel::migrate(comm_, *decomposition_, F);
  mine_->refresh_ids();
  sort_mine();
  f_->set_decomposition(*decomposition_);
  if (projection_) projection_->particles_moved();
  arkode().resize(mine_->state(), at, h);
  count_fewest();
  ++migrations_;
  migration_seconds_ += seconds_since(t0);
}

// summary.json: what the decomposition did.
void RankProcess::report(RunTotals& totals) {
  totals.neighbor_rebuilds = f_->exchanges();
  if (scene_.reorder_every > 0) {
    totals.reorders = migrations_;
    totals.reorder_seconds = migration_seconds_;
  }
  // The peak resident memory of every rank (getrusage; kB on Linux).
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const std::vector<std::int64_t> peak_kb =
      comm_.gatherv(std::vector<std::int64_t>{static_cast<std::int64_t>(usage.ru_maxrss)});
  Json& mpi = totals.mpi;
  mpi.set("ranks", ranks_).set("halo_exchanges", f_->exchanges()).set("migrations", migrations_);
  mpi.set("fewest_particles", static_cast<long>(fewest_));
  Json seconds = Json::object();  // rank 0's wall time in f (distributed/halo_rhs.hpp)
  seconds.set("halo_exchange", f_->seconds().exchange).set("halo_update", f_->seconds().update);
  seconds.set("evaluator", f_->seconds().evaluator);
  mpi.set("seconds", seconds);
  Json peaks = Json::array();
  for (std::int64_t kb : peak_kb) peaks.push(static_cast<long>(kb));
  mpi.set("max_rss_kb", peaks);  // per rank, in rank order
}

}  // namespace

RunResult run_distributed(const Scene& scene, const RunOptions& options, const parallel::Communicator& comm) {
  const auto wall_start = Clock::now();
  RankProcess process(scene, options, comm);
  return run_model(scene, options, process, wall_start);
}

}  // namespace arksph::distributed
