#pragma once

#include <string>
#include <vector>

#include "io/core/block_manifest.h"
#include "io/orientation/block_source.h"

namespace roofsweep::orientation {

// `vgg`: an Oxford VGG multi-view set folder. Every `*.P` below it (3x4
// projection matrix, x ~ P X) is one image, paired with the image file of
// the same stem below the folder (2D/001.P with images/001.jpg,
// 3D/house.000.P with images/house.000.pgm). Each P becomes its own camera
// (K keeps its skew) and pose via DecomposeProjection, shifted by +0.5 px
// because VGG's origin is the centre of the top-left pixel. No CRS, no
// ground.
//
// Some sets (corridor, model_house) have P matrices that only a left-handed
// world explains (the scene points lie behind every camera otherwise);
// roofsweep poses are proper rotations, so such a set is imported in the
// mirrored world (X, Y, -Z): VggWorldIsMirrored tells which, and the set's
// own 3D points must be mirrored alike to compare.
//
// Sets whose images are not at hand (merton2, wadham, library) are refused
// with a message saying so, unless options.check_images is false: then the
// camera size is nominal, twice the principal point rounded (the P files do
// not record it), and the image path is the stem.
BlockManifest ReadVgg(const std::vector<std::string>& sources, const ImportOptions& options);

// True when the set's P matrices put its 3D points (p3d/l3d) in front of
// the cameras only in a mirrored world. Throws when the views disagree.
bool VggWorldIsMirrored(const std::string& folder);

// The regular files below `folder` (recursively) whose name ends with
// `suffix`, sorted: a set's P matrices, .lines, nview-lines, p3d and l3d.
std::vector<std::string> VggFilesEndingWith(const std::string& folder, const std::string& suffix);

// True when `folder` holds a *.P file somewhere below it.
bool LooksLikeVggSet(const std::string& folder);

}  // namespace roofsweep::orientation
