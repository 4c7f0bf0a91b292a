#pragma once

#include <Eigen/Core>
#include <array>
#include <memory>
#include <opencv2/core.hpp>
#include <vector>

#include "algorithms/edges/segment2d.h"
#include "algorithms/edges/segment_index.h"
#include "algorithms/geometry/block.h"
#include "algorithms/matching/colour_balance.h"
#include "algorithms/matching/match_options.h"

namespace roofsweep {

// Chromatic attributes of one flanking region (Scholze et al. 2000, §3.2.2):
// robust (MCD) mean and covariance of (a*, b*) over the L*-inlier pixels of
// the adaptive region.
struct SideColour {
  bool valid = false;
  int n = 0;  // pixels the estimate rests on
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  Eigen::Matrix2d cov = Eigen::Matrix2d::Identity();
  double l_location = 0, l_scale = 0;  // L* inlier band: |L - location| <= k scale
};

// One image prepared for matching: CIE L*a*b* bands, gradient magnitude,
// the label map of its segments and each segment's flanking attributes.
// Geometry uses ideal (distortion-free) pixel coordinates; the image
// itself stays distorted, so sampling maps ideal -> image first.
struct ViewFeatures {
  int view = -1;
  const Camera* camera = nullptr;
  Pose pose;
  Eigen::Matrix<double, 3, 4> P;                 // ideal pixels
  cv::Mat lab;                                   // CV_32FC3, L* in [0, 100]
  cv::Mat gradient;                              // CV_32F, |grad| of L*/100 per px
  cv::Mat labels;                                // CV_32S, segment id or -1
  bool grey = false;                             // no chroma: correlation on L* instead of a*, b*
  bool distorted = false;                        // camera->HasDistortion(), asked per sample
  Segments2D segments;                           // image pixel coordinates, as detected
  Segments2D ideal;                              // the same in ideal pixel coordinates
  std::unique_ptr<SegmentIndex> index;           // over `ideal`
  std::vector<std::array<SideColour, 2>> sides;  // [left, right] per segment

  // Ideal pixel <-> image pixel (identity without distortion).
  Eigen::Vector2d ToImage(const Eigen::Vector2d& ideal_px) const {
    return distorted ? Distorted(ideal_px) : ideal_px;
  }
  Eigen::Vector2d ToIdeal(const Eigen::Vector2d& image_px) const {
    return distorted ? Undistorted(image_px) : image_px;
  }
  bool Inside(const Eigen::Vector2d& image_px) const {
    return image_px.x() >= 0 && image_px.y() >= 0 && image_px.x() < lab.cols &&
           image_px.y() < lab.rows;
  }

 private:
  Eigen::Vector2d Distorted(const Eigen::Vector2d& ideal_px) const;
  Eigen::Vector2d Undistorted(const Eigen::Vector2d& image_px) const;
};

// Builds the features of one view from its RGB image (CV_32FC3 in [0, 1],
// or CV_32FC1 grey) and detected segments (segments shorter than
// options.min_length are kept but get no attributes). The colour correction
// is applied on the way to L*a*b* (as ApplyColourCorrection would, without
// the copy of the image); grey images ignore it.
ViewFeatures PrepareView(const Block& block, int view, const cv::Mat& image, Segments2D segments,
                         const MatchOptions& options, const ColourCorrection& correction = {});

// The pixels of one adaptive flanking region (§3.2.1), as image positions
// (pixel centres), grown row by row away from the segment with the 3x3
// rule: a cell joins when the three cells before it joined and no other
// contour is right behind it. side: +1 left, -1 right. `scale` stretches the
// region across the segment (used by the correlation, §3.4).
std::vector<Eigen::Vector2d> FlankingRegion(const cv::Mat& labels, const Segment2D& segment, int id,
                                            int side, double offset, double width);

// Attributes of a region from its pixels.
SideColour RegionColour(const cv::Mat& lab, const std::vector<Eigen::Vector2d>& pixels,
                        const MatchOptions& options, unsigned seed);

// Bilinear sample of all channels of a float image; false outside. Inline:
// the correlation calls it for every pixel of every candidate's strips.
inline bool SampleBilinear(const cv::Mat& image, const Eigen::Vector2d& p, float* out) {
  // Pixel centres are at +0.5 (corner convention).
  const double x = p.x() - 0.5, y = p.y() - 0.5;
  if (!(x >= 0 && y >= 0 && x < image.cols - 1 && y < image.rows - 1)) return false;
  const int x0 = static_cast<int>(x), y0 = static_cast<int>(y);
  const float fx = static_cast<float>(x - x0), fy = static_cast<float>(y - y0);
  const int ch = image.channels();
  const float* r0 = image.ptr<float>(y0) + x0 * ch;
  const float* r1 = image.ptr<float>(y0 + 1) + x0 * ch;
  for (int c = 0; c < ch; ++c) {
    const float top = r0[c] + fx * (r0[ch + c] - r0[c]);
    const float bot = r1[c] + fx * (r1[ch + c] - r1[c]);
    out[c] = top + fy * (bot - top);
  }
  return true;
}

}  // namespace roofsweep
