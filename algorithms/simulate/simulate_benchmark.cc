#include <benchmark/benchmark.h>

#include "algorithms/simulate/presets.h"

namespace roofsweep {
namespace sim {
namespace {

// The `bench` preset end to end: scene, truth, layout and 6 views of
// 2048 x 2048 (the issue asks for well under a minute on 2 cores).
void BM_SimulateBenchPreset(benchmark::State& state) {
  const SimulationOptions o = SimulationPreset("bench");
  NullProgress progress;
  for (auto _ : state) {
    SimulationResult r = Simulate(o, progress);
    benchmark::DoNotOptimize(r.images.back().data);
    state.counters["views"] = static_cast<double>(r.views.size());
    state.counters["buildings"] = static_cast<double>(r.scene.city.buildings.size());
  }
}
BENCHMARK(BM_SimulateBenchPreset)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

// One 2048 x 2048 view of the same scene.
void BM_RenderOneView(benchmark::State& state) {
  const SimulationOptions o = SimulationPreset("bench");
  const Scene scene = GenerateScene(o.scene, o.seed);
  const auto views = LayoutCameras(scene.area, scene.ground.z, o.cameras, o.seed);
  const Renderer renderer(scene, o.render);
  for (auto _ : state) benchmark::DoNotOptimize(renderer.Render(views[0], 0, o.seed).data);
}
BENCHMARK(BM_RenderOneView)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

}  // namespace
}  // namespace sim
}  // namespace roofsweep
