#include "algorithms/geometry/camera.h"

#include <Eigen/Dense>
#include <cmath>

#include "algorithms/core/error.h"

namespace roofsweep {

Eigen::Matrix3d Camera::K() const {
  Eigen::Matrix3d k;
  k << fx, skew, cx, 0, fy, cy, 0, 0, 1;
  return k;
}

bool Camera::HasDistortion() const { return k1 != 0 || k2 != 0 || k3 != 0 || p1 != 0 || p2 != 0; }

Eigen::Vector2d Camera::Distort(const Eigen::Vector2d& u) const {
  const double x = u.x(), y = u.y();
  const double r2 = x * x + y * y;
  const double radial = 1 + r2 * (k1 + r2 * (k2 + r2 * k3));
  return {x * radial + 2 * p1 * x * y + p2 * (r2 + 2 * x * x),
          y * radial + p1 * (r2 + 2 * y * y) + 2 * p2 * x * y};
}

Eigen::Vector2d Camera::Undistort(const Eigen::Vector2d& d) const {
  if (!HasDistortion()) return d;
  // Newton on f(u) = Distort(u) - d with a numeric Jacobian: converges in a
  // few steps from u = d, also for the strong barrel distortion of drones.
  Eigen::Vector2d u = d;
  for (int it = 0; it < 20; ++it) {
    const Eigen::Vector2d f = Distort(u) - d;
    if (f.squaredNorm() < 1e-26) break;
    const double h = 1e-7;
    Eigen::Matrix2d J;
    J.col(0) = (Distort(u + Eigen::Vector2d(h, 0)) - Distort(u - Eigen::Vector2d(h, 0))) / (2 * h);
    J.col(1) = (Distort(u + Eigen::Vector2d(0, h)) - Distort(u - Eigen::Vector2d(0, h))) / (2 * h);
    u -= J.inverse() * f;
  }
  return u;
}

Eigen::Vector2d Camera::NormalizedToPixel(const Eigen::Vector2d& n) const {
  const Eigen::Vector2d d = Distort(n);
  return {fx * d.x() + skew * d.y() + cx, fy * d.y() + cy};
}

Eigen::Vector2d Camera::PixelToNormalized(const Eigen::Vector2d& p) const {
  const double y = (p.y() - cy) / fy;
  const double x = (p.x() - cx - skew * y) / fx;
  return Undistort({x, y});
}

void Camera::Validate(const std::string& where) const {
  auto bad = [&](const std::string& what) {
    throw Error(where + ": camera '" + id + "': " + what);
  };
  for (double v : {fx, fy, cx, cy, skew, k1, k2, k3, p1, p2}) {
    if (!std::isfinite(v)) bad("parameter is NaN or infinite");
  }
  if (width <= 0 || height <= 0) bad("image size must be positive");
  if (!(fx > 0) || !(fy > 0)) bad("focal length must be positive (got " + std::to_string(fx) + ")");
}

}  // namespace roofsweep
