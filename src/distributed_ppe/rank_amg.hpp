// The smoothed-aggregation V-cycle of the one-process "cg_amg" solver (projection/poisson/
// amg_hierarchy.hpp: Vanek, Mandel & Brezina 1996; Chebyshev smoothing after Adams et al. 2003) over
// the ranks of a decomposed run, each rank holding its rows of every level.
//
// What is distributed, and how:
//   - Aggregates are built by each rank over its own rows (the strong connections within its block),
//     so no aggregate spans two ranks: the tentative prolongator is block diagonal.
//   - The smoothed prolongator P = (I - omega D^-1 A) P_tent (Vanek et al. §4) reaches across: a row
//     next to another rank's rows takes columns of that rank's aggregates (their global numbers come
//     along the fine level's halo). omega = (4/3) / rho(D^-1 A), rho by a power iteration with global
//     sums.
//   - The Galerkin product A_c = P^T A P (Stüben 2001 eq. 2.2): a rank multiplies its rows of A by P
//     (the rows of P at its halo's points come from their owners), then by its rows' part of P^T.
//     Rows of A_c for another rank's aggregates (P's columns across the boundary) are sent to their
//     owner and added there.
//   - Every level holds its own halo (ghost_exchange.hpp); the V-cycle exchanges it before each
//     product with the level's matrix and the prolongator, and adds the restriction's halo part back
//     to its owners.
//   - The coarsest level (at most max_coarse rows over all ranks) is gathered on every rank and
//     solved there by dense Cholesky: every rank solves the same small system.
// The V-cycle is the same symmetric positive definite operator as one process's when the aggregates
// are (one rank), and a symmetric positive definite one on any rank count, as PCG requires.
#pragma once
#include <Eigen/Dense>
#include <cstdint>
#include <memory>
#include <vector>

#include "distributed_ppe/ghost_exchange.hpp"
#include "parallel/communicator.hpp"
#include "projection/poisson/amg_hierarchy.hpp"

namespace arksph::distributed_ppe {

class RankAmg {
 public:
  RankAmg(const parallel::Communicator& comm, AmgOptions opt = {}) : comm_(comm), opt_(opt) {}
  // Collective. A: this rank's rows, columns numbered as `halo` numbers them (own rows first, then
  // the ghosts), the diagonal at the row's own column. A and halo are read by vcycle(): they must
  // outlive its use, or be replaced by rebind_finest().
  void setup(const CsrRef& A, const GhostExchange& halo);
  // Points the finest level at a new matrix of the same rows (its halo may differ); the coarse
  // levels stay those of the last set-up.
  void rebind_finest(const CsrRef& A, const GhostExchange& halo);
  // Collective. z = M r on this rank's rows: one V-cycle from a zero guess. z: at least as many
  // entries as the finest level's own rows and ghosts.
  void vcycle(const double* r, double* z) const;
  int levels() const { return static_cast<int>(coarse_.size()) + 1; }
  std::int64_t global_size(int level) const { return offsets(level).back(); }
  bool ready() const { return halo0_ != nullptr; }

 private:
  struct Coarse {  // a level below the finest: its rows, its halo, every rank's first row
    CsrOwned A;
    GhostExchange halo;
    std::vector<std::int64_t> offsets;
  };
  CsrRef op(int level) const { return level == 0 ? A0_ : coarse_[static_cast<std::size_t>(level) - 1].A.ref(); }
  const GhostExchange& halo(int level) const {
    return level == 0 ? *halo0_ : coarse_[static_cast<std::size_t>(level) - 1].halo;
  }
  const std::vector<std::int64_t>& offsets(int level) const {
    return level == 0 ? offsets0_ : coarse_[static_cast<std::size_t>(level) - 1].offsets;
  }
  double spectral_radius(int level) const;
  // The coarse level below `level` from its aggregates (nc on this rank).
  void build_level(int level, const std::vector<int>& agg, int nc);
  void finish();
  void size_work(int level);
  void smooth(int level, const double* b, double* x, bool zero_guess) const;
  void cycle(int level, const double* b, double* x) const;

  const parallel::Communicator& comm_;
  AmgOptions opt_;
  CsrRef A0_;
  const GhostExchange* halo0_ = nullptr;
  std::vector<std::int64_t> offsets0_;
  std::vector<Coarse> coarse_;
  std::vector<CsrOwned> prolong_;   // level l's rows x level l + 1's columns (own, then its ghosts)
  std::vector<CsrOwned> restrict_;  // P^T: level l + 1's own and ghost rows x level l's own columns
  std::vector<std::vector<double>> inv_diag_;
  std::vector<double> rho_;
  Eigen::LLT<Eigen::MatrixXd> coarsest_;
  mutable std::vector<std::vector<double>> r_, b_, x_, d_, t_;
};

}  // namespace arksph::distributed_ppe
