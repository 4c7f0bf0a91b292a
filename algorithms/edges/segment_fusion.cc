#include "algorithms/edges/segment_fusion.h"

#include <algorithm>
#include <utility>
#include <vector>

#include "algorithms/edges/segment_geometry.h"
#include "algorithms/edges/segment_index.h"

namespace roofsweep {

int AddMissingSegments(Segments2D& base, const Segments2D& extra, double max_distance,
                       double max_angle_deg, double min_overlap) {
  const size_t original = base.size();
  const SegmentIndex index(base);
  Segments2D added;
  for (const Segment2D& s : extra) {
    bool present = false;
    // Covering segments are within max_distance of s somewhere, so this
    // query finds every candidate among the original ones.
    for (int id : index.Near(s, max_distance)) {
      if (CoveredFraction(s, base[id], max_distance, max_angle_deg) >= min_overlap) {
        present = true;
        break;
      }
    }
    // Few segments get added, so a linear scan of those is cheap.
    for (size_t k = 0; !present && k < added.size(); ++k) {
      present = CoveredFraction(s, added[k], max_distance, max_angle_deg) >= min_overlap;
    }
    if (!present) added.push_back(s);
  }
  base.insert(base.end(), added.begin(), added.end());
  return static_cast<int>(base.size() - original);
}

int AddUncoveredParts(Segments2D& base, const Segments2D& extra, double max_distance,
                      double max_angle_deg, double min_length) {
  const SegmentIndex index(base);
  Segments2D added;
  std::vector<std::pair<double, double>> covered;
  for (const Segment2D& s : extra) {
    const double length = s.Length();
    if (!(length >= min_length)) continue;
    covered.clear();
    for (int id : index.Near(s, max_distance)) {
      double lo = 0, hi = 0;
      if (CoveredInterval(s, base[id], max_distance, max_angle_deg, lo, hi))
        covered.emplace_back(lo, hi);
    }
    std::sort(covered.begin(), covered.end());
    covered.emplace_back(length, length);  // closes the last gap
    double start = 0;                      // of the current uncovered part
    for (const auto& [lo, hi] : covered) {
      if (lo - start >= min_length) {
        Segment2D part = s;
        const Eigen::Vector2d d = s.Direction();
        part.p0 = s.p0 + start * d;
        part.p1 = s.p0 + lo * d;
        part.support = std::max(2, static_cast<int>(s.support * (lo - start) / length));
        added.push_back(part);
      }
      start = std::max(start, hi);
    }
  }
  base.insert(base.end(), added.begin(), added.end());
  return static_cast<int>(added.size());
}

}  // namespace roofsweep
