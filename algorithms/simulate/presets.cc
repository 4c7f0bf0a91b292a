#include "algorithms/simulate/presets.h"

#include <algorithm>
#include <cmath>

#include "algorithms/core/error.h"

namespace roofsweep {
namespace sim {

std::vector<std::string> SimulationPresetNames() { return {"easy", "realistic", "hard", "bench"}; }

Eigen::Vector2d FlightCoverage(const CameraLayoutOptions& c) {
  const double fa = c.image_height * c.gsd, fc = c.image_width * c.gsd;
  const double along = fa + std::max(0, c.images_per_strip - 1) * (1 - c.forward_overlap) * fa;
  const double across = fc + std::max(0, c.strips - 1) * (1 - c.side_overlap) * fc;
  const double h = c.heading_deg * M_PI / 180;
  const double ch = std::abs(std::cos(h)), sh = std::abs(std::sin(h));
  return {ch * along + sh * across, sh * along + ch * across};
}

SceneOptions FitSceneToFlight(const SimulationOptions& o) {
  SceneOptions so = o.scene;
  if (!o.fit_scene_to_flight || o.cameras.strips <= 0 || o.cameras.images_per_strip <= 0) return so;
  const Eigen::Vector2d cover = FlightCoverage(o.cameras);
  so.extent_x = cover.x();
  so.extent_y = cover.y();
  // The same views Simulate() lays out over the scene's area.
  const Eigen::Vector4d area(-cover.x() / 2, -cover.y() / 2, cover.x() / 2, cover.y() / 2);
  so.visibility_views.clear();
  for (const SimulatedView& v : LayoutCameras(area, so.ground_z, o.cameras, o.seed))
    so.visibility_views.push_back({v.camera, v.pose});
  return so;
}

SimulationOptions SimulationPreset(const std::string& name) {
  SimulationOptions o;  // struct defaults are the realistic preset
  o.cameras.attitude_sigma_deg = 1.0;
  o.cameras.position_sigma_m = 0.5;
  // A built-up quarter at 5 cm seen by 2 strips of 4 images with the 80/60 %
  // overlap of current urban flights; the scene fills the covered ground
  // (about 165 x 145 m), so every image is full of buildings.
  o.cameras.gsd = 0.05;
  o.cameras.strips = 2;
  o.cameras.images_per_strip = 4;
  o.cameras.forward_overlap = 0.8;
  o.cameras.side_overlap = 0.6;
  o.scene.building_count = 90;
  o.scene.tree_count = 70;
  o.render.haze = 0.05;
  if (name == "realistic") return o;
  if (name == "bench") {
    // 6 views of 2048 x 2048 (2 strips x 3).
    o.cameras.images_per_strip = 3;
    o.scene.building_count = 75;
    o.scene.tree_count = 60;
    return o;
  }
  if (name == "easy") {
    o.scene.tree_count = 0;
    o.scene.same_roof_material = 0.0;
    o.scene.isoluminant_fraction = 0.0;
    o.scene.roof_objects = false;
    o.cameras.attitude_sigma_deg = 0;
    o.cameras.position_sigma_m = 0;
    o.cameras.strips = 2;
    o.cameras.images_per_strip = 2;
    o.scene.building_count = 75;
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
    o.scene.tree_count = 140;
    o.scene.building_count = 160;
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
    o.render.sun_radius_deg = 1.0;  // forward scattering in haze: wide penumbra
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
  const SceneOptions so = city ? o.scene : FitSceneToFlight(o);
  r.scene = city ? SceneFromCityModel(*city, so, o.seed) : GenerateScene(so, o.seed);
  r.truth = TruthOf(r.scene);
  r.views = LayoutCameras(r.scene.area, r.scene.ground.z, o.cameras, o.seed);
  ReportOrCancel(progress, 0.02, "scene");
  const Renderer renderer(r.scene, o.render);
  for (size_t i = 0; i < r.views.size(); ++i) {
    SubProgress sub(progress, 0.02 + 0.98 * i / r.views.size(),
                    0.02 + 0.98 * (i + 1) / r.views.size());
    r.images.push_back(renderer.Render(r.views[i], static_cast<int>(i), o.seed, &sub));
  }
  r.roof_visibility = RoofVisibility(renderer, r.scene, r.views);
  return r;
}

}  // namespace sim
}  // namespace roofsweep
