#pragma once

#include <opencv2/core.hpp>

#include "algorithms/edges/edge_options.h"

namespace roofsweep {

struct HysteresisThresholds {
  float low = 0;
  float high = 0;
  float noise = 0;  // the noise estimate behind automatic thresholds
};

// The thresholds ExtractSegments uses: the explicit ones in `options`
// where given (>= 0), else the automatic rule documented in EdgeOptions.
HysteresisThresholds ChooseThresholds(const cv::Mat& magnitude, const EdgeOptions& options);

}  // namespace roofsweep
