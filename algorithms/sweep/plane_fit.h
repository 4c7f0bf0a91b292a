#pragma once

#include <Eigen/Core>
#include <cmath>
#include <vector>

namespace roofsweep {

struct WeightedPoint {
  Eigen::Vector3d x;
  double w;
};

// Total least squares plane n . X + d = 0 (unit n, n_z >= 0) through
// weighted points; returns `fallback` when the points do not span a plane
// (one line, or collinear lines).
Eigen::Vector4d FitPlane(const std::vector<WeightedPoint>& points, const Eigen::Vector4d& fallback);

// Height of the plane n . X + d = 0 above (x, y); the plane must not be
// vertical.
inline double PlaneZ(const Eigen::Vector4d& plane, double x, double y) {
  return -(plane[0] * x + plane[1] * y + plane[3]) / plane[2];
}

// |n . x + d| for a plane with unit normal.
inline double PlaneDistance(const Eigen::Vector4d& plane, const Eigen::Vector3d& x) {
  return std::abs(plane.head<3>().dot(x) + plane[3]);
}

}  // namespace roofsweep
