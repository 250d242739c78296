// ISPH pressure Poisson equation: divergence + assembly (C&R eqs. 17, 19) and each solver. KLU is
// timed both fresh (symbolic + numeric factorisation) and as in a running simulation (same pattern,
// numeric refactorisation only); CG and CG-IC warm-started from the previous pressure, as in a run.
// The GPPS grid Poisson solve (grid_poisson.hpp) on an n x n walled grid of uniform density: KLU's
// triangular solves with the factorisation made once, and the transforms.
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "bench_scenes.hpp"
#include "projection/grid/grid_poisson.hpp"
#include "projection/poisson/amg_hierarchy.hpp"
#include "projection/poisson/poisson_solver.hpp"
#include "projection/ppe_assembly.hpp"

namespace arksph::bench {
namespace {

constexpr double kDt = 1e-3;

void BM_PpeAssembly(benchmark::State& state) {
  Prepared p = prepare(static_cast<int>(state.range(0)), "isph");
  const FluidFields& f = p.model.rhs->fields();
  PoissonSystem sys;  // reused, as in a running simulation
  for (auto _ : state) {
    const auto div = divergence_cummins_rudman(f);
    assemble_ppe(f, div, kDt, sys);
    benchmark::DoNotOptimize(sys.b.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long>(f.n_real));
}

// fresh: a new solver object each time (full factorisation / cold start); else one solver reused.
void BM_Solve(benchmark::State& state, const std::string& solver, bool fresh) {
  Prepared p = prepare(static_cast<int>(state.range(0)), "isph");
  const FluidFields& f = p.model.rhs->fields();
  const PoissonSystem sys = assemble_ppe(f, divergence_cummins_rudman(f), kDt);
  auto s = make_poisson_solver(solver, 1e-8);
  std::vector<double> pressure(f.n_real, 0.0);
  s->solve(sys.A, sys.b, pressure);  // warm-up: the state of a solver in a running simulation
  long iterations = 0;
  // A running simulation solves a nearby system each step: perturb the source by 1e-3 relative.
  std::vector<double> b = sys.b;
  int k = 0;
  for (auto _ : state) {
    for (std::size_t i = 0; i < b.size(); ++i) b[i] = sys.b[i] * (1.0 + 1e-3 * ((i + k) % 7 == 0));
    ++k;
    if (fresh) {
      s = make_poisson_solver(solver, 1e-8);
      std::fill(pressure.begin(), pressure.end(), 0.0);
    }
    iterations += s->solve(sys.A, b, pressure).iterations;
  }
  state.counters["iterations"] = static_cast<double>(iterations) / static_cast<double>(state.iterations());
  state.counters["N"] = static_cast<double>(f.n_real);
}

// Setup of the aggregation AMG hierarchy of "cg_amg" (aggregates, prolongators, Galerkin products,
// smoother bounds, coarsest Cholesky): paid once per rebuild, not per solve.
void BM_AmgSetup(benchmark::State& state) {
  Prepared p = prepare(static_cast<int>(state.range(0)), "isph");
  const FluidFields& f = p.model.rhs->fields();
  const PoissonSystem sys = assemble_ppe(f, divergence_cummins_rudman(f), kDt);
  AmgHierarchy amg;
  for (auto _ : state) amg.setup(csr_view(sys.A));
  long nnz = 0;
  for (int l = 0; l < amg.levels(); ++l) nnz += amg.nonzeros(l);
  state.counters["levels"] = amg.levels();
  state.counters["coarse1"] = amg.levels() > 1 ? amg.size(1) : 0;
  state.counters["op_complexity"] = static_cast<double>(nnz) / static_cast<double>(amg.nonzeros(0));
  state.counters["N"] = static_cast<double>(f.n_real);
}

// The parts of one cg_amg iteration: a product with the PPE matrix, and one V-cycle.
void BM_AmgParts(benchmark::State& state, bool vcycle) {
  Prepared p = prepare(static_cast<int>(state.range(0)), "isph");
  const FluidFields& f = p.model.rhs->fields();
  const PoissonSystem sys = assemble_ppe(f, divergence_cummins_rudman(f), kDt);
  AmgHierarchy amg;
  amg.setup(csr_view(sys.A));
  std::vector<double> z(sys.b.size());
  for (auto _ : state) {
    if (vcycle) amg.vcycle(sys.b.data(), z.data());
    else csr_multiply(csr_view(sys.A), sys.b.data(), z.data());
    benchmark::DoNotOptimize(z.data());
  }
  state.counters["nnz"] = static_cast<double>(sys.A.nonZeros());
}

void BM_GridSolve(benchmark::State& state, GridPoisson::Solver solver) {
  GridSpec g;
  g.nx = g.ny = static_cast<int>(state.range(0));
  g.h = 1.0 / g.nx;
  GridPoisson poisson(g, solver);
  poisson.set_density(std::vector<double>(g.cells(), 1.0));  // KLU factorises here, outside the timing
  std::vector<double> s(g.cells()), p;
  for (std::size_t c = 0; c < s.size(); ++c) s[c] = std::sin(1e-3 * static_cast<double>(c * c));
  for (auto _ : state) {
    poisson.solve(s, p);
    benchmark::DoNotOptimize(p.data());
  }
}

BENCHMARK_CAPTURE(BM_GridSolve, klu, GridPoisson::Solver::klu)->Arg(240)->Arg(480)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_GridSolve, transform, GridPoisson::Solver::automatic)->Arg(240)->Arg(480)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PpeAssembly)->Arg(50)->Arg(100)->Arg(240)->Arg(500)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Solve, klu_fresh, std::string("klu"), true)->Arg(50)->Arg(100)->Arg(240)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Solve, klu_same_pattern, std::string("klu"), false)->Arg(50)->Arg(100)->Arg(240)->Unit(benchmark::kMillisecond);
// N = 2,500 ... 250,000 for the iterative solvers (KLU above 57,600 takes minutes per factorisation).
BENCHMARK_CAPTURE(BM_Solve, cg_warm, std::string("cg"), false)->Arg(50)->Arg(100)->Arg(240)->Arg(500)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Solve, cg_ic_warm, std::string("cg_ic"), false)->Arg(50)->Arg(100)->Arg(240)->Arg(500)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Solve, cg_amg_warm, std::string("cg_amg"), false)->Arg(50)->Arg(100)->Arg(240)->Arg(500)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_AmgParts, spmv, false)->Arg(240)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_AmgParts, vcycle, true)->Arg(240)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_AmgSetup)->Arg(50)->Arg(100)->Arg(240)->Arg(500)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Solve, cg_cold, std::string("cg"), true)->Arg(50)->Arg(100)->Arg(240)->Arg(500)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Solve, cg_amg_cold, std::string("cg_amg"), true)->Arg(50)->Arg(100)->Arg(240)->Arg(500)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace arksph::bench
