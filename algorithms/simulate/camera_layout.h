#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "algorithms/geometry/camera.h"
#include "algorithms/geometry/view.h"

namespace roofsweep {
namespace sim {

// A simulated aerial image: its camera, pose and place in the flight plan.
struct SimulatedView {
  std::string name;  // e.g. "s01_i003" or "s01_i003_fwd"
  Camera camera;
  Pose pose;
  int strip = 0;               // flight line; colour calibration differs per strip
  int index = 0;               // station along the strip
  std::string look = "nadir";  // nadir, forward, backward, left, right
};

// Flight plan of a nadir frame camera over a rectangle (photogrammetric
// block): parallel strips, forward overlap along a strip, side overlap
// between strips, flying height from GSD and focal length.
struct CameraLayoutOptions {
  int image_width = 2048;
  int image_height = 2048;
  double gsd = 0.10;  // m per pixel on the ground (nadir), 0.05..0.15 typical
  // With pixel_size_um gives the focal length in pixels. 12 mm on a 2048 px
  // chip of 4.6 um (9.4 mm) is a 43 deg field of view, that of the frame
  // cameras aerial blocks are flown with (DMC: 120 mm on 92 mm along track;
  // UltraCam: 100 mm on 45-68 mm), so base/height ratios (0.09 along a strip
  // at 80 % overlap, 0.3 across at 60 % side overlap) and relief displacement
  // are those of real blocks. A longer lens would make the stereo geometry
  // much weaker than real data and every height figure look worse than it is.
  double focal_mm = 12;
  double pixel_size_um = 4.6;
  double forward_overlap = 0.7;  // along a strip, 0.6..0.8
  double side_overlap = 0.4;     // between strips, 0.2..0.6
  double heading_deg = 0;        // flight direction, counter-clockwise from east (+x)
  int strips = 0;                // 0: enough to cover the area
  int images_per_strip = 0;      // 0: enough to cover the area
  bool serpentine = true;        // every other strip flown back (kappa + 180)
  // Random attitude (roll/pitch/yaw, deg, 1 sigma) and position (m) of real
  // flights; 0 gives the ideal plan.
  double attitude_sigma_deg = 0;
  double position_sigma_m = 0;
  // Oblique views: four extra views per station tilted by oblique_tilt_deg
  // forward, backward, left and right (Maltese cross).
  bool obliques = false;
  double oblique_tilt_deg = 45;
  // Lens distortion (OpenCV k1, k2, p1, p2, k3) applied to every camera.
  double k1 = 0, k2 = 0, k3 = 0, p1 = 0, p2 = 0;
};

// Camera (interior orientation) the options describe; principal point at
// the image centre.
Camera LayoutCamera(const CameraLayoutOptions& options);
// Flying height above ground: gsd * focal_px.
double FlyingHeight(const CameraLayoutOptions& options);

// Views over area (min x, min y, max x, max y) at ground height ground_z,
// strip by strip. Deterministic for the seed (used only for the random
// attitude). Throws roofsweep::Error for impossible options.
std::vector<SimulatedView> LayoutCameras(const Eigen::Vector4d& area, double ground_z,
                                         const CameraLayoutOptions& options, uint64_t seed);

}  // namespace sim
}  // namespace roofsweep
