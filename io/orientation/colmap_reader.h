#pragma once

#include <string>
#include <vector>

#include "io/core/block_manifest.h"
#include "io/orientation/block_source.h"

namespace roofsweep::orientation {

// `colmap`: a text model folder (cameras.txt + images.txt), or the two files.
// Models SIMPLE_PINHOLE, PINHOLE, SIMPLE_RADIAL, RADIAL, OPENCV, FULL_OPENCV
// (k4..k6 must be 0). COLMAP's pixel origin is the top-left corner, as
// roofsweep's. No CRS unless options.crs: COLMAP's frame is arbitrary.
// Image folders: options.image_dir, the model folder, its ../images and
// ../../images (COLMAP's sparse/0 layout).
BlockManifest ReadColmap(const std::vector<std::string>& sources, const ImportOptions& options);

}  // namespace roofsweep::orientation
