#include "algorithms/edges/texture_filter.h"

#include <algorithm>
#include <cmath>

#include "algorithms/edges/segment_index.h"

namespace roofsweep {

std::vector<bool> MarkRepetitiveTexture(const Segments2D& segments, const EdgeOptions& o) {
  struct Hit {
    double offset;
    float contrast;
  };
  const SegmentIndex index(segments);
  const double cos_max = std::cos(o.texture_max_angle * M_PI / 180.0);
  std::vector<bool> out(segments.size(), false);
  std::vector<Hit> left, right;
  for (size_t i = 0; i < segments.size(); ++i) {
    const Segment2D& s = segments[i];
    const Eigen::Vector2d d = s.Direction(), n = s.LeftNormal();
    const double len = s.Length();
    left.clear();
    right.clear();
    for (int j : index.Neighbours(static_cast<int>(i), o.texture_max_offset)) {
      const Segment2D& t = segments[static_cast<size_t>(j)];
      // Signed: the brighter side on the same hand (Segment2D's orientation).
      if (d.dot(t.Direction()) < cos_max) continue;
      const double offset = n.dot(t.Midpoint() - s.p0);
      if (std::abs(offset) < o.texture_min_offset || std::abs(offset) > o.texture_max_offset)
        continue;
      double a = d.dot(t.p0 - s.p0), b = d.dot(t.p1 - s.p0);
      if (a > b) std::swap(a, b);
      const double overlap = std::min(b, len) - std::max(a, 0.0);
      if (overlap < o.texture_min_overlap * std::min(len, t.Length())) continue;
      (offset > 0 ? left : right).push_back({std::abs(offset), t.contrast});
    }
    for (size_t l = 0; l < left.size() && !out[i]; ++l) {
      if (s.contrast >= o.texture_dominance * left[l].contrast) continue;
      for (const Hit& r : right) {
        if (s.contrast >= o.texture_dominance * r.contrast) continue;
        const double ratio = left[l].offset / r.offset;
        if (ratio <= o.texture_spacing_ratio && ratio >= 1.0 / o.texture_spacing_ratio) {
          out[i] = true;
          break;
        }
      }
    }
  }
  return out;
}

}  // namespace roofsweep
