// Neighbour search: cell list, Verlet candidates (radius + skin) and the pair list with kernel values.
#include <benchmark/benchmark.h>

#include "bench_scenes.hpp"
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

BENCHMARK(BM_CellListBuild)->Arg(50)->Arg(100)->Arg(240)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Candidates)->Arg(50)->Arg(100)->Arg(240)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PairsFromCandidates)->Arg(50)->Arg(100)->Arg(240)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace arksph::bench
