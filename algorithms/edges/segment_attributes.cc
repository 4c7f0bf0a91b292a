#include "algorithms/edges/segment_attributes.h"

#include <algorithm>
#include <cmath>

namespace roofsweep {
namespace {

// Bilinear sample at a corner-convention position; false outside the
// pixel centres' hull.
bool Sample(const cv::Mat& image, double x, double y, Eigen::Vector3f& out) {
  const double u = x - 0.5;
  const double v = y - 0.5;
  if (!(u >= 0 && v >= 0 && u <= image.cols - 1 && v <= image.rows - 1)) return false;
  const int x0 = std::min(static_cast<int>(u), image.cols - 2 < 0 ? 0 : image.cols - 2);
  const int y0 = std::min(static_cast<int>(v), image.rows - 2 < 0 ? 0 : image.rows - 2);
  const int x1 = std::min(x0 + 1, image.cols - 1);
  const int y1 = std::min(y0 + 1, image.rows - 1);
  const float fx = static_cast<float>(u - x0);
  const float fy = static_cast<float>(v - y0);
  const int c = image.channels();
  const float* r0 = image.ptr<float>(y0);
  const float* r1 = image.ptr<float>(y1);
  for (int k = 0; k < 3; ++k) {
    const int b = c == 1 ? 0 : k;
    const float top = r0[x0 * c + b] * (1 - fx) + r0[x1 * c + b] * fx;
    const float bottom = r1[x0 * c + b] * (1 - fx) + r1[x1 * c + b] * fx;
    out[k] = top * (1 - fy) + bottom * fy;
  }
  return true;
}

}  // namespace

Segment2D PieceToSegment(const LinePiece& piece, const EdgeMap& map,
                         const GradientField& gradient) {
  Segment2D s;
  // Each edge point stands for the edge's crossing of one pixel, so the
  // edge reaches half a pixel beyond the extreme points.
  s.p0 = piece.fit.Start() - 0.5 * piece.fit.direction;
  s.p1 = piece.fit.End() + 0.5 * piece.fit.direction;
  s.rms_residual = static_cast<float>(piece.fit.rms);
  s.support = static_cast<int>(piece.points.size());
  s.method = gradient.method;
  double sum = 0;
  double per_band[3] = {0, 0, 0};
  for (int id : piece.points) {
    const EdgePoint& p = map.points[id];
    sum += p.magnitude;
    if (gradient.method == GradientMethod::kMax) {
      per_band[static_cast<int>(p.band)] += p.magnitude;
    }
  }
  s.contrast = piece.points.empty() ? 0.f : static_cast<float>(sum / piece.points.size());
  switch (gradient.method) {
    case GradientMethod::kMax:
      s.band = static_cast<EdgeBand>(std::max_element(per_band, per_band + 3) - per_band);
      break;
    case GradientMethod::kDiZenzo:
      s.band = EdgeBand::kFused;
      break;
    case GradientMethod::kGrey:
      s.band = EdgeBand::kGrey;
      break;
  }
  return s;
}

void MeasureSideColours(Segment2D& s, const cv::Mat& image, double distance) {
  const double length = s.Length();
  if (length <= 0) return;
  const Eigen::Vector2d d = s.Direction();
  const Eigen::Vector2d n = s.LeftNormal() * distance;
  const int along = std::max(1, static_cast<int>(std::floor(length)));
  Eigen::Vector3f left = Eigen::Vector3f::Zero(), right = Eigen::Vector3f::Zero();
  int nl = 0, nr = 0;
  Eigen::Vector3f v;
  for (int i = 0; i < along; ++i) {
    const Eigen::Vector2d c = s.p0 + (i + 0.5) * (length / along) * d;
    if (Sample(image, c.x() + n.x(), c.y() + n.y(), v)) {
      left += v;
      ++nl;
    }
    if (Sample(image, c.x() - n.x(), c.y() - n.y(), v)) {
      right += v;
      ++nr;
    }
  }
  s.colour_left = nl ? Eigen::Vector3f(left / static_cast<float>(nl)) : Eigen::Vector3f::Zero();
  s.colour_right = nr ? Eigen::Vector3f(right / static_cast<float>(nr)) : Eigen::Vector3f::Zero();
}

}  // namespace roofsweep
