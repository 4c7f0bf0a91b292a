#include "algorithms/buildings/right_corners.h"

#include <cmath>

#include "algorithms/buildings/convex_polygon2.h"

namespace roofsweep {

int CountRightCorners(const std::vector<std::array<Eigen::Vector2d, 2>>& l,
                      const RightCornerOptions& o) {
  const double max_cos = std::sin(o.max_angle_deg * M_PI / 180);
  int corners = 0;
  for (size_t i = 0; i < l.size(); ++i) {
    const Eigen::Vector2d di = l[i][1] - l[i][0];
    if (di.norm() < o.min_arm_m) continue;
    for (size_t j = i + 1; j < l.size(); ++j) {
      const Eigen::Vector2d dj = l[j][1] - l[j][0];
      if (dj.norm() < o.min_arm_m) continue;
      if (std::abs(di.normalized().dot(dj.normalized())) > max_cos) continue;
      // Crossing of the two infinite lines; the angle test keeps it finite.
      const double den = di.x() * dj.y() - di.y() * dj.x();
      const Eigen::Vector2d w = l[j][0] - l[i][0];
      const double t = (w.x() * dj.y() - w.y() * dj.x()) / den;
      const Eigen::Vector2d x = l[i][0] + t * di;
      corners += PointSegmentDistance(x, l[i][0], l[i][1]) <= o.max_gap_m &&
                 PointSegmentDistance(x, l[j][0], l[j][1]) <= o.max_gap_m;
    }
  }
  return corners;
}

}  // namespace roofsweep
