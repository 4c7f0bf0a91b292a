// Timing of the matching stages on a small simulated block (the full
// `-preset bench` figures come from `roofsweep match`, see the report).
#include <benchmark/benchmark.h>

#include "algorithms/matching/match_lines.h"
#include "algorithms/matching/sim_block_fixture.h"

namespace roofsweep {
namespace {

const SimBlock& Block512() {
  static const SimBlock d = SimulateSmallBlock(1);
  return d;
}

void BM_MatchLines512(benchmark::State& state) {
  const SimBlock& d = Block512();
  for (auto _ : state) {
    NullProgress np;
    const MatchResult r = MatchLines(d.block, d.images, MatchOptions{}, EdgeOptions{}, np);
    benchmark::DoNotOptimize(r.lines.size());
    state.counters["edges_s"] = r.timings.edges_s;
    state.counters["features_s"] = r.timings.features_s;
    state.counters["candidates_s"] = r.timings.candidates_s;
    state.counters["lines"] = static_cast<double>(r.lines.size());
  }
}
BENCHMARK(BM_MatchLines512)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace
}  // namespace roofsweep
