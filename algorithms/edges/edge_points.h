#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "algorithms/edges/gradient.h"

namespace roofsweep {

// One sub-pixel edge point: at most one per pixel.
struct EdgePoint {
  float x = 0, y = 0;    // sub-pixel position, corner convention
  float gx = 0, gy = 0;  // fused gradient (see GradientField)
  float magnitude = 0;
  int px = 0, py = 0;                // the pixel it was found in
  EdgeBand band = EdgeBand::kFused;  // the band that carries the gradient (CarryingBand)
};

// Edge points plus a raster index into them (CV_32S, -1 where none).
struct EdgeMap {
  std::vector<EdgePoint> points;
  cv::Mat index;
};

// Non-maximum suppression with sub-pixel positions, then Canny hysteresis.
//
// A pixel is a candidate when its magnitude is at least `low` and a local
// maximum along the image axis closest to its gradient direction (strictly
// greater than the neighbour before, at least the one after, so plateaus
// give one point). Candidates are kept when 8-connected through candidates
// to one of magnitude >= `high` (high <= low keeps them all).
//
// The position is the vertex of the parabola through the three magnitudes
// along that axis. Comparing along the axis rather than along interpolated
// samples in the exact gradient direction is Devernay's choice (1995; von
// Gioi & Randall, IPOL 2017): for a straight edge the magnitude profile
// along any line crossing it peaks on the edge, so the axis fit is unbiased
// and needs no interpolation. Points come out in raster order.
EdgeMap DetectEdgePoints(const GradientField& gradient, float low, float high);

}  // namespace roofsweep
