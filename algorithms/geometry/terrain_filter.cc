#include "algorithms/geometry/terrain_filter.h"

#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

#include "algorithms/core/error.h"

namespace roofsweep {

GroundModel::Grid TerrainFromSurfaceModel(const GroundModel::Grid& dsm, double window_m) {
  if (!(window_m > 0) || !(dsm.dx > 0) || !(dsm.dy > 0))
    throw Error("terrain from a surface model: the window and the cell size must be positive");
  if (dsm.rows <= 0 || dsm.cols <= 0 ||
      dsm.z.size() != static_cast<size_t>(dsm.rows) * static_cast<size_t>(dsm.cols))
    throw Error("terrain from a surface model: the grid is empty or inconsistent");
  constexpr float kInf = std::numeric_limits<float>::infinity();
  cv::Mat z(dsm.rows, dsm.cols, CV_32F);
  for (int r = 0; r < dsm.rows; ++r)
    for (int c = 0; c < dsm.cols; ++c) {
      const float v = dsm.z[static_cast<size_t>(r) * dsm.cols + c];
      // No data never wins the minimum.
      z.at<float>(r, c) = std::isfinite(v) ? v : kInf;
    }
  // An odd window at least one cell wide, the same extent in metres along x and y.
  auto side = [&](double cell) {
    return 2 * static_cast<int>(std::lround(0.5 * window_m / cell)) + 1;
  };
  const cv::Mat kernel = cv::getStructuringElement(cv::MORPH_RECT, {side(dsm.dx), side(dsm.dy)});
  cv::Mat low;
  // Outside the grid counts as no data (OpenCV's default border for
  // erosion is +inf and for dilation -inf).
  cv::erode(z, low, kernel);
  // Windows with no data at all: -inf, so that they never win the maximum.
  low.setTo(-kInf, low == kInf);
  cv::Mat open;
  cv::dilate(low, open, kernel);
  GroundModel::Grid out = dsm;
  for (int r = 0; r < dsm.rows; ++r)
    for (int c = 0; c < dsm.cols; ++c) {
      float& v = out.z[static_cast<size_t>(r) * dsm.cols + c];
      const float o = open.at<float>(r, c);
      v = std::isfinite(v) && std::isfinite(o) ? o : std::numeric_limits<float>::quiet_NaN();
    }
  return out;
}

}  // namespace roofsweep
