#include "distributed/halo_domain.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "core/errors.hpp"
#include "distributed_ppe/halo_poisson.hpp"
#include "parallel/agreement.hpp"

namespace arksph::distributed {

void HaloDomain::refresh(double t, const double* y) {
  Verdict refreshed;
  try {
    f_.eval(t, y, nullptr);
  } catch (const NumericalFailure& e) {
    refreshed = {3, e.what()};
  }
  refreshed = parallel::agree(comm_, refreshed);
  if (refreshed.code) throw NumericalFailure(refreshed.message);
}

double HaloDomain::level(const std::vector<double>& p, bool zero_min) const {
  if (zero_min) {
    double lowest = std::numeric_limits<double>::infinity();
    for (double x : p) lowest = std::min(lowest, x);
    return -comm_.max(-lowest);
  }
  double sum = 0;
  for (double x : p) sum += x;
  return comm_.sum(sum) / static_cast<double>(comm_.sum(static_cast<std::int64_t>(p.size())));
}

std::vector<double> HaloDomain::with_halo(const std::vector<double>& own) const {
  std::vector<double> all(own);
  const std::vector<double> copies = std::move(f_.halo_values({&own}).front());
  all.insert(all.end(), copies.begin(), copies.end());
  return all;
}

std::pair<std::vector<double>, std::vector<double>> HaloDomain::with_halo(const std::vector<double>& a,
                                                                        const std::vector<double>& b) const {
  std::vector<std::vector<double>> copies = f_.halo_values(std::vector<const std::vector<double>*>{&a, &b});
  std::pair<std::vector<double>, std::vector<double>> all(a, b);
  all.first.insert(all.first.end(), copies[0].begin(), copies[0].end());
  all.second.insert(all.second.end(), copies[1].begin(), copies[1].end());
  return all;
}

CellCombine HaloDomain::cell_combine() const {
  return [this](std::vector<double>& sums, std::vector<double>& maxima) {
    if (!sums.empty()) comm_.sum_in_place(sums);  // every rank passes the same sizes
    if (!maxima.empty()) comm_.max_in_place(maxima);
  };
}

CorrectionSpan HaloDomain::correction_span() const {
  CorrectionSpan s;
  s.own = owned_.layout().n;
  s.sum = [this](double v) { return comm_.sum(v); };
  s.extend = [this](std::vector<double>& v) {
    const std::vector<double> copies = std::move(f_.halo_values({&v}).front());
    v.insert(v.end(), copies.begin(), copies.end());
    if (v.size() != f_.evaluator().fields().n_real)
      throw std::logic_error("density correction: the halo values do not match the evaluator's points");
  };
  s.gather = [this](const std::vector<double>& v) { return comm_.allgatherv(v); };
  s.any = [this](bool v) { return comm_.max(static_cast<std::int64_t>(v)) > 0; };
  return s;
}

std::unique_ptr<ParticlePoisson> HaloDomain::poisson(const Scene& scene, bool exact_operator) {
  if (exact_operator)
    throw InputError(scene.source + ": method.ppe_operator = \"exact\" runs on one process only");
  HaloRhs& f = f_;
  auto halo_values = [&f](const std::vector<const std::vector<double>*>& own) { return f.halo_values(own); };
  return std::make_unique<distributed_ppe::HaloPoisson>(
      comm_, halo_values, owned_, pinned_id_,
      distributed_ppe::make_rank_poisson_solver(scene.rank_ppe_solver, comm_, scene.ppe_tolerance));
}

}  // namespace arksph::distributed
