#pragma once

#include <fstream>
#include <string>

#include "algorithms/core/error.h"
#include "algorithms/geometry/rotation.h"
#include "algorithms/geometry/view.h"
#include "io/core/block_manifest.h"

// Small helpers shared by the rs_io_orientation tests.
namespace roofsweep::orientation::testing {

inline std::string WriteFile(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
  return path;
}

// The pose of a manifest image in its own (CRS grid) axes.
inline Pose PoseOf(const ManifestImage& image) {
  Pose p;
  p.R = PatbToCv(image.rotation);
  p.C = image.position;
  return p;
}

inline const ManifestImage* FindImage(const BlockManifest& m, const std::string& name) {
  for (const auto& i : m.images)
    if (i.name == name) return &i;
  return nullptr;
}

inline const Camera& CameraOf(const BlockManifest& m, const ManifestImage& image) {
  return m.cameras.at(static_cast<size_t>(m.FindCamera(image.camera)));
}

}  // namespace roofsweep::orientation::testing
