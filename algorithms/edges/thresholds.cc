#include "algorithms/edges/thresholds.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace roofsweep {
namespace {

// Median over every second pixel of every second row, skipping the zero
// border; a quarter of the pixels estimates a median to well under 1 %.
float SubsampledMedian(const cv::Mat& magnitude) {
  std::vector<float> values;
  values.reserve(static_cast<size_t>((magnitude.rows / 2 + 1) * (magnitude.cols / 2 + 1)));
  for (int y = 1; y < magnitude.rows - 1; y += 2) {
    const float* m = magnitude.ptr<float>(y);
    for (int x = 1; x < magnitude.cols - 1; x += 2) values.push_back(m[x]);
  }
  if (values.empty()) return 0.f;
  auto mid = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), mid, values.end());
  return *mid;
}

}  // namespace

HysteresisThresholds ChooseThresholds(const cv::Mat& magnitude, const EdgeOptions& o) {
  HysteresisThresholds t;
  t.noise = SubsampledMedian(magnitude) / static_cast<float>(std::sqrt(2.0 * std::log(2.0)));
  t.high = o.high_threshold >= 0 ? static_cast<float>(o.high_threshold)
                                 : std::max(static_cast<float>(o.auto_high_factor) * t.noise,
                                            static_cast<float>(o.auto_min_high));
  t.low = o.low_threshold >= 0 ? static_cast<float>(o.low_threshold)
                               : static_cast<float>(o.auto_low_ratio) * t.high;
  t.low = std::min(t.low, t.high);
  return t;
}

}  // namespace roofsweep
