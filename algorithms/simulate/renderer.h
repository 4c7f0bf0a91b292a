#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <opencv2/core.hpp>
#include <vector>

#include "algorithms/core/progress.h"
#include "algorithms/simulate/camera_layout.h"
#include "algorithms/simulate/scene.h"

namespace roofsweep {
namespace sim {

// Light and sensor of the simulated camera. Radiometry is linear RGB;
// the sensor output is 8-bit sRGB.
struct RenderOptions {
  int supersampling = 2;  // n x n jittered samples per pixel (anti-aliasing), >= 1
  // Sun position: azimuth clockwise from north, elevation above horizon.
  double sun_azimuth_deg = 150;
  double sun_elevation_deg = 40;
  Eigen::Vector3f sun_rgb = Eigen::Vector3f(1.00f, 0.96f, 0.90f);  // direct irradiance
  Eigen::Vector3f sky_rgb = Eigen::Vector3f(0.26f, 0.30f, 0.36f);  // diffuse sky irradiance
  bool shadows = true;                                             // cast shadows (shadow rays)
  // Angular radius of the sun disc (deg): each sample's shadow ray aims at a
  // random point of the disc, so shadows get a penumbra (0.27 = the real sun;
  // forward scattering in haze widens it).
  double sun_radius_deg = 0.27;
  double exposure = 1.0;
  // Atmospheric veil: output = (1 - haze) * signal + haze * haze_rgb.
  double haze = 0.03;
  Eigen::Vector3f haze_rgb = Eigen::Vector3f(0.55f, 0.60f, 0.68f);
  // Optics and sensor.
  double psf_sigma_px = 0.6;        // Gaussian blur (lens + motion + demosaicing)
  double vignetting = 0.12;         // relative brightness loss in the image corners
  double read_noise = 0.002;        // linear units (1 = white), per channel
  double shot_noise = 0.0004;       // variance per unit signal (photon noise)
  double strip_gain_sigma = 0.025;  // per flight line and channel, relative
};

// What a pixel shows, for the face-id map.
enum class FaceKind {
  kTerrain,
  kRoof,
  kWall,
  kGroundSurface,
  kClosure,
  kTreeCrown,
  kTreeTrunk,
  kProp  // car, hedge, chimney, solar panel, ... (Scene::props; not ground truth)
};

struct FaceInfo {
  FaceKind kind = FaceKind::kTerrain;
  int building = -1;  // index into Scene::city.buildings
  int surface = -1;   // index into Building::surfaces
  int polygon = -1;   // index into Surface::polygons
  int tree = -1;      // index into Scene::trees
  int prop = -1;      // index into Scene::props
  int material = -1;
  // Plane n·X + d = 0 (planar faces), texture frame (u horizontal, v down
  // the slope), texture seed.
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double d = 0;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero(), u_axis = Eigen::Vector3d::UnitX(),
                  v_axis = Eigen::Vector3d::UnitY();
  uint32_t seed = 0;
};

// Per-pixel geometry of a view, sampled at pixel centres.
struct GeometryMaps {
  cv::Mat depth;  // CV_32F, camera z (m) of the visible surface; +inf where none
  cv::Mat face;   // CV_32S, index into Renderer::faces(); -1 where none
};

// Ray caster for one scene: perspective views with visibility, sun and sky
// shading with cast shadows, procedural textures, jittered supersampling,
// then the sensor (PSF, vignetting, flight-line colour, noise, 8 bit).
// Every pixel's randomness is a hash of (seed, view, pixel), so the output
// is identical for any number of threads.
class Renderer {
 public:
  Renderer(const Scene& scene, const RenderOptions& options);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // 8-bit RGB image (CV_8UC3, R, G, B order) of one view. `view_index`
  // selects the view's noise; rows are rendered in parallel with TBB.
  cv::Mat Render(const SimulatedView& view, int view_index, uint64_t seed,
                 Progress* progress = nullptr) const;
  // Linear radiance before the sensor model (CV_32FC3, R, G, B), for tests.
  cv::Mat RenderRadiance(const Camera& camera, const Pose& pose, int view_index,
                         uint64_t seed) const;
  // Depth and face-id maps at pixel centres (no supersampling).
  GeometryMaps RenderGeometry(const Camera& camera, const Pose& pose) const;

  const std::vector<FaceInfo>& faces() const;
  size_t triangle_count() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sim
}  // namespace roofsweep
