#pragma once

#include <string>
#include <vector>

#include "io/core/block_manifest.h"
#include "io/orientation/block_source.h"

namespace roofsweep::orientation {

// Cameras of an OpenSfM reconstruction.json (all reconstructions) or
// cameras.json / camera_models.json (an object of cameras), converted to
// roofsweep's corner pixel convention.
std::vector<Camera> ReadOpenSfmCameras(const std::string& path);

// `opensfm`: sources = one reconstruction.json. The largest reconstruction
// (most shots) is imported; OpenSfM puts each reconstruction in its own
// frame, so mixing them would mix frames. Positions and rotations go from
// the topocentric frame at reference_lla to WGS84 / UTM (zone of
// reference_lla, ellipsoidal heights). Without -ground, the ground height is
// estimated as the 5th percentile of the points' heights.
BlockManifest ReadOpenSfm(const std::vector<std::string>& sources, const ImportOptions& options);

struct OpenSfmImportOptions {
  // Percentile of the reconstruction points' heights taken as ground height
  // when none is given (low, to sit below roofs and walls). Default 5.
  double ground_percentile = 5.0;
};

}  // namespace roofsweep::orientation
