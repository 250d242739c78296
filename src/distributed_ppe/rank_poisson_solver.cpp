#include "distributed_ppe/rank_poisson_solver.hpp"

#include <stdexcept>

#include "distributed_ppe/rank_amg_poisson.hpp"
#ifdef ARKSPH_WITH_HYPRE
#include "distributed_ppe/hypre_poisson.hpp"
#endif

namespace arksph::distributed_ppe {

std::vector<std::string> rank_poisson_solver_names() {
#ifdef ARKSPH_WITH_HYPRE
  return {"auto", "amg", "hypre"};
#else
  return {"auto", "amg"};
#endif
}

// "auto" is "amg": on the Re = 1000 cavity over 2 ranks a step takes less time with it than with
// hypre's BoomerAMG (bench/RESULTS.md, "The ranks' cg_amg").
std::string resolved_rank_poisson_solver(const std::string& name) {
  return name == "auto" ? "amg" : name;
}

std::unique_ptr<RankPoissonSolver> make_rank_poisson_solver(const std::string& name, const parallel::Communicator& comm,
                                                            double tolerance) {
  const std::string resolved = resolved_rank_poisson_solver(name);
  if (resolved == "amg")
    return std::make_unique<RankAmgPoisson>(comm, tolerance);
#ifdef ARKSPH_WITH_HYPRE
  if (resolved == "hypre")
    return std::make_unique<HyprePoisson>(comm, tolerance);
#endif
  throw std::invalid_argument("no rank Poisson solver named \"" + name + "\"");
}

}  // namespace arksph::distributed_ppe
