#pragma once

#include <opencv2/core.hpp>

#include "algorithms/edges/edge_options.h"
#include "algorithms/edges/segment2d.h"

namespace roofsweep {

// What one extraction found, for diagnostics and benchmarks.
struct EdgeStats {
  float noise = 0;          // automatic noise estimate (EdgeOptions)
  float low = 0, high = 0;  // thresholds used
  int edge_points = 0;      // after hysteresis
  int chains = 0;           // with at least min_support points
  int pieces = 0;           // straight pieces before merging
};

// Straight edge segments of an image (Scholze et al. 2000, §2): Gaussian
// smoothing, fused colour gradient, non-maximum suppression with
// sub-pixel positions, hysteresis, linking, splitting into straight pieces,
// merging across small gaps, the minimum length, side colours, and the
// optional fusion with other gradient methods (§2.3), and the mark of the
// segments of periodic texture (EdgeOptions::mark_texture). Segments come out
// sorted by decreasing length (ties by position), deterministically.
//
// `image`: CV_32FC3 (R, G, B) or CV_32FC1 in [0, 1], as io's ReadImage
// returns (16-bit data scaled the same way is fine). Grey images always
// use the grey method. Images smaller than 3x3 give no segments. Throws
// roofsweep::Error for an empty image, another type, NaN or infinite
// pixels, or invalid options.
Segments2D ExtractSegments(const cv::Mat& image, const EdgeOptions& options,
                           EdgeStats* stats = nullptr);

}  // namespace roofsweep
