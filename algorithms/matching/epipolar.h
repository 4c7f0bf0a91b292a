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

// Height range of the scene in the local frame (ground - margin up to ground
// + max building height + margin); empty when the ground is unknown.
std::optional<std::pair<double, double>> SceneHeightRange(const Block& block, double margin_m);

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
std::vector<PairHypothesis> GeometricCandidates(
    const ViewFeatures& vi, const ViewFeatures& vj, int i_index, int j_index, const PairGeometry& g,
    int si, const std::optional<std::pair<double, double>>& z_range, const MatchOptions& options);

// The point of segment t's line corresponding to p (intersection with the
// epipolar line of p); empty when parallel.
std::optional<Eigen::Vector2d> EpipolarTransfer(const PairGeometry& g, const Eigen::Vector2d& p,
                                                const Segment2D& t);

}  // namespace roofsweep
