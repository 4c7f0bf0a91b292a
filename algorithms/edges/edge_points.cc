#include "algorithms/edges/edge_points.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace roofsweep {
namespace {

// Candidate state of one row: 0 none, 1 weak (>= low), 2 strong
// (>= high). Branch-free, with every neighbour loaded unconditionally
// (conditional loads would keep the loop scalar), so GCC vectorises it.
void CandidateRow(const float* __restrict up, const float* __restrict mid,
                  const float* __restrict down, const float* __restrict gx,
                  const float* __restrict gy, float low, float high, int* __restrict state, int w) {
  for (int x = 1; x < w - 1; ++x) {
    const float c = mid[x], left = mid[x - 1], right = mid[x + 1], top = up[x], bottom = down[x];
    const bool horizontal = std::fabs(gx[x]) >= std::fabs(gy[x]);
    const float before = horizontal ? left : top;
    const float after = horizontal ? right : bottom;
    const int candidate = (c >= low) & (c > before) & (c >= after);
    state[x] = candidate * (1 + (c >= high));
  }
}

constexpr std::uint8_t kWeak = 1;
constexpr std::uint8_t kStrong = 2;
constexpr std::uint8_t kKept = 3;

}  // namespace

EdgeMap DetectEdgePoints(const GradientField& g, float low, float high) {
  const int w = g.magnitude.cols;
  const int h = g.magnitude.rows;
  EdgeMap map;
  map.index = cv::Mat(h, w, CV_32S, cv::Scalar(-1));
  if (w < 3 || h < 3) return map;
  // Never accept a zero magnitude, even with a zero threshold.
  low = std::max(low, std::numeric_limits<float>::min());
  high = std::max(high, low);

  // 1. Candidates with their sub-pixel positions, and their state in a
  //    byte raster (a quarter of the index's memory, so that the flood fill
  //    below stays in cache); strong ones go onto the stack.
  cv::Mat state(h, w, CV_8U, cv::Scalar(0));
  std::vector<int> row_state(w, 0);
  std::vector<float> gx(w, 0.f), gy(w, 0.f);
  std::vector<EdgePoint> candidates;
  candidates.reserve(static_cast<size_t>(w) * h / 8);
  std::vector<int> stack;
  for (int y = 1; y < h - 1; ++y) {
    GradientRow(g, y, nullptr, gx.data(), gy.data());
    const float* m = g.magnitude.ptr<float>(y);
    const float* m_up = g.magnitude.ptr<float>(y - 1);
    const float* m_down = g.magnitude.ptr<float>(y + 1);
    CandidateRow(m_up, m, m_down, gx.data(), gy.data(), low, high, row_state.data(), w);
    std::uint8_t* s = state.ptr<std::uint8_t>(y);
    for (int x = 1; x < w - 1; ++x) {
      if (!row_state[x]) continue;
      s[x] = static_cast<std::uint8_t>(row_state[x]);
      if (row_state[x] == kStrong) stack.push_back(y * w + x);
      const float c = m[x];
      const bool horizontal = std::fabs(gx[x]) >= std::fabs(gy[x]);
      const float before = horizontal ? m[x - 1] : m_up[x];
      const float after = horizontal ? m[x + 1] : m_down[x];
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
      candidates.push_back(p);
    }
  }

  // 2. Hysteresis: flood from the strong candidates through weak ones.
  std::uint8_t* base = state.ptr<std::uint8_t>(0);
  for (int seed : stack) base[seed] = kKept;
  const int offsets[8] = {-w - 1, -w, -w + 1, -1, 1, w - 1, w, w + 1};
  while (!stack.empty()) {
    const int p = stack.back();
    stack.pop_back();
    // Candidates never sit on the outermost pixels, so neighbours exist.
    for (int o : offsets) {
      if (base[p + o] == kWeak) {
        base[p + o] = kKept;
        stack.push_back(p + o);
      }
    }
  }

  // 3. The kept candidates, still in raster order.
  size_t kept = 0;
  for (const EdgePoint& p : candidates) kept += base[p.py * w + p.px] == kKept;
  map.points.reserve(kept);
  for (const EdgePoint& p : candidates) {
    if (base[p.py * w + p.px] != kKept) continue;
    map.index.ptr<int>(p.py)[p.px] = static_cast<int>(map.points.size());
    map.points.push_back(p);
  }
  return map;
}

}  // namespace roofsweep
