#include "projection/local_domain.hpp"

#include <algorithm>
#include <chrono>
#include <numeric>


namespace arksph {

LocalPoisson::LocalPoisson(const std::string& solver, double tolerance, bool exact_operator)
    : tolerance_(tolerance), exact_operator_(exact_operator), solver_(make_poisson_solver(solver, tolerance)) {}

SolveReport LocalPoisson::solve(const FluidFields& f, const std::vector<double>& source, double dt,
                                std::vector<double>& p) {
  const auto t0 = std::chrono::steady_clock::now();
  if (exact_operator_)
    system_ = assemble_ppe_exact(f, source, dt);
  else
    assemble_ppe(f, source, dt, given_, system_);
  assembly_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (p.size() != f.n_real) p.assign(f.n_real, 0.0);
  return solver_->solve(system_.A, system_.b, p);
}

LocalDomain::LocalDomain(const Scene& scene, RhsEvaluator& rhs) : rhs_(rhs) {
  if (scene.pressure_in_f()) {
    RhsOptions o = rhs_.options();
    o.pairs_at_every_f = true;  // the constrained projection walks the pairs of each f
    rhs_.set_options(o);
  }
}

double LocalDomain::level(const std::vector<double>& p, bool zero_min) const {
  return zero_min ? *std::min_element(p.begin(), p.end())
                  : std::accumulate(p.begin(), p.end(), 0.0) / static_cast<double>(p.size());
}

std::unique_ptr<ParticlePoisson> LocalDomain::poisson(const Scene& scene, bool exact_operator) {
  return std::make_unique<LocalPoisson>(scene.ppe_solver, scene.ppe_tolerance, exact_operator);
}

}  // namespace arksph
