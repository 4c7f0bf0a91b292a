#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

namespace roofsweep {

// Slope in degrees of a plane with this normal (any length, either
// orientation): 0 for a flat roof, 90 for a wall. Degenerate normals give 90.
inline double SlopeDeg(const Eigen::Vector3d& normal) {
  const double n = normal.norm();
  if (!(n > 0)) return 90.0;
  return std::acos(std::clamp(std::abs(normal.z()) / n, 0.0, 1.0)) * 180.0 / M_PI;
}

}  // namespace roofsweep
