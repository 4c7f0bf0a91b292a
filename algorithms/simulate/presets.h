#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "algorithms/core/progress.h"
#include "algorithms/simulate/camera_layout.h"
#include "algorithms/simulate/renderer.h"
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
};

// Presets:
//  easy       no noise, no blur beyond 0.4 px, no haze, hard sun, no shadows,
//             no trees, every roof face its own material tone; 4 views.
//  realistic  the default for reported figures: ~45 buildings on 200 x 200 m,
//             8 cm GSD, 70/40 % overlap,
//             sun 40 deg, shadows, trees, sensor noise, PSF 0.6 px,
//             vignetting, strip colour differences, 1 deg attitude noise.
//  hard       hazy low sun contrast (more sky light), 15 % isoluminant roofs
//             raised to 30 %, roof colours pulled to the ground colour,
//             more trees, strong noise, 60/25 % overlap (wide baseline).
//  bench      realistic at 6 views (2 strips x 3) of 2048 x 2048, 6 cm GSD,
//             30 buildings on 180 x 180 m.
// Throws roofsweep::Error for an unknown name.
SimulationOptions SimulationPreset(const std::string& name);
std::vector<std::string> SimulationPresetNames();

struct SimulationResult {
  Scene scene;
  SceneTruth truth;
  std::vector<SimulatedView> views;
  std::vector<cv::Mat> images;  // CV_8UC3 RGB, one per view
};

// Generates the scene (or uses `city` when given), lays out the cameras over
// it and renders every view. Deterministic for options.seed.
SimulationResult Simulate(const SimulationOptions& options, Progress& progress,
                          const CityModel* city = nullptr);

}  // namespace sim
}  // namespace roofsweep
