// Timing of the matching stages on a small simulated block (the full
// `-preset bench` figures come from `roofsweep match`, see the report).
#include <benchmark/benchmark.h>

#include "algorithms/matching/match_lines.h"
#include "algorithms/simulate/presets.h"

namespace roofsweep {
namespace {

struct Data {
  Block block;
  std::vector<cv::Mat> images;
};

const Data& Block512() {
  static const Data d = [] {
    sim::SimulationOptions o = sim::SimulationPreset("realistic");
    o.cameras.image_width = o.cameras.image_height = 512;
    o.cameras.gsd = 0.1;
    o.cameras.focal_mm = 3;
    o.cameras.strips = 2;
    o.cameras.images_per_strip = 3;
    o.scene.building_count = 6;
    NullProgress np;
    const sim::SimulationResult r = sim::Simulate(o, np);
    Data out;
    for (const sim::SimulatedView& v : r.views) {
      out.block.cameras.push_back(v.camera);
      View view;
      view.name = v.name;
      view.camera = static_cast<int>(out.block.cameras.size()) - 1;
      view.pose = v.pose;
      out.block.views.push_back(view);
    }
    out.block.ground.height = r.scene.ground.z;
    out.block.max_building_height = 30;
    for (const cv::Mat& im : r.images) {
      cv::Mat f;
      im.convertTo(f, CV_32FC3, 1.0 / 255);
      out.images.push_back(f);
    }
    return out;
  }();
  return d;
}

void BM_MatchLines512(benchmark::State& state) {
  const Data& d = Block512();
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
