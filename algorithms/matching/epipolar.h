#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "algorithms/geometry/segment3.h"
#include "algorithms/matching/view_features.h"

namespace roofsweep {

// Two-view geometry in ideal pixel coordinates: F maps a point of view i to
// its epipolar line in view j (l_j = F p_i); e_i is the image of C_j in
// view i (homogeneous; w ~ 0 when at infinity).
struct PairGeometry {
  Eigen::Matrix3d F = Eigen::Matrix3d::Zero();
  Eigen::Vector3d e_i = Eigen::Vector3d::Zero(), e_j = Eigen::Vector3d::Zero();
  bool valid = false;  // false when the centres coincide (no stereo)
};
PairGeometry MakePairGeometry(const ViewFeatures& vi, const ViewFeatures& vj);

// Unit direction of the epipolar line through p, given the epipole.
Eigen::Vector2d EpipolarDirection(const Eigen::Vector3d& epipole, const Eigen::Vector2d& p);
// Angle in degrees (0..90) between a segment and the epipolar lines through its midpoint.
double EpipolarAngle(const Eigen::Vector3d& epipole, const Segment2D& s);

// World ray through an ideal pixel of a view.
struct WorldRay {
  Eigen::Vector3d origin, direction;  // direction not normalised
};
WorldRay RayThrough(const ViewFeatures& v, const Eigen::Vector2d& ideal_px);
// Plane (n, d) through the camera centre and an image line.
Eigen::Vector4d BackProjectLine(const ViewFeatures& v, const Eigen::Vector2d& a,
                                const Eigen::Vector2d& b);
// Ray-plane intersection; empty when (nearly) parallel.
std::optional<Eigen::Vector3d> IntersectPlane(const WorldRay& ray, const Eigen::Vector4d& plane);
// Ideal pixel of a world point; empty behind the camera.
std::optional<Eigen::Vector2d> ProjectIdeal(const ViewFeatures& v, const Eigen::Vector3d& X);

// The heights a scene point can have (§3.1: "the height range of the scene
// (ground height or DTM + maximum building height)"), in the local frame.
struct SceneHeights {
  // Over the whole block: from the lowest ground less the margin up to the
  // highest ground plus max_building_height and the margin. It bounds the
  // epipolar search window.
  double lo = 0, hi = 0;
  // Where the ground model has a value, a point must lie within the margin
  // of the ground under it and max_building_height above that. On a hillside
  // the block-wide range spans the whole slope: on a real drone block with
  // 56 m of relief it let most two-view matches through at heights no
  // surface has (below the valley floor, far above the hilltop).
  const GroundModel* ground = nullptr;  // not owned; the block's
  double above = 0, margin = 0;
  bool Contains(const Eigen::Vector3d& X) const;
  // Cuts *s back to the part between its first and its last point (sampled
  // every step_m) that Contains holds for; false when it holds nowhere. A
  // line's ends come from the rays of its observed endpoints, which near the
  // epipolar direction meet it far away: 85 m lines reaching 90 m under the
  // ground on that drone block.
  bool Clip(Segment3* s, double step_m = 0.25) const;
};
// Empty when the ground is unknown. The result refers to block.ground.
std::optional<SceneHeights> SceneHeightRange(const Block& block, double margin_m);

// A putative correspondence of segment si in view i with sj in view j.
struct PairHypothesis {
  int vi = -1, vj = -1;       // view indices (into the features vector)
  int si = -1, sj = -1;       // segment ids
  double la = 0, lb = 1;      // common part as parameters on si (p0 at 0, p1 at 1)
  bool reversed = false;      // sj runs opposite to si (its left is si's right)
  Segment3 line;              // 3D segment of the common part
  int sides = 0;              // bit 0: left chromatically compatible, bit 1: right
  double corr[2] = {-9, -9};  // mean h per side of si (§3.4)
  double score = 0;
  int true_pair = -1;  // ground-truth label when known: 1 true, 0 false
};

// Geometric candidates of segment si of view i in view j (§3.1): R-tree
// query over the region the epipolar strip covers within the height range,
// then the exact strip, angle and height tests. Empty when si meets the
// epipolar lines at less than min_epipolar_angle.
std::vector<PairHypothesis> GeometricCandidates(const ViewFeatures& vi, const ViewFeatures& vj,
                                                int i_index, int j_index, const PairGeometry& g,
                                                int si, const std::optional<SceneHeights>& z_range,
                                                const MatchOptions& options);

// The point of segment t's line corresponding to p (intersection with the
// epipolar line of p); empty when parallel.
std::optional<Eigen::Vector2d> EpipolarTransfer(const PairGeometry& g, const Eigen::Vector2d& p,
                                                const Segment2D& t);

}  // namespace roofsweep
