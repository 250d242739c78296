#include "distributed/halo_density_correction.hpp"

#include <chrono>
#include <stdexcept>

namespace arksph::distributed {

HaloDensityCorrection::HaloDensityCorrection(const Scene& scene, const parallel::Communicator& comm, HaloRhs& f,
                                             const RankParticles& owned, std::int64_t pinned_id)
    : comm_(comm),
      f_(f),
      owned_(owned),
      threshold_(scene.correction_threshold),
      max_iterations_(scene.correction_max_iterations),
      spacing_(scene.spacing),
      newton_(scene.correction_solver == "newton"),
      pinned_id_(pinned_id),
      solver_(comm, scene.ppe_tolerance) {}

void HaloDensityCorrection::particles_moved() {
  pstar_.clear();
  solver_.invalidate();
}

void HaloDensityCorrection::fixed_point_step(const std::vector<double>& s, double* y) {
  const StateLayout L = owned_.layout();
  const std::size_t n = L.n;
  const FluidFields& f = f_.evaluator().fields();
  // Rows: the rank's particles numbered after the ranks below, the copies carrying their owners'.
  const distributed_ppe::RowRange range = distributed_ppe::global_rows(comm_, n);
  const distributed_ppe::GlobalRow pinned = distributed_ppe::row_of_id(comm_, owned_.ids(), range, pinned_id_);
  std::vector<double> own_rows(n);
  for (std::size_t a = 0; a < n; ++a) own_rows[a] = static_cast<double>(range.first + static_cast<std::int64_t>(a));
  const std::vector<double> halo_rows = f_.halo_values(own_rows);
  std::vector<distributed_ppe::GlobalRow> row_of(n + halo_rows.size());
  for (std::size_t a = 0; a < n; ++a) row_of[a] = range.first + static_cast<std::int64_t>(a);
  for (std::size_t k = 0; k < halo_rows.size(); ++k) row_of[n + k] = static_cast<distributed_ppe::GlobalRow>(halo_rows[k]);
  // Eq. 58 with the Laplacian of C&R eq. 19 at rho = rho0: the PPE's rows with the source 1 -
  // rho~/rho0 in place of div u* and dt = 1 (as one process's assemble_ppe(f, source, 1.0)).
  distributed_ppe::assemble_rows(comm_, f, n, row_of, range, pinned, s, 1.0, rows_);
  if (pstar_.size() != n) pstar_.assign(n, 0.0);
  solver_.solve(rows_, pstar_);
  ++stats_.iterations;
  // Eq. 57: r_a -= grad p*_a / rho0, the gradient in difference form with the copies' p* their owners'.
  std::vector<double> p_all(pstar_);
  const std::vector<double> halo_p = f_.halo_values(pstar_);
  p_all.insert(p_all.end(), halo_p.begin(), halo_p.end());
  std::vector<double> dx, dy;
  correction_shift(f, p_all, dx, dy, n);
  for (std::size_t a = 0; a < n; ++a) {
    y[L.pos(0) + a] += dx[a];
    if (L.dim == 2) y[L.pos(1) + a] += dy[a];
  }
}

CorrectionSpan HaloDensityCorrection::span() const {
  CorrectionSpan s;
  s.own = owned_.layout().n;
  s.sum = [this](double v) { return comm_.sum(v); };
  s.extend = [this](std::vector<double>& v) {
    const std::vector<double> copies = f_.halo_values(v);
    v.insert(v.end(), copies.begin(), copies.end());
    if (v.size() != f_.evaluator().fields().n_real)
      throw std::logic_error("density correction: the halo values do not match the evaluator's points");
  };
  s.gather = [this](const std::vector<double>& v) { return comm_.allgatherv(v); };
  s.any = [this](bool v) { return comm_.max(static_cast<std::int64_t>(v)) > 0; };
  return s;
}

void HaloDensityCorrection::apply(double t, double* y) {
  const auto t0 = std::chrono::steady_clock::now();
  const bool record = stats_.applications == 0;
  f_.eval(t, y, nullptr);
  std::vector<double> s;
  double error = density_fluctuation(f_.evaluator().fields(), span(), s);
  if (error <= threshold_) return;
  ++stats_.applications;
  if (record) stats_.first_history.push_back(error);
  if (newton_) {
    const NewtonCorrectionResult r = correct_density_newton(
        [&](const double* state) { f_.eval(t, state, nullptr); },
        [&]() -> const FluidFields& { return f_.evaluator().fields(); }, [&] { return span(); }, owned_.layout(), y,
        max_iterations_, threshold_, spacing_);
    stats_.iterations += r.iterations;
    error = r.error;
  } else {
    for (int it = 0; it < max_iterations_ && error > threshold_; ++it) {
      if (it > 0 && record) stats_.first_history.push_back(error);
      fixed_point_step(s, y);
      // The error after the shift decides whether to go on; after the last allowed solve it is
      // only wanted for the recorded history.
      if (it + 1 < max_iterations_ || record) {
        f_.eval(t, y, nullptr);
        error = density_fluctuation(f_.evaluator().fields(), span(), s);
      }
    }
  }
  if (record) stats_.first_history.push_back(error);
  stats_.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace arksph::distributed
