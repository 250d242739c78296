#include "distributed/halo_constrained_pressure.hpp"

#include <tuple>

#include "distributed/halo_density_correction.hpp"
#include "projection/divergence_operator.hpp"
#include "projection/ppe_assembly.hpp"
#include "projection/velocity_correction.hpp"

namespace arksph::distributed {

HaloConstrainedPressure::HaloConstrainedPressure(const Scene& scene, const parallel::Communicator& comm, HaloRhs& f,
                                                 const RankParticles& owned, std::int64_t pinned_id, double flow_rate)
    : comm_(comm),
      f_(f),
      owned_(owned),
      split_(scene),
      relaxation_(scene.constraint_relaxation * flow_rate),
      zero_min_level_(scene.ppe_pressure_level == "zero_min"),
      poisson_(comm, f, owned, pinned_id, scene.ppe_tolerance) {
  if (scene.density_correction == "pozorski_wawrenczuk")
    density_ = std::make_unique<DensityRelaxation>(scene, scene.correction_relaxation * flow_rate);
}

void HaloConstrainedPressure::particles_moved() {
  poisson_.particles_moved();
  solution_.clear();
}

distributed_ppe::HypreSolveReport HaloConstrainedPressure::constrain(const double* y, double* ydot) {
  const FluidFields& f = f_.evaluator().fields();
  const StateLayout L = owned_.layout();
  const std::size_t n = L.n;
  const bool two_d = L.dim == 2;
  const double* u = y + L.vel(0);
  const double* v = two_d ? y + L.vel(1) : nullptr;
  // 1. w = a* + alpha u (less g under the split), then at the copies from their owners.
  std::vector<double> wx(n), wy(two_d ? n : 0);
  for (std::size_t a = 0; a < n; ++a) {
    wx[a] = ydot[L.vel(0) + a] + relaxation_ * u[a];
    if (two_d) wy[a] = ydot[L.vel(1) + a] + relaxation_ * v[a];
  }
  if (split_.active()) {
    std::vector<double> bx, by;
    split_.at(n, f.x.data(), two_d ? f.y.data() : nullptr, f.t, bx, by);
    for (std::size_t a = 0; a < n; ++a) {
      wx[a] -= bx[a];
      if (two_d) wy[a] -= by[a];
    }
  }
  std::vector<double> wx_all, wy_all;
  if (two_d)
    std::tie(wx_all, wy_all) = poisson_.with_halo(wx, wy);  // one all-to-all for both components
  else
    wx_all = poisson_.with_halo(wx);
  // 2. D w - Q at every real point (only the rank's particles are used), the copies' velocities
  // those of the evaluator's state.
  const StateLayout& E = f_.evaluator().layout();
  const double* state = f_.evaluated_state();
  std::vector<double> div(f.n_real);
  divergence_minus_motion(f, wx_all.data(), two_d ? wy_all.data() : nullptr, state + E.vel(0),
                          two_d ? state + E.vel(1) : nullptr, div.data());
  div.resize(n);
  if (split_.active()) {
    const std::vector<double> dg = split_.divergence(f), flux = neumann_source(f);
    for (std::size_t a = 0; a < n; ++a) div[a] += dg[a] + flux[a];
  }
  const distributed_ppe::HypreSolveReport rep = poisson_.solve(div, 1.0, solution_);
  // 3. The level over all ranks, then du/dt -= G p with the copies' p their owners'.
  const double level = poisson_.level(solution_, zero_min_level_);
  p_.resize(n);
  for (std::size_t a = 0; a < n; ++a) p_[a] = solution_[a] - level;
  subtract_pressure_gradient(f, poisson_.with_halo(p_), 1.0, n, ydot + L.vel(0), two_d ? ydot + L.vel(1) : nullptr);
  // 4. The P-W correction as a velocity in dr/dt.
  if (density_)
    density_->add_velocity(f, rank_correction_span(comm_, f_, n), ydot + L.pos(0), two_d ? ydot + L.pos(1) : nullptr);
  return rep;
}

distributed_ppe::HypreSolveReport HaloConstrainedPressure::project_velocity(double t, double* y) {
  f_.eval(t, y, nullptr);
  const FluidFields& f = f_.evaluator().fields();
  const StateLayout L = owned_.layout();
  const std::size_t n = L.n;
  const bool two_d = L.dim == 2;
  const StateLayout& E = f_.evaluator().layout();
  const double* state = f_.evaluated_state();
  std::vector<double> div(f.n_real);
  difference_divergence(f, state + E.vel(0), two_d ? state + E.vel(1) : nullptr, div.data());
  div.resize(n);
  // phi is a potential, not the pressure: its own cold start, the pressure's warm start kept apart.
  std::vector<double> phi;
  const distributed_ppe::HypreSolveReport rep = poisson_.solve(div, 1.0, phi);
  const double level = poisson_.level(phi, zero_min_level_);
  for (double& x : phi) x -= level;
  subtract_pressure_gradient(f, poisson_.with_halo(phi), 1.0, n, y + L.vel(0), two_d ? y + L.vel(1) : nullptr,
                             false);
  return rep;
}

}  // namespace arksph::distributed
