#include "algorithms/sweep/half_plane_family.h"

#include <Eigen/Geometry>
#include <cmath>

namespace roofsweep {

std::optional<HalfPlaneFamily> HalfPlaneFamily::Make(const Segment3& line, int side,
                                                     double max_line_slope_deg) {
  if (side != 1 && side != -1) return std::nullopt;
  const double length = line.Length();
  if (!(length > 0) || !std::isfinite(length)) return std::nullopt;
  HalfPlaneFamily f;
  f.line_ = line;
  f.side_ = side;
  f.d_ = line.Direction();
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d h = z.cross(f.d_);
  // |z x d| = cos(slope of the line).
  if (h.norm() < std::cos(max_line_slope_deg * M_PI / 180.0)) return std::nullopt;
  f.e_ = side * h.normalized();
  f.n0_ = f.d_.cross(f.e_) * side;  // unit: d and e are orthonormal
  if (f.n0_.z() < 0) f.n0_ = -f.n0_;
  return f;
}

Eigen::Vector3d HalfPlaneFamily::Direction(double theta) const {
  return std::cos(theta) * e_ + std::sin(theta) * n0_;
}

Eigen::Vector3d HalfPlaneFamily::Normal(double theta) const {
  Eigen::Vector3d n = d_.cross(Direction(theta)).normalized();
  if (n.z() < 0) n = -n;
  return n;
}

Eigen::Vector4d HalfPlaneFamily::Plane(double theta) const {
  const Eigen::Vector3d n = Normal(theta);
  Eigen::Vector4d p;
  p << n, -n.dot(line_.a);
  return p;
}

double HalfPlaneFamily::AngleOfNormal(const Eigen::Vector3d& normal) const {
  // The in-plane direction perpendicular to the line, pointed to this side.
  Eigen::Vector3d w = normal.cross(d_);
  if (w.dot(e_) < 0) w = -w;
  return std::atan2(w.dot(n0_), w.dot(e_));
}

}  // namespace roofsweep
