// Neighbour search: cell list, Verlet candidates (radius + skin) and the pair list with kernel values.
#include <benchmark/benchmark.h>

#include "bench_scenes.hpp"
#include "integrate/dependency_pattern.hpp"
#include "neighbors/cell_list.hpp"

namespace arksph::bench {
namespace {

void BM_CellListBuild(benchmark::State& state) {
  Prepared p = prepare(static_cast<int>(state.range(0)), "wcsph");
  const FluidFields& f = p.model.rhs->fields();
  CellList cells;
  const double radius = 1.15 * f.kernel->radius();
  for (auto _ : state) cells.build(f.x.data(), f.y.data(), f.n_all, radius);
  state.SetItemsProcessed(state.iterations() * static_cast<long>(f.n_real));
}

void BM_Candidates(benchmark::State& state) {
  Prepared p = prepare(static_cast<int>(state.range(0)), "wcsph");
  const FluidFields& f = p.model.rhs->fields();
  CellList cells;
  cells.build(f.x.data(), f.y.data(), f.n_all, 1.15 * f.kernel->radius());
  CandidateList cand;
  for (auto _ : state) build_candidates(cells, f.x.data(), f.y.data(), f.n_real, cand);
  state.SetItemsProcessed(state.iterations() * static_cast<long>(f.n_real));
}

void BM_PairsFromCandidates(benchmark::State& state) {
  Prepared p = prepare(static_cast<int>(state.range(0)), "wcsph");
  const FluidFields& f = p.model.rhs->fields();
  CellList cells;
  cells.build(f.x.data(), f.y.data(), f.n_all, 1.15 * f.kernel->radius());
  CandidateList cand;
  build_candidates(cells, f.x.data(), f.y.data(), f.n_real, cand);
  PairList pairs;
  for (auto _ : state) pairs_from_candidates(cand, *f.kernel, f.x.data(), f.y.data(), pairs);
  std::size_t total = 0;
  for (std::size_t a = 0; a < f.n_real; ++a) total += pairs.count[a];
  state.counters["neighbours"] = static_cast<double>(total) / static_cast<double>(f.n_real);
  state.SetItemsProcessed(state.iterations() * static_cast<long>(f.n_real));
}

// The IMEX dependency pattern (time.imex) at the radius of a one-pass viscosity model with mirror
// walls, R + dx / 2 (the Jacobian's skin): the cell-list search, and the all-pairs search it replaced.
template <bool Brute>
void BM_ImexPattern(benchmark::State& state) {
  Prepared p = prepare(static_cast<int>(state.range(0)), "wcsph");
  const FluidFields& f = p.model.rhs->fields();
  PeriodicAxes axes;
  axes.periodic[0] = axes.periodic[1] = true;
  const double radius = f.kernel->radius() + 0.5 * p.scene.spacing;
  std::size_t entries = 0;
  for (auto _ : state) {
    const auto pat = Brute ? dependency_pattern_brute(f.x.data(), f.y.data(), f.n_real, radius, axes)
                           : dependency_pattern(f.x.data(), f.y.data(), f.n_real, radius, axes);
    entries = 0;
    for (const auto& row : pat) entries += row.size();
  }
  state.counters["per_row"] = static_cast<double>(entries) / static_cast<double>(f.n_real);
  state.SetItemsProcessed(state.iterations() * static_cast<long>(f.n_real));
}

BENCHMARK_TEMPLATE(BM_ImexPattern, false)->Name("BM_ImexPattern")->Arg(50)->Arg(100)->Arg(240)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_ImexPattern, true)->Name("BM_ImexPatternBrute")->Arg(50)->Arg(100)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CellListBuild)->Arg(50)->Arg(100)->Arg(240)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Candidates)->Arg(50)->Arg(100)->Arg(240)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PairsFromCandidates)->Arg(50)->Arg(100)->Arg(240)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace arksph::bench
