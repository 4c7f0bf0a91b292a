#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <utility>
#include <vector>

#include "algorithms/sweep/sweep_options.h"

namespace roofsweep {

// What the sweep needs of one view: the grey image (CV_32F, [0, 1]) it
// correlates on, and the mask (CV_8U, 255 = edge) of its points of interest.
struct ViewTexture {
  cv::Mat grey;
  cv::Mat poi;
};

// `image`: CV_32FC3 RGB or CV_32FC1 in [0, 1]. Points of interest are the
// paper's low-threshold edges (§3.3): Canny on the blurred grey image.
ViewTexture PrepareViewTexture(const cv::Mat& image, const SweepOptions& options);

using Segment2 = std::pair<Eigen::Vector2d, Eigen::Vector2d>;

struct BandPoint {
  Eigen::Vector2d pixel;  // pixel centre, corner-origin convention
  double distance = 0;    // to the projected line, px
};

// Points of interest in the band on one image side of the projected segment
// p0 -> p1 (`image_side`: the sign ImageSide gives for points of the band),
// from options.min_distance_px to options.band_width_px off the line, skipping
// points whose perpendicular path to the line crosses one of `blockers` or
// that lie within min_distance_px + ncc_radius of one.
// At most options.max_points, evenly thinned in raster order.
std::vector<BandPoint> BandPoints(const ViewTexture& texture, const Eigen::Vector2d& p0,
                                  const Eigen::Vector2d& p1, int image_side,
                                  const std::vector<Segment2>& blockers,
                                  const SweepOptions& options);

// Signed side of x relative to p0 -> p1: the sign of cross(p1 - p0, x - p0).
inline int ImageSide(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1,
                     const Eigen::Vector2d& x) {
  const Eigen::Vector2d u = p1 - p0, v = x - p0;
  const double c = u.x() * v.y() - u.y() * v.x();
  return c > 0 ? 1 : (c < 0 ? -1 : 0);
}

}  // namespace roofsweep
