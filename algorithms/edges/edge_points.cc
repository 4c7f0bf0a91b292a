#include "algorithms/edges/edge_points.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace roofsweep {

EdgeMap SuppressNonMaxima(const GradientField& g, float low) {
  const int w = g.magnitude.cols;
  const int h = g.magnitude.rows;
  EdgeMap map;
  map.index = cv::Mat(h, w, CV_32S, cv::Scalar(-1));
  if (w < 3 || h < 3) return map;
  // Never accept a zero magnitude, even with a zero threshold.
  const float floor = std::max(low, std::numeric_limits<float>::min());
  const bool has_band = !g.band.empty();
  const size_t step = g.magnitude.step1();
  for (int y = 1; y < h - 1; ++y) {
    const float* m = g.magnitude.ptr<float>(y);
    const float* gx = g.gx.ptr<float>(y);
    const float* gy = g.gy.ptr<float>(y);
    int* idx = map.index.ptr<int>(y);
    for (int x = 1; x < w - 1; ++x) {
      const float c = m[x];
      if (!(c >= floor)) continue;
      const bool horizontal = std::fabs(gx[x]) >= std::fabs(gy[x]);
      const float before = horizontal ? m[x - 1] : m[x - step];
      const float after = horizontal ? m[x + 1] : m[x + step];
      if (!(c > before && c >= after)) continue;
      const float curvature = before - 2 * c + after;  // < 0 at a maximum
      float offset = curvature < 0 ? 0.5f * (before - after) / curvature : 0.f;
      offset = std::clamp(offset, -0.5f, 0.5f);
      EdgePoint p;
      p.px = x;
      p.py = y;
      p.x = x + 0.5f + (horizontal ? offset : 0.f);
      p.y = y + 0.5f + (horizontal ? 0.f : offset);
      p.gx = gx[x];
      p.gy = gy[x];
      p.magnitude = c;
      p.band = has_band ? g.band.ptr<uchar>(y)[x] : static_cast<std::uint8_t>(EdgeBand::kFused);
      idx[x] = static_cast<int>(map.points.size());
      map.points.push_back(p);
    }
  }
  return map;
}

void ApplyHysteresis(EdgeMap& map, float high) {
  const int n = static_cast<int>(map.points.size());
  std::vector<char> keep(n, 0);
  std::vector<int> stack;
  for (int i = 0; i < n; ++i) {
    if (keep[i] || map.points[i].magnitude < high) continue;
    keep[i] = 1;
    stack.push_back(i);
    while (!stack.empty()) {
      const EdgePoint& p = map.points[stack.back()];
      stack.pop_back();
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          // Points never sit on the outermost pixels, so neighbours exist.
          const int j = map.index.ptr<int>(p.py + dy)[p.px + dx];
          if (j >= 0 && !keep[j]) {
            keep[j] = 1;
            stack.push_back(j);
          }
        }
      }
    }
  }
  std::vector<EdgePoint> kept;
  kept.reserve(n);
  for (int i = 0; i < n; ++i) {
    const EdgePoint& p = map.points[i];
    int& slot = map.index.ptr<int>(p.py)[p.px];
    if (keep[i]) {
      slot = static_cast<int>(kept.size());
      kept.push_back(p);
    } else {
      slot = -1;
    }
  }
  map.points = std::move(kept);
}

}  // namespace roofsweep
