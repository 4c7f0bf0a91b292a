#include "algorithms/edges/edge_points.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "algorithms/core/vector_clones.h"

namespace roofsweep {
namespace {

// Candidate state of one row: 0 none, 1 weak (>= low), 2 strong
// (>= high). Branch-free, with every neighbour loaded unconditionally
// (conditional loads would keep the loop scalar), so GCC vectorises it.
RS_VECTOR_CLONES void CandidateRow(const float* __restrict up, const float* __restrict mid,
                                   const float* __restrict down,
                                   const std::uint8_t* __restrict horizontal, float low, float high,
                                   std::uint8_t* __restrict state, int w) {
  for (int x = 1; x < w - 1; ++x) {
    const float c = mid[x], left = mid[x - 1], right = mid[x + 1], top = up[x], bottom = down[x];
    const bool h = horizontal[x];
    const float before = h ? left : top;
    const float after = h ? right : bottom;
    const int candidate = (c >= low) & (c > before) & (c >= after);
    state[x] = static_cast<std::uint8_t>(candidate * (1 + (c >= high)));
  }
}

constexpr std::uint8_t kWeak = 1;
constexpr std::uint8_t kStrong = 2;
constexpr std::uint8_t kKept = 3;

// The columns 1 .. w - 2 of a state row holding `wanted` (kStrong before
// the flood, kKept after it), into xs; returns their number. Eight states
// are tested at once, as one bit each of a word. A byte loop mispredicts on
// candidates as dense as these (one pixel in six of the bench's simulated
// aerial scene).
int CompactColumns(const std::uint8_t* state, std::uint8_t wanted, int* xs, int w) {
  static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "byte x + k is bits 8k .. 8k + 7");
  constexpr std::uint64_t kLow = 0x0101010101010101ull;
  int n = 0;
  int x = 1;
  for (; x + 8 <= w - 1; x += 8) {
    std::uint64_t word;
    std::memcpy(&word, state + x, 8);
    // Bit 8k set where byte k equals `wanted` (states are 0 .. 3).
    std::uint64_t hits = wanted == kKept ? word & (word >> 1) & kLow : (word >> 1) & ~word & kLow;
    while (hits) {
      xs[n++] = x + __builtin_ctzll(hits) / 8;
      hits &= hits - 1;
    }
  }
  for (; x < w - 1; ++x) {
    if (state[x] == wanted) xs[n++] = x;
  }
  return n;
}

}  // namespace

EdgeMap DetectEdgePoints(const GradientField& g, float low, float high) {
  const int w = g.magnitude.cols;
  const int h = g.magnitude.rows;
  EdgeMap map;
  map.index.create(h, w, CV_32S);
  // All bytes 0xff make every int -1: memset writes that in a fraction of
  // the instructions setTo takes (three per pixel).
  std::memset(map.index.data, 0xff, map.index.total() * sizeof(int));
  if (w < 3 || h < 3) return map;
  // Never accept a zero magnitude, even with a zero threshold.
  low = std::max(low, std::numeric_limits<float>::min());
  high = std::max(high, low);

  // 1. Candidates, as their state in a byte raster (a quarter of the
  //    index's memory, so that the flood fill below stays in cache); strong
  //    ones go onto the stack.
  cv::Mat state(h, w, CV_8U);
  state.row(0).setTo(0);
  state.row(h - 1).setTo(0);
  std::vector<int> stack;
  std::vector<int> xs(w);
  for (int y = 1; y < h - 1; ++y) {
    std::uint8_t* s = state.ptr<std::uint8_t>(y);
    s[0] = s[w - 1] = 0;
    CandidateRow(g.magnitude.ptr<float>(y - 1), g.magnitude.ptr<float>(y),
                 g.magnitude.ptr<float>(y + 1), g.horizontal.ptr<std::uint8_t>(y), low, high, s, w);
    const int n = CompactColumns(s, kStrong, xs.data(), w);
    for (int i = 0; i < n; ++i) stack.push_back(y * w + xs[i]);
  }

  // 2. Hysteresis: flood from the strong candidates through weak ones.
  std::uint8_t* base = state.ptr<std::uint8_t>(0);
  for (int seed : stack) base[seed] = kKept;
  const int offsets[8] = {-w - 1, -w, -w + 1, -1, 1, w - 1, w, w + 1};
  size_t kept = stack.size();
  while (!stack.empty()) {
    const int p = stack.back();
    stack.pop_back();
    // Candidates never sit on the outermost pixels, so neighbours exist.
    for (int o : offsets) {
      if (base[p + o] == kWeak) {
        base[p + o] = kKept;
        stack.push_back(p + o);
        ++kept;
      }
    }
  }

  // 3. The kept candidates in raster order, with their sub-pixel positions
  //    and gradients: only now, as hysteresis drops a good part of the
  //    candidates, and one exactly sized array is all the memory they take.
  map.points.reserve(kept);
  std::vector<GradientVector> vectors(w);
  for (int y = 1; y < h - 1; ++y) {
    const float* m = g.magnitude.ptr<float>(y);
    const float* m_up = g.magnitude.ptr<float>(y - 1);
    const float* m_down = g.magnitude.ptr<float>(y + 1);
    const std::uint8_t* horizontal = g.horizontal.ptr<std::uint8_t>(y);
    const std::uint8_t* s = state.ptr<std::uint8_t>(y);
    const int n = CompactColumns(s, kKept, xs.data(), w);
    GradientAtColumns(g, y, xs.data(), n, vectors.data());
    int* index = map.index.ptr<int>(y);
    for (int i = 0; i < n; ++i) {
      const int x = xs[i];
      const float c = m[x];
      const bool along_x = horizontal[x];
      // Both neighbours loaded, then selected: a branch here mispredicts.
      const float left = m[x - 1], right = m[x + 1], top = m_up[x], bottom = m_down[x];
      const float before = along_x ? left : top;
      const float after = along_x ? right : bottom;
      const float curvature = before - 2 * c + after;  // < 0 at a maximum
      float offset = curvature < 0 ? 0.5f * (before - after) / curvature : 0.f;
      offset = std::clamp(offset, -0.5f, 0.5f);
      EdgePoint p;
      p.px = x;
      p.py = y;
      p.x = x + 0.5f + (along_x ? offset : 0.f);
      p.y = y + 0.5f + (along_x ? 0.f : offset);
      p.gx = vectors[i].gx;
      p.gy = vectors[i].gy;
      p.magnitude = c;
      p.band = vectors[i].band;
      index[x] = static_cast<int>(map.points.size());
      map.points.push_back(p);
    }
  }
  return map;
}

}  // namespace roofsweep
