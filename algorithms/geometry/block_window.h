#pragma once

#include <Eigen/Core>
#include <vector>

#include "algorithms/geometry/block.h"

namespace roofsweep {

// A part of an image: columns x .. x + width - 1, rows y .. y + height - 1.
struct PixelWindow {
  int x = 0, y = 0, width = 0, height = 0;
  long long Pixels() const { return static_cast<long long>(width) * height; }
};

// A block cut down to what can see a region: the views that see it, each
// with the window of its image that does.
struct BlockWindows {
  // The views that see the region, in their original order. Each has a
  // camera of its own: the original with the principal point moved into
  // the window and the window's size, so that projecting into the window
  // is projecting into the image less the window's corner (distortion acts
  // on normalised coordinates and is unchanged).
  Block block;
  std::vector<int> source_view;      // per kept view: its index in the original block
  std::vector<PixelWindow> windows;  // per kept view: in the original image's pixels
};

// The views of `block` that see any point of the box `region` (local x, y:
// min x, min y, max x, max y) between heights z_min and z_max, and of each
// the smallest window holding the box's image, widened by `margin_px` on
// every side (image filters and correlation windows reach that far) and
// clipped to the image. The box's edges are sampled (lens distortion bends
// them); a view that has part of the box behind it keeps its whole image.
BlockWindows CropBlockToRegion(const Block& block, const Eigen::Vector4d& region, double z_min,
                               double z_max, int margin_px);

}  // namespace roofsweep
