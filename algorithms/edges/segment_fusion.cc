#include "algorithms/edges/segment_fusion.h"

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

}  // namespace roofsweep
