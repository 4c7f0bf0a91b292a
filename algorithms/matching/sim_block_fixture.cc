#include "algorithms/matching/sim_block_fixture.h"

#include "algorithms/core/progress.h"
#include "algorithms/simulate/presets.h"

namespace roofsweep {

SimBlock SimulateSmallBlock(uint64_t seed) {
  sim::SimulationOptions o = sim::SimulationPreset("realistic");
  o.seed = seed;
  o.cameras.image_width = o.cameras.image_height = 512;
  // 15 cm: the 512 px views cover 77 m, room for several houses under the
  // simulator's rule that a building must lie wholly inside two views.
  o.cameras.gsd = 0.15;
  // 3 mm on a 512 px chip: the photogrammetric base/height of ~0.25.
  o.cameras.focal_mm = 3;
  o.cameras.strips = 2;
  o.cameras.images_per_strip = 3;
  o.scene.building_count = 6;
  NullProgress np;
  const sim::SimulationResult r = sim::Simulate(o, np);
  SimBlock b;
  for (const sim::SimulatedView& v : r.views) {
    b.block.cameras.push_back(v.camera);
    View view;
    view.name = v.name;
    view.camera = static_cast<int>(b.block.cameras.size()) - 1;
    view.pose = v.pose;
    b.block.views.push_back(view);
  }
  b.block.ground.height = r.scene.ground.z;
  b.block.max_building_height = 30;
  for (const cv::Mat& im : r.images) {
    cv::Mat f;
    im.convertTo(f, CV_32FC3, 1.0 / 255);
    b.images.push_back(f);
  }
  for (const sim::TrueEdge& e : r.truth.edges) {
    b.truth.push_back({e.a, e.b});
    (sim::IsRoofEdge(e.kind) ? b.roof : b.extra).push_back({e.a, e.b});
  }
  return b;
}

}  // namespace roofsweep
