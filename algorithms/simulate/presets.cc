#include "algorithms/simulate/presets.h"

#include "algorithms/core/error.h"

namespace roofsweep {
namespace sim {

std::vector<std::string> SimulationPresetNames() { return {"easy", "realistic", "hard", "bench"}; }

SimulationOptions SimulationPreset(const std::string& name) {
  SimulationOptions o;  // struct defaults are the realistic preset
  o.cameras.attitude_sigma_deg = 1.0;
  o.cameras.position_sigma_m = 0.5;
  // A built-up quarter: ~45 buildings on 200 x 200 m seen at 8 cm.
  o.cameras.gsd = 0.08;
  o.scene.extent_x = o.scene.extent_y = 200;
  o.scene.building_count = 45;
  if (name == "realistic") return o;
  if (name == "bench") {
    // 6 views of 2048 x 2048 at 6 cm cover ~200 x 200 m: the 180 m scene.
    o.cameras.gsd = 0.06;
    o.scene.extent_x = o.scene.extent_y = 180;
    o.scene.building_count = 30;
    o.cameras.strips = 2;
    o.cameras.images_per_strip = 3;
    return o;
  }
  if (name == "easy") {
    o.scene.tree_count = 0;
    o.scene.same_roof_material = 0.0;
    o.scene.isoluminant_fraction = 0.0;
    o.cameras.attitude_sigma_deg = 0;
    o.cameras.position_sigma_m = 0;
    o.cameras.strips = 2;
    o.cameras.images_per_strip = 2;
    o.render.shadows = false;
    o.render.sky_rgb = Eigen::Vector3f(0.15f, 0.16f, 0.18f);
    o.render.sun_rgb = Eigen::Vector3f(1.1f, 1.08f, 1.05f);
    o.render.haze = 0;
    o.render.psf_sigma_px = 0.4;
    o.render.vignetting = 0;
    o.render.read_noise = 0;
    o.render.shot_noise = 0;
    o.render.strip_gain_sigma = 0;
    return o;
  }
  if (name == "hard") {
    o.scene.tree_count = 45;
    o.scene.isoluminant_fraction = 0.3;
    o.scene.roof_contrast = 0.6;
    o.scene.same_roof_material = 1.0;
    o.cameras.forward_overlap = 0.6;
    o.cameras.side_overlap = 0.25;
    o.cameras.attitude_sigma_deg = 2.0;
    o.render.sun_elevation_deg = 62;  // high sun: faces differ little in shading
    o.render.sun_rgb = Eigen::Vector3f(0.55f, 0.54f, 0.52f);
    o.render.sky_rgb = Eigen::Vector3f(0.50f, 0.53f, 0.58f);
    o.render.haze = 0.12;
    o.render.psf_sigma_px = 0.9;
    o.render.read_noise = 0.006;
    o.render.shot_noise = 0.0012;
    o.render.vignetting = 0.25;
    o.render.strip_gain_sigma = 0.05;
    return o;
  }
  throw Error("simulate: unknown preset '" + name + "' (easy, realistic, hard, bench)");
}

SimulationResult Simulate(const SimulationOptions& o, Progress& progress, const CityModel* city) {
  SimulationResult r;
  r.scene = city ? SceneFromCityModel(*city, o.scene, o.seed) : GenerateScene(o.scene, o.seed);
  r.truth = TruthOf(r.scene);
  r.views = LayoutCameras(r.scene.area, r.scene.ground.z, o.cameras, o.seed);
  ReportOrCancel(progress, 0.02, "scene");
  const Renderer renderer(r.scene, o.render);
  for (size_t i = 0; i < r.views.size(); ++i) {
    SubProgress sub(progress, 0.02 + 0.98 * i / r.views.size(),
                    0.02 + 0.98 * (i + 1) / r.views.size());
    r.images.push_back(renderer.Render(r.views[i], static_cast<int>(i), o.seed, &sub));
  }
  return r;
}

}  // namespace sim
}  // namespace roofsweep
