#include "distributed/halo_viscous_split.hpp"

#include <algorithm>
#include <cstdint>
#include <memory>

#include "integrate/dependency_pattern.hpp"
#include "integrate/viscous_jacobian.hpp"

namespace arksph::distributed {

namespace {
// A rank's HaloRhs as the split's source: its own particles' f, the halo's velocities from their
// owners, the ranks' agreement.
class HaloSource final : public SplitSource {
 public:
  HaloSource(HaloRhs& f, const RankParticles& mine, const parallel::Communicator& comm)
      : f_(f), mine_(mine), comm_(comm) {}
  StateLayout layout() const override { return mine_.layout(); }
  void eval(double t, const double* y, double* ydot) override { f_.eval(t, y, ydot); }
  void implicit_part(double* ydot_i) override { f_.implicit_part(ydot_i); }
  void viscous_acceleration(const double* u, const double* v, double* au, double* av) override {
    f_.viscous_acceleration(u, v, au, av);
  }
  long builds() const override { return f_.builds(); }
  bool everywhere(bool local) const override { return -comm_.max(-static_cast<std::int64_t>(local)) > 0; }

 private:
  HaloRhs& f_;
  const RankParticles& mine_;
  const parallel::Communicator& comm_;
};

HaloRhs& switched_to_split(HaloRhs& f) {
  f.set_imex_split(true);
  return f;
}
}  // namespace

HaloViscousSplit::HaloViscousSplit(const Scene& scene, HaloRhs& f, const RankParticles& mine,
                                   const parallel::Communicator& comm)
    : SplitCache(std::make_unique<HaloSource>(switched_to_split(f), mine, comm)), f_(f), mine_(mine) {
  radius_ = viscous_dependency_radius(scene, f_.evaluator().ghost_depth());
}

// The fields at the frozen part of y, and the affine part (zero velocities, halo included).
void HaloViscousSplit::linearize(double t, const double* y) {
  if (!cached(y)) evaluate_at(t, y);
  const std::size_t all = f_.evaluator().layout().n;
  pu_.assign(all, 0.0);
  pv_.assign(all, 0.0);
  bu_.resize(all);
  bv_.resize(all);
  f_.evaluator().viscous_acceleration(pu_.data(), pv_.data(), bu_.data(), bv_.data());
}

void HaloViscousSplit::times(const double* v, double* Jv) {
  const StateLayout L = mine_.layout();
  au_.resize(L.n);
  av_.resize(L.n);
  f_.viscous_acceleration(v + L.vel(0), v + L.vel(1), au_.data(), av_.data());
  std::fill(Jv, Jv + L.size(), 0.0);
  for (std::size_t a = 0; a < L.n; ++a) {
    Jv[L.vel(0) + a] = au_[a] - bu_[a];
    Jv[L.vel(1) + a] = av_[a] - bv_[a];
  }
}

// Greedy distance-1 colouring of the evaluator's particles (the rank's, then the halo copies) over
// R_dep at the frozen positions; one probe per colour and velocity component.
void HaloViscousSplit::diagonal(double* d) {
  const StateLayout L = mine_.layout();
  RhsEvaluator& rhs = f_.evaluator();
  const FluidFields& ff = rhs.fields();
  const std::size_t all = rhs.layout().n;
  const std::vector<std::vector<std::uint32_t>> near =
      dependency_pattern(ff.x.data(), ff.y.data(), all, radius_, PeriodicAxes{});
  int colours = 0;
  const std::vector<int> colour = greedy_colouring(near, false, colours);
  std::fill(d, d + L.size(), 0.0);
  qu_.resize(all);
  qv_.resize(all);
  for (int k = 0; k < 2; ++k)
    for (int c = 0; c < colours; ++c) {
      pu_.assign(all, 0.0);
      pv_.assign(all, 0.0);
      std::vector<double>& probe = k == 0 ? pu_ : pv_;
      for (std::size_t j = 0; j < all; ++j)
        if (colour[j] == c) probe[j] = 1.0;
      rhs.viscous_acceleration(pu_.data(), pv_.data(), qu_.data(), qv_.data());
      const std::vector<double>& q = k == 0 ? qu_ : qv_;
      const std::vector<double>& b = k == 0 ? bu_ : bv_;
      for (std::size_t a = 0; a < L.n; ++a)
        if (colour[a] == c) d[L.vel(k) + a] = q[a] - b[a];
    }
}

ImexFunctions HaloViscousSplit::functions() {
  ImexFunctions f;
  f.explicit_rhs = [this](double t, const double* y, double* yd) { explicit_rhs(t, y, yd); };
  f.implicit_rhs = [this](double t, const double* y, double* yd) { implicit_rhs(t, y, yd); };
  f.krylov.linearize = [this](double t, const double* y) { linearize(t, y); };
  f.krylov.times = [this](const double* v, double* Jv) { times(v, Jv); };
  f.krylov.diagonal = [this](double* d) { diagonal(d); };
  return f;
}

}  // namespace arksph::distributed
