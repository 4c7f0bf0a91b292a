#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

namespace roofsweep {

// How square corners between plan-view line segments are told.
struct RightCornerOptions {
  double min_arm_m = 1.0;       // both segments at least this long
  double max_angle_deg = 10.0;  // from a right angle
  double max_gap_m = 1.0;       // the crossing this close to both segments
};

// The number of pairs of `lines` (plan view) that meet at a right angle:
// the crossing of their infinite lines lies within max_gap_m of both
// segments. A shed's roof drawn by three of its edges has two; the
// facets of a tree crown or the strokes of a shadow rarely have any.
int CountRightCorners(const std::vector<std::array<Eigen::Vector2d, 2>>& lines,
                      const RightCornerOptions& o);

}  // namespace roofsweep
