#include "distributed/halo_rhs.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/resize_with_headroom.hpp"
#include "core/seconds_since.hpp"
#include "kernels/kernel.hpp"
#include "rhs/terms.hpp"

namespace arksph::distributed {

namespace {
// The neighbourhoods a particle's sums depend on: its own and its neighbours' (see the header).
constexpr double kHaloSupports = 2.0;
// The Verlet skin of the neighbour search (rhs/neighbor_cache.cpp), as a fraction of the support.
constexpr double kSkinFraction = 0.15;
}  // namespace

Scene rank_scene(const Scene& scene) {
  Scene s = scene;
  for (SideSpec& side : s.sides) side.halo = side.kind == SideKind::periodic;
  return s;
}

std::unique_ptr<RhsEvaluator> without_particles(const Scene& scene, const Model& model) {
  ParticleSet none;
  none.dim = model.particles.dim;
  none.n = model.particles.n;
  none.dx = model.particles.dx;
  none.init_energy = model.particles.init_energy;
  return std::make_unique<RhsEvaluator>(scene, none, model.rhs->kernel(), terms_from_scene(scene, model.sound_speed));
}

HaloRhs::HaloRhs(const Scene& scene, const Model& model, const parallel::Communicator& comm,
                 parallel::RankParticles& owned)
    : scene_(rank_scene(scene)),
      model_(model),
      comm_(comm),
      owned_(owned),
      radius_(model.rhs->kernel().radius()),
      skin_(kSkinFraction * radius_),
      cutoff_(kHaloSupports * radius_ + skin_) {
  const parallel::RankFieldIndex& ix = owned.index();
  for (int k = 0; k < ix.dim; ++k) update_fields_.push_back(ix.seen(k));
  for (int k = 0; k < ix.dim; ++k) update_fields_.push_back(ix.vel(k));
  if (ix.density) update_fields_.push_back(ix.rho());
  if (ix.energy) update_fields_.push_back(ix.e());
  blocks_ = ix.state_blocks(true);
  offset_.resize(static_cast<std::size_t>(ix.dim));
  ref_.resize(static_cast<std::size_t>(ix.dim));
}

void HaloRhs::set_decomposition(const parallel::Decomposition& decomposition) {
  decomposition_ = &decomposition;
  exchange_due_ = true;  // the particles were migrated: exchange at the next eval
}

void HaloRhs::exchange() {
  const auto t0 = std::chrono::steady_clock::now();
  parallel::ParticleFields& F = owned_.fields();
  const parallel::RankFieldIndex& ix = owned_.index();
  const parallel::Domain& domain = decomposition_->grid().domain();
  const std::size_t n = F.size();
  parallel::Box mine = decomposition_->box(comm_.rank());
  owned_.wrap_seen(domain);
  for (int k = 0; k < ix.dim; ++k)
    for (double x : F.field[static_cast<std::size_t>(ix.seen(k))])
      if (std::isfinite(x)) {
        mine.lo[k] = std::min(mine.lo[k], x);
        mine.hi[k] = std::max(mine.hi[k], x);
      }
  for (int k = 0; k < ix.dim; ++k) {
    const auto& seen = F.field[static_cast<std::size_t>(ix.seen(k))];
    const auto& state = F.field[static_cast<std::size_t>(ix.state_pos(k))];
    auto& off = offset_[static_cast<std::size_t>(k)];
    off.resize(n);
    for (std::size_t a = 0; a < n; ++a) off[a] = state[a] - seen[a];
    ref_[static_cast<std::size_t>(k)] = seen;
  }
  const std::vector<parallel::Box> boxes = comm_.allgatherv(std::vector<parallel::Box>{mine});
  exchange_.exchange(comm_, domain, boxes, F, cutoff_, halo_);
  build_evaluator();
  exchange_due_ = false;
  ++exchanges_;
  seconds_.exchange += seconds_since(t0);
}

// The evaluator over the rank's particles, then the halo copies, built anew at each exchange (and
// after release_storage): its neighbour list and ghosts are built at the next eval, at the rule of
// one process's Verlet list. No initial positions or velocities: the state comes from eval, never
// from RhsEvaluator::initial_state.
void HaloRhs::build_evaluator() {
  const parallel::ParticleFields& F = owned_.fields();
  const parallel::RankFieldIndex& ix = owned_.index();
  ParticleSet set;
  set.dim = ix.dim;
  set.n = F.size() + halo_.size();
  set.dx = model_.particles.dx;
  set.init_energy = model_.particles.init_energy;
  const auto joined = [&](int field) {
    std::vector<double> v;
    v.reserve(set.n);
    const auto& o = F.field[static_cast<std::size_t>(field)];
    const auto& h = halo_.field[static_cast<std::size_t>(field)];
    v.insert(v.end(), o.begin(), o.end());
    v.insert(v.end(), h.begin(), h.end());
    return v;
  };
  set.mass = joined(ix.mass());
  set.rho0 = joined(ix.rho0());
  set.phase.reserve(set.n);
  for (double p : joined(ix.phase())) set.phase.push_back(static_cast<std::int32_t>(p));
  set.id.reserve(set.n);
  for (std::uint64_t id : F.id) set.id.push_back(static_cast<std::int64_t>(id));
  for (std::uint64_t id : halo_.id) set.id.push_back(static_cast<std::int64_t>(id));
  evaluator_.reset();  // never the old and the new at once
  RhsOptions options;
  options.pairs_at_every_f = scene_.pressure_in_f();  // the constrained projection walks the pairs of each f
  options.derivative_count = F.size();                // the halo copies' derivatives are discarded
  options.imex_split = imex_split_;
  evaluator_ = std::make_unique<RhsEvaluator>(scene_, set, make_kernel(scene_.kernel, model_.h, scene_.dimension),
                                              terms_from_scene(scene_, model_.sound_speed), options);
  evaluator_->set_slip_origin(slip_on_, slip_t0_);
  ++builds_;
}

void HaloRhs::set_imex_split(bool on) {
  imex_split_ = on;
  if (!evaluator_) return;
  RhsOptions options = evaluator_->options();
  options.imex_split = on;
  evaluator_->set_options(options);
}

void HaloRhs::implicit_part(double* ydot_i) {
  const StateLayout& L = evaluator_->layout();
  resize_with_headroom(ydot_all_, L.size());
  evaluator_->implicit_part(ydot_all_.data());
  const std::size_t n = owned_.fields().size();
  for (std::size_t b = 0; b < blocks_.size(); ++b)
    std::copy_n(ydot_all_.begin() + static_cast<long>(b * L.n), n, ydot_i + b * n);
}

void HaloRhs::viscous_acceleration(const double* u, const double* v, double* au, double* av) {
  const std::size_t n = owned_.fields().size(), all = evaluator_->layout().n;
  own_u_.assign(u, u + n);
  own_v_.assign(v, v + n);
  const std::vector<std::vector<double>> copies = halo_values({&own_u_, &own_v_});
  all_u_ = own_u_;
  all_v_ = own_v_;
  all_u_.insert(all_u_.end(), copies[0].begin(), copies[0].end());
  all_v_.insert(all_v_.end(), copies[1].begin(), copies[1].end());
  all_au_.resize(all);
  all_av_.resize(all);
  evaluator_->viscous_acceleration(all_u_.data(), all_v_.data(), all_au_.data(), all_av_.data());
  std::copy_n(all_au_.begin(), n, au);
  std::copy_n(all_av_.begin(), n, av);
}

void HaloRhs::set_slip_origin(bool on, double t0) {
  slip_on_ = on;
  slip_t0_ = t0;
  if (evaluator_) evaluator_->set_slip_origin(on, t0);
}

std::vector<std::vector<double>> HaloRhs::halo_values(const std::vector<const std::vector<double>*>& own) const {
  const int dim = owned_.index().dim;
  const int k = static_cast<int>(own.size());
  // Records of the fields beyond the coordinates (update shifts the coordinates only).
  parallel::ParticleFields from(dim, dim + k), to(dim, dim + k);
  from.id = owned_.fields().id;
  std::vector<int> sent;
  for (int i = 0; i < k; ++i) {
    std::vector<double>& field = from.field[static_cast<std::size_t>(dim + i)];
    field = *own[static_cast<std::size_t>(i)];
    field.resize(from.id.size(), 0.0);
    sent.push_back(dim + i);
  }
  to.resize(halo_.size());
  exchange_.update(comm_, from, sent, to);
  std::vector<std::vector<double>> copies;
  for (int i = 0; i < k; ++i) copies.push_back(std::move(to.field[static_cast<std::size_t>(dim + i)]));
  return copies;
}

void HaloRhs::eval(double t, const double* y, double* ydot) {
  parallel::ParticleFields& F = owned_.fields();
  const parallel::RankFieldIndex& ix = owned_.index();
  const std::size_t n = F.size();
  owned_.load(y);
  if (exchange_due_) {
    exchange();
  } else {
    // The seen positions move with the state; this rank's largest displacement since the exchange
    // travels with the halo values, and every rank learns the largest over the ranks from them.
    const auto t0 = std::chrono::steady_clock::now();
    double moved2 = 0;
    for (std::size_t a = 0; a < n; ++a) {
      double d2 = 0;
      for (int k = 0; k < ix.dim; ++k) {
        const std::size_t kk = static_cast<std::size_t>(k);
        const double x = F.field[static_cast<std::size_t>(ix.state_pos(k))][a] - offset_[kk][a];
        F.field[static_cast<std::size_t>(ix.seen(k))][a] = x;
        d2 += (x - ref_[kk][a]) * (x - ref_[kk][a]);
      }
      moved2 = std::max(moved2, d2);  // NaN positions: the state checks, not here
    }
    const double largest = exchange_.update_max(comm_, F, update_fields_, halo_, moved2);
    seconds_.update += seconds_since(t0);
    if (largest > 0.25 * skin_ * skin_) exchange();  // the copies just sent are replaced
  }
  const auto t_eval = std::chrono::steady_clock::now();

  // The evaluator's state: this rank's particles, then the halo copies.
  if (!evaluator_) build_evaluator();  // after release_storage
  const StateLayout& L = evaluator_->layout();
  resize_with_headroom(y_all_, L.size());  // the halo grows by a few copies at some exchanges
  for (std::size_t b = 0; b < blocks_.size(); ++b) {
    const auto& own = F.field[static_cast<std::size_t>(blocks_[b])];
    const auto& copy = halo_.field[static_cast<std::size_t>(blocks_[b])];
    std::copy(own.begin(), own.end(), y_all_.begin() + static_cast<long>(b * L.n));
    std::copy(copy.begin(), copy.end(), y_all_.begin() + static_cast<long>(b * L.n + n));
  }
  if (!ydot) {  // the fields only (output.pieces, the projection), as a whole frame's refresh
    evaluator_->eval(t, y_all_.data(), nullptr);
    seconds_.evaluator += seconds_since(t_eval);
    return;
  }
  resize_with_headroom(ydot_all_, L.size());
  evaluator_->eval(t, y_all_.data(), ydot_all_.data());

  // This rank's derivatives, in its own layout.
  double a2 = 0;
  for (std::size_t a = 0; a < n; ++a) {
    double s = 0;
    for (int k = 0; k < ix.dim; ++k) s += ydot_all_[L.vel(k) + a] * ydot_all_[L.vel(k) + a];
    a2 = std::max(a2, s);
  }
  max_accel_ = std::sqrt(a2);
  for (std::size_t b = 0; b < blocks_.size(); ++b)
    std::copy_n(ydot_all_.begin() + static_cast<long>(b * L.n), n, ydot + b * n);
  seconds_.evaluator += seconds_since(t_eval);
}

namespace {
class HaloSource final : public SplitSource {
 public:
  HaloSource(HaloRhs& f, const parallel::RankParticles& mine, const parallel::Communicator& comm)
      : f_(f), mine_(mine), comm_(comm) {}
  StateLayout layout() const override { return mine_.layout(); }
  void eval(double t, const double* y, double* ydot) override { f_.eval(t, y, ydot); }
  void implicit_part(double* ydot_i) override { f_.implicit_part(ydot_i); }
  void viscous_acceleration(const double* u, const double* v, double* au, double* av) override {
    f_.viscous_acceleration(u, v, au, av);
  }
  long builds() const override { return f_.builds(); }
  bool everywhere(bool local) const override { return -comm_.max(-static_cast<std::int64_t>(local)) > 0; }
  RhsEvaluator& evaluator() override { return f_.evaluator(); }

 private:
  HaloRhs& f_;
  const parallel::RankParticles& mine_;
  const parallel::Communicator& comm_;
};
}  // namespace

std::unique_ptr<SplitSource> split_source(HaloRhs& f, const parallel::RankParticles& mine,
                                          const parallel::Communicator& comm) {
  f.set_imex_split(true);
  return std::make_unique<HaloSource>(f, mine, comm);
}

}  // namespace arksph::distributed
