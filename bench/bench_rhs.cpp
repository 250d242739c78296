// The WCSPH right-hand side: the whole f(t, y) (steady state between neighbour rebuilds, as in a
// running simulation) and each physical term on its own. items_per_second of BM_RhsEval is the
// particle-evaluation rate (target >= 5e6 on 2 threads with about 50 neighbours).
#include <benchmark/benchmark.h>

#include "bench_scenes.hpp"
#include "rhs/terms.hpp"

namespace arksph::bench {
namespace {

// Particle regularisation off: the scene's "auto" turns on shifting and delta-SPH under WCSPH, and
// these two benchmarks measure the f without them.
const std::vector<std::string> kNoRegularisation = {"method.regularisation=\"none\"",
                                                   "method.density_diffusion=\"none\""};

// The f without regularisation: per-particle force terms in one sweep, each neighbourhood gathered once.
void BM_RhsEval(benchmark::State& state) {
  Prepared p = prepare(static_cast<int>(state.range(0)), "wcsph", kNoRegularisation);
  for (auto _ : state) {
    p.model.rhs->eval(0.0, p.y.data(), p.ydot.data());
    benchmark::DoNotOptimize(p.ydot.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long>(p.model.rhs->layout().n));
}

// The default f, with the regularisation of WCSPH: particle shifting and delta-SPH (both in the sweep).
void BM_RhsEvalRegularised(benchmark::State& state) {
  Prepared p = prepare(static_cast<int>(state.range(0)), "wcsph",
                       {"method.regularisation=\"shifting\"", "method.density_diffusion=\"delta_sph\""});
  for (auto _ : state) {
    p.model.rhs->eval(0.0, p.y.data(), p.ydot.data());
    benchmark::DoNotOptimize(p.ydot.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long>(p.model.rhs->layout().n));
}

// BM_RhsEval's f with method.force_sweep = false: the pair list with kernel values stored, then each
// term walks it on its own (the path before the sweep, and still the one of the projection schemes).
void BM_RhsEvalPairWalk(benchmark::State& state) {
  std::vector<std::string> sets = kNoRegularisation;
  sets.push_back("method.force_sweep=false");
  Prepared p = prepare(static_cast<int>(state.range(0)), "wcsph", sets);
  for (auto _ : state) {
    p.model.rhs->eval(0.0, p.y.data(), p.ydot.data());
    benchmark::DoNotOptimize(p.ydot.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long>(p.model.rhs->layout().n));
}

// One term applied to a copy of the fields of a full evaluation.
void BM_Term(benchmark::State& state, const std::string& term_name) {
  Prepared p = prepare(static_cast<int>(state.range(0)), "wcsph");
  FluidFields f = p.model.rhs->fields();
  auto terms = terms_from_scene(p.scene, p.model.sound_speed);
  for (const auto& term : terms) {
    if (term->name() != term_name) continue;
    for (auto _ : state) term->apply(f);
    state.SetItemsProcessed(state.iterations() * static_cast<long>(f.n_real));
    return;
  }
  state.SkipWithError(("no term " + term_name).c_str());
}

BENCHMARK(BM_RhsEval)->Arg(50)->Arg(100)->Arg(240)->UseRealTime()->Unit(benchmark::kMicrosecond);  // wall clock: threads count
BENCHMARK(BM_RhsEvalRegularised)->Arg(50)->Arg(100)->Arg(240)->UseRealTime()->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_RhsEvalPairWalk)->Arg(50)->Arg(100)->Arg(240)->UseRealTime()->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Term, eos, std::string("eos:tait"))->Arg(100)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Term, continuity, std::string("continuity:szewc19"))->Arg(100)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Term, pressure_gradient, std::string("pressure_gradient:colagrossi"))->Arg(100)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Term, viscosity, std::string("viscosity:morris"))->Arg(100)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace arksph::bench
