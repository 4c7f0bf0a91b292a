#pragma once

#include <map>
#include <string>
#include <vector>

#include "algorithms/geometry/camera.h"
#include "io/core/block_manifest.h"

namespace roofsweep::orientation {

// Interior orientation read from a camera file (ImportOptions::camera_file),
// for orientation formats that carry none (OPK text files).
struct CameraSet {
  std::string source;
  std::vector<Camera> cameras;
  // Per-image cameras (Pix4D calibrated_camera_parameters.txt): image name
  // as written there -> camera id.
  std::map<std::string, std::string> image_camera;
  // Cameras given in mm without the image size (Pix4D .cam): their fx, fy,
  // cx, cy are in mm and width = height = 0 until the images are known;
  // then ScaleMmCameras turns them into pixels.
  struct SensorMm {
    double width_mm = 0, height_mm = 0;
  };
  std::map<std::string, SensorMm> in_mm;

  // The camera for an image: by the OPK file's camera column when given
  // (exact id, or ignoring OpenSfM's "v2 " prefix and case), else by the
  // image's name, else the only camera. Null when nothing matches.
  const Camera* Find(const std::string& camera_column, const std::string& image_name) const;
};

// By content and extension:
//  .yaml/.yml  orthority interior parameters (pinhole, brown, opencv)
//  .cam        Pix4D *_pix4d_calibrated_internal_camera_parameters.cam
//  .txt        Pix4D *_calibrated_camera_parameters.txt (K per image)
//  .xml        Metashape calibration (<calibration>, or a camera export
//              with <sensor> elements)
//  .json       OpenSfM reconstruction.json / cameras.json, or a roofsweep
//              block manifest (its cameras)
CameraSet ReadCameraFile(const std::string& path);

// Converts the in_mm cameras of `set` in `manifest` to pixels, now that
// AddImages has given them the image size.
void ScaleMmCameras(const CameraSet& set, BlockManifest* manifest);

// Metashape calibration XML: one camera per <calibration> (with <f>).
std::vector<Camera> ReadMetashapeCalibration(const std::string& path);

// orthority's interior parameter YAML.
std::vector<Camera> ReadOrthorityYaml(const std::string& path);

}  // namespace roofsweep::orientation
