#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "algorithms/core/progress.h"
#include "algorithms/simulate/camera_layout.h"
#include "algorithms/simulate/renderer.h"
#include "algorithms/simulate/roof_visibility.h"
#include "algorithms/simulate/scene.h"

namespace roofsweep {
namespace sim {

// Everything a simulation needs; each preset fills it, every field can be
// overridden afterwards.
struct SimulationOptions {
  uint64_t seed = 1;
  SceneOptions scene;
  CameraLayoutOptions cameras;
  RenderOptions render;
  // With a fixed flight plan (strips and images_per_strip > 0), set the
  // scene extent to the ground the images cover, so that every image is
  // built up to its borders (the town is generated where the cameras look).
  bool fit_scene_to_flight = true;
};

// Ground rectangle (x, y extent, m) the images of a fixed nadir flight plan
// cover (their union, without attitude noise).
Eigen::Vector2d FlightCoverage(const CameraLayoutOptions& cameras);

// The scene options Simulate() uses: with fit_scene_to_flight and a fixed
// plan, the extent is the flight's coverage and buildings are only placed
// where at least two of the (noisy) views see them whole.
SceneOptions FitSceneToFlight(const SimulationOptions& options);

// Presets (the scene is generated over the ground the flight covers, so
// images are built up to their borders; building counts are upper bounds):
//  easy       no noise, no blur beyond 0.4 px, no haze, hard sun, no shadows,
//             no trees, no roof objects, every roof face its own material
//             tone; 4 views.
//  realistic  the default for reported figures: 2 strips x 4 views at 5 cm
//             GSD, 80/60 % overlap (about 165 x 145 m, up to 80 buildings),
//             sun 40 deg with soft shadows, trees, cars, roof objects,
//             sensor noise, PSF 0.6 px, haze 5 %, vignetting, strip colour
//             differences, 1 deg attitude noise.
//  hard       hazy, flat light (more sky than sun), 30 % isoluminant roofs,
//             roof colours pulled to the ground colour, more trees, strong
//             noise, 60/25 % overlap (wide baseline, larger area).
//  bench      realistic at 6 views (2 strips x 3) of 2048 x 2048, up to 60
//             buildings on about 143 x 143 m.
// Throws roofsweep::Error for an unknown name.
SimulationOptions SimulationPreset(const std::string& name);
std::vector<std::string> SimulationPresetNames();

struct SimulationResult {
  Scene scene;
  SceneTruth truth;
  std::vector<SimulatedView> views;
  std::vector<cv::Mat> images;  // CV_8UC3 RGB, one per view
  // What each view sees of each true roof polygon (RoofVisibility).
  std::vector<RoofPolygonVisibility> roof_visibility;
};

// Generates the scene (or uses `city` when given), lays out the cameras over
// it and renders every view. Deterministic for options.seed.
SimulationResult Simulate(const SimulationOptions& options, Progress& progress,
                          const CityModel* city = nullptr);

}  // namespace sim
}  // namespace roofsweep
