#pragma once

#include <Eigen/Core>
#include <cmath>

namespace roofsweep {

// Tests only: the plane through point p with the given slope (deg), falling
// towards azimuth (deg, from +x counter-clockwise), as n . X + d = 0.
inline Eigen::Vector4d SlopedPlane(const Eigen::Vector3d& p, double slope_deg, double azimuth_deg) {
  const double s = slope_deg * M_PI / 180, a = azimuth_deg * M_PI / 180;
  const Eigen::Vector3d n(std::sin(s) * std::cos(a), std::sin(s) * std::sin(a), std::cos(s));
  return {n.x(), n.y(), n.z(), -n.dot(p)};
}

}  // namespace roofsweep
