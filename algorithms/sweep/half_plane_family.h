#pragma once

#include <Eigen/Core>
#include <optional>

#include "algorithms/geometry/segment3.h"

namespace roofsweep {

// The one-parameter family of half-planes pi(theta) bounded by a 3D line
// (Baillard & Zisserman 2000, §3.1, figure 3), for one side of the line.
//
// Frame: d is the unit line direction (a -> b); e is the horizontal unit
// vector perpendicular to d, e = s * normalize(z x d) with s = +1 for the
// side left of a -> b seen from above and s = -1 for the right side; n0 is
// the unit vector perpendicular to d closest to the vertical z (so for a
// horizontal line n0 = z). The half-plane at angle theta leaves the line in
// direction w(theta) = cos(theta) e + sin(theta) n0: theta = 0 is the least
// steep plane through the line (the horizontal plane for a horizontal line),
// theta > 0 rises away from the line on that side, theta < 0 falls (a gable
// roof's ridge carries two half-planes at theta = -pitch, its eaves one at
// +pitch on the inner side).
class HalfPlaneFamily {
 public:
  // Empty for a degenerate or (nearly) vertical line, whose sides are not
  // defined by a horizontal direction. `max_line_slope_deg` bounds the
  // line's own inclination from the horizontal.
  static std::optional<HalfPlaneFamily> Make(const Segment3& line, int side,
                                             double max_line_slope_deg = 80.0);

  // Direction in which the half-plane leaves the line (unit, perpendicular
  // to the line).
  Eigen::Vector3d Direction(double theta_rad) const;
  // Unit normal (upward, n_z >= 0 unless the plane is vertical).
  Eigen::Vector3d Normal(double theta_rad) const;
  // The plane (n, -n . a) with n = Normal(theta): n . X + pi_4 = 0.
  Eigen::Vector4d Plane(double theta_rad) const;
  // Angle of the half-plane that contains the line and has unit normal
  // `normal`, on this side; the plane need not exactly contain the line
  // (the component along d is ignored). In [-pi/2, pi/2].
  double AngleOfNormal(const Eigen::Vector3d& normal) const;

  const Segment3& line() const { return line_; }
  int side() const { return side_; }
  const Eigen::Vector3d& d() const { return d_; }
  const Eigen::Vector3d& e() const { return e_; }
  const Eigen::Vector3d& n0() const { return n0_; }

 private:
  Segment3 line_;
  int side_ = 1;
  Eigen::Vector3d d_, e_, n0_;
};

}  // namespace roofsweep
