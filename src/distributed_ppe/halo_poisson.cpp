#include "distributed_ppe/halo_poisson.hpp"

#include <chrono>
#include <cstddef>
#include <utility>

namespace arksph::distributed_ppe {

HaloPoisson::HaloPoisson(const parallel::Communicator& comm, HaloValues halo_values,
                         const parallel::RankParticles& owned, std::int64_t pinned_id,
                         std::unique_ptr<RankPoissonSolver> solver)
    : comm_(comm),
      halo_values_(std::move(halo_values)),
      owned_(owned),
      pinned_id_(pinned_id),
      solver_(std::move(solver)) {}

void HaloPoisson::reset() {
  numbered_ = false;
  solver_->invalidate();  // the hierarchy was set up on the old numbering
}

SolveReport HaloPoisson::solve(const FluidFields& f, const std::vector<double>& source, double dt,
                               std::vector<double>& p) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::size_t n = owned_.layout().n;
  if (!numbered_) {  // the rows of the rank's particles, after a deal or migration
    range_ = global_rows(comm_, n);
    pinned_row_ = row_of_id(comm_, owned_.ids(), range_, pinned_id_);
    own_rows_.resize(n);
    for (std::size_t a = 0; a < n; ++a) own_rows_[a] = static_cast<double>(range_.first + static_cast<std::int64_t>(a));
    numbered_ = true;
  }
  // The halo copies' rows (the halo may have been exchanged anew by any f since the last solve).
  const std::vector<double> halo_rows = std::move(halo_values_({&own_rows_}).front());
  row_of_.resize(n + halo_rows.size());
  for (std::size_t a = 0; a < n; ++a) row_of_[a] = range_.first + static_cast<std::int64_t>(a);
  for (std::size_t k = 0; k < halo_rows.size(); ++k) row_of_[n + k] = static_cast<GlobalRow>(halo_rows[k]);
  if (given_.empty()) {
    assemble_rows(comm_, f, n, row_of_, range_, pinned_row_, source, dt, rows_);
  } else {  // the halo copies' flags and values are their owners'
    std::vector<double> fixed(n);
    for (std::size_t a = 0; a < n; ++a) fixed[a] = given_.fixed.at(a) ? 1.0 : 0.0;
    given_.value.resize(n);
    std::vector<std::vector<double>> halo = halo_values_({&fixed, &given_.value});
    given_real_.fixed.assign(given_.fixed.begin(), given_.fixed.begin() + static_cast<std::ptrdiff_t>(n));
    given_real_.value.assign(given_.value.begin(), given_.value.end());
    for (std::size_t k = 0; k < halo[0].size(); ++k) {
      given_real_.fixed.push_back(halo[0][k] != 0.0 ? 1 : 0);
      given_real_.value.push_back(halo[1][k]);
    }
    assemble_rows(comm_, f, n, row_of_, range_, pinned_row_, source, dt, rows_, given_real_);
  }
  assembly_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (p.size() != n) p.assign(n, 0.0);
  return solver_->solve(rows_, p);
}

}  // namespace arksph::distributed_ppe
