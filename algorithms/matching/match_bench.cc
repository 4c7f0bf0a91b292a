// Timing of the matching stages on a small simulated block (the full
// `-preset bench` figures come from `roofsweep match`, see the report).
#include <benchmark/benchmark.h>

#include <cmath>

#include "algorithms/matching/match_lines.h"
#include "algorithms/matching/robust_estimate.h"
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

// The a*-b* estimate of one flanking region (150 points, as RegionColour
// caps them; a fifth of them another colour): it runs twice per segment.
void BM_RobustMcd2D(benchmark::State& state) {
  std::vector<Eigen::Vector2d> pts;
  for (int i = 0; i < 150; ++i) {
    const double u = std::sin(i * 12.9898) * 43758.5453, v = std::sin(i * 78.233) * 12345.6789;
    const double du = u - std::floor(u) - 0.5, dv = v - std::floor(v) - 0.5;
    pts.emplace_back(i % 5 == 0 ? Eigen::Vector2d(8 + du, -6 + dv) : Eigen::Vector2d(du, dv));
  }
  unsigned seed = 1;
  for (auto _ : state) benchmark::DoNotOptimize(RobustMcd2D(pts, ++seed, 4).mean.x());
}
BENCHMARK(BM_RobustMcd2D);

}  // namespace
}  // namespace roofsweep
