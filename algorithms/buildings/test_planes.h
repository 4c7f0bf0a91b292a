#pragma once

#include <Eigen/Core>
#include <cmath>
#include <string>
#include <utility>

#include "algorithms/buildings/assemble_buildings.h"
#include "algorithms/buildings/convex_polygon2.h"
#include "algorithms/buildings/footprint.h"

namespace roofsweep {

// Tests only: the plane through point p with the given slope (deg), falling
// towards azimuth (deg, from +x counter-clockwise), as n . X + d = 0.
inline Eigen::Vector4d SlopedPlane(const Eigen::Vector3d& p, double slope_deg, double azimuth_deg) {
  const double s = slope_deg * M_PI / 180, a = azimuth_deg * M_PI / 180;
  const Eigen::Vector3d n(std::sin(s) * std::cos(a), std::sin(s) * std::sin(a), std::cos(s));
  return {n.x(), n.y(), n.z(), -n.dot(p)};
}

// Tests only: a plane hypothesis over the hull of `patch`, and a footprint.
inline RoofPlaneHypothesis TestPlane(const Eigen::Vector4d& plane, Ring2 patch,
                                     const std::string& id) {
  RoofPlaneHypothesis h;
  h.plane = plane;
  h.patch = ConvexHull(std::move(patch));
  h.id = id;
  return h;
}

inline Footprint TestFootprint(const std::string& id, Ring2 outline) {
  Footprint f;
  f.id = id;
  f.outline = std::move(outline);
  return f;
}

}  // namespace roofsweep
