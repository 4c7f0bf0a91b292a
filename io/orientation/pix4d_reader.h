#pragma once

#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

#include "io/core/block_manifest.h"
#include "io/orientation/block_source.h"

namespace roofsweep::orientation {

// One 10-line block of a Pix4D `*_calibrated_camera_parameters.txt`.
struct Pix4dCalibratedImage {
  std::string name;
  int width = 0, height = 0;
  Eigen::Matrix3d K = Eigen::Matrix3d::Identity();
  Eigen::Vector3d radial = Eigen::Vector3d::Zero();      // R1 R2 R3 = k1 k2 k3
  Eigen::Vector2d tangential = Eigen::Vector2d::Zero();  // T1 T2 = OpenCV p1 p2
  Eigen::Vector3d t = Eigen::Vector3d::Zero();           // centre minus offset
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();       // world -> camera, CV axes
  int line = 0;                                          // line of the name
};

// Parses the file; the text header (7 lines and a blank in Pix4D's output)
// is skipped up to the first "NAME WIDTH HEIGHT" line.
std::vector<Pix4dCalibratedImage> ParsePix4dCalibrated(const std::string& path);

// Cameras of the parsed blocks, identical intrinsics merged into one camera
// ("pix4d_1", "pix4d_2", ...); image_camera maps image names to camera ids.
void Pix4dCameras(const std::vector<Pix4dCalibratedImage>& blocks, std::vector<Camera>* cameras,
                  std::map<std::string, std::string>* image_camera);

// `pix4d`: sources = the calibrated_camera_parameters.txt, optionally the
// `*_offset.xyz` (else the one beside it). CRS from options or `*_wkt.prj`
// beside it.
BlockManifest ReadPix4d(const std::vector<std::string>& sources, const ImportOptions& options);

}  // namespace roofsweep::orientation
