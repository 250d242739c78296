// hypre's BoomerAMG-preconditioned PCG (distributed_ppe/hypre_poisson.hpp) on P ranks beside the
// one-process "cg_amg" solver on the same pressure Poisson matrix (bench/RESULTS.md, "hypre").
//
//   mpirun -n P build/bench/arksph_bench_hypre SCENE.toml [KEY=VALUE ...]
//
// Every rank builds the scene's lattice jittered by up to 0.2 dx (the matrix of a disordered
// particle set rather than the perfect lattice) and the one-process system (assemble_ppe); each rank
// then assembles its own rows over its particles and halo (as tests/mpi/ppe_fixture.hpp does for the
// tests). Two sources: a random one (every wavelength, the hard case for a multigrid cycle) and
// the smooth one of div(u) = sin(2 pi x) sin(2 pi y). Solves start from zero, with the scene's
// method.ppe_tolerance. Rank 0 prints one line per source: N, ranks, hypre's iterations, setup and
// solve seconds (the fastest of kRepeats), the seconds and iterations of a second solve that keeps
// the hierarchy (matrix hand-over and PCG: the case of a run between set-ups), and cg_amg's iterations, setup + solve and reused-
// hierarchy solve seconds on rank 0 alone (the others wait).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <random>
#include <string>
#include <vector>

#include "distributed_ppe/rank_poisson_solver.hpp"
#include "ppe_fixture.hpp"
#include "projection/poisson/poisson_solver.hpp"

using namespace arksph;
using namespace arksph::parallel;
using namespace arksph::parallel::testing;

namespace {

constexpr int kRepeats = 3;

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The source -V (s - mean s) / dt of assemble_ppe for the values s (by one-process index), pinned 0.
std::vector<double> scaled_source(const OneProcessPpe& one, const std::vector<double>& s) {
  const FluidFields& f = one.rhs->fields();
  double mean = 0;
  for (double v : s) mean += v;
  mean /= static_cast<double>(s.size());
  std::vector<double> b(s.size());
  for (std::size_t a = 0; a < s.size(); ++a) b[a] = -(f.m[a] / f.rho[a]) * (s[a] - mean) / kPpeDt;
  b[0] = 0.0;
  return b;
}

void run(const Communicator& comm, OneProcessPpe& one, RankPpe& mine, const std::string& source, double tol,
         const std::string& solver) {
  const std::size_t n = one.particles.n;
  std::vector<double> s(n);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t a = 0; a < n; ++a) {
    const double x = one.particles.init_pos[0][a], y = one.particles.init_pos[1][a];
    s[a] = source == "random" ? u(rng) : std::sin(2 * M_PI * x) * std::sin(2 * M_PI * y);
  }
  one.sys.b = scaled_source(one, s);
  for (std::size_t a = 0; a < mine.rows.size(); ++a) mine.rows.b[a] = one.sys.b[mine.index_of[a]];

  const auto made = distributed_ppe::make_rank_poisson_solver(solver, comm, tol);
  distributed_ppe::RankPoissonSolver& hypre = *made;
  double h_setup = 1e300, h_solve = 1e300, h_res = 0, h_again = 1e300;
  int h_its = 0, h_its_again = 0;
  for (int k = 0; k < kRepeats; ++k) {
    std::vector<double> p;
    comm.barrier();
    hypre.invalidate();  // BoomerAMG set up for this solve
    const auto rep = hypre.solve(mine.rows, p);
    h_setup = std::min(h_setup, comm.max(rep.setup_seconds));
    h_solve = std::min(h_solve, comm.max(rep.solve_seconds));
    h_its = rep.iterations;
    h_res = rep.relative_residual;
    std::fill(p.begin(), p.end(), 0.0);
    comm.barrier();
    const auto again = hypre.solve(mine.rows, p);  // the hierarchy kept (as a run reuses it)
    h_again = std::min(h_again, comm.max(again.setup_seconds + again.solve_seconds));
    h_its_again = again.iterations;
  }
  comm.barrier();
  if (comm.rank() != 0) {
    comm.barrier();
    return;
  }
  double c_first = 1e300, c_again = 1e300, c_res = 0;
  int c_its = 0, c_its_again = 0;
  for (int k = 0; k < kRepeats; ++k) {
    auto cg = make_poisson_solver("cg_amg", tol);
    std::vector<double> p(n, 0.0);
    auto t0 = std::chrono::steady_clock::now();
    const SolveReport r1 = cg->solve(one.sys.A, one.sys.b, p);
    c_first = std::min(c_first, seconds_since(t0));
    std::fill(p.begin(), p.end(), 0.0);
    t0 = std::chrono::steady_clock::now();
    const SolveReport r2 = cg->solve(one.sys.A, one.sys.b, p);  // hierarchy kept: the solve alone
    c_again = std::min(c_again, seconds_since(t0));
    c_its = r1.iterations;
    c_its_again = r2.iterations;
    c_res = r1.relative_residual;
  }
  std::printf("%-7s N=%zu ranks=%d tol=%.0e | %s: %d its, setup %.3f s, solve %.3f s, total %.3f s, residual %.1e,"
              " hierarchy kept %.3f s (%d its)"
              " | cg_amg: %d its, setup+solve %.3f s, solve alone %.3f s (%d its), residual %.1e | ratio its %.2f\n",
              source.c_str(), n, comm.size(), tol, solver.c_str(), h_its, h_setup, h_solve, h_setup + h_solve, h_res, h_again,
              h_its_again, c_its, c_first, c_again, c_its_again, c_res, static_cast<double>(h_its) / c_its);
  std::fflush(stdout);
  comm.barrier();
}

}  // namespace

int main(int argc, char** argv) {
  MpiSession session(&argc, &argv);
  const Communicator comm;
  if (argc < 2) {
    if (comm.rank() == 0) std::fprintf(stderr, "usage: arksph_bench_hypre SCENE.toml [KEY=VALUE ...]\n");
    return 2;
  }
  try {
    const std::vector<std::string> sets(argv + 2, argv + argc);
    OneProcessPpe one(read_scene_file(argv[1], sets));
    const auto t0 = std::chrono::steady_clock::now();
    RankPpe mine(comm, one);
    const double assembly = comm.max(seconds_since(t0));
    if (comm.rank() == 0)
      std::printf("N=%zu ranks=%d: rank set-up (halo, fields, rows) %.2f s, rows per rank %zu on rank 0\n", one.particles.n,
                  comm.size(), assembly, mine.rows.size());
    for (const std::string solver : {"amg", "hypre"})
      for (const std::string source : {"random", "smooth"}) run(comm, one, mine, source, one.scene.ppe_tolerance, solver);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "arksph_bench_hypre: %s\n", e.what());
    return 2;
  }
  return 0;
}
