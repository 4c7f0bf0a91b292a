#include "algorithms/sweep/plane_homography.h"

#include <Eigen/Dense>
#include <cmath>

namespace roofsweep {

PlaneHomography ViewPairHomography(const Camera& ref_camera, const Pose& ref_pose,
                                   const Camera& camera, const Pose& pose) {
  PlaneHomography h;
  const Eigen::Matrix3d K = camera.K();
  h.A = K * pose.R * ref_pose.R.transpose() * ref_camera.K().inverse();
  h.a = K * pose.R * (ref_pose.C - pose.C);
  return h;
}

std::optional<Eigen::Vector3d> PlaneVector(const Camera& ref_camera, const Pose& ref_pose,
                                           const Eigen::Vector4d& plane) {
  // X = R^T X_c + C  =>  (R n) . X_c + (n . C + pi_4) = 0.
  const Eigen::Vector3d n = plane.head<3>();
  const Eigen::Vector3d n_c = ref_pose.R * n;
  const double d_c = n.dot(ref_pose.C) + plane(3);
  if (!(std::abs(d_c) > 1e-12 * std::max(1.0, n.norm()))) return std::nullopt;
  return Eigen::Vector3d(-ref_camera.K().inverse().transpose() * n_c / d_c);
}

std::optional<PlaneHomography> HomographyThroughPlane(const Camera& ref_camera,
                                                      const Pose& ref_pose, const Camera& camera,
                                                      const Pose& pose,
                                                      const Eigen::Vector4d& plane) {
  const auto v = PlaneVector(ref_camera, ref_pose, plane);
  if (!v) return std::nullopt;
  PlaneHomography h = ViewPairHomography(ref_camera, ref_pose, camera, pose);
  h.v = *v;
  return h;
}

Eigen::Vector2d IdealPixel(const Camera& camera, const Eigen::Vector2d& pixel) {
  if (!camera.HasDistortion()) return pixel;
  const Eigen::Vector2d n = camera.PixelToNormalized(pixel);
  const Eigen::Vector3d p = camera.K() * Eigen::Vector3d(n.x(), n.y(), 1.0);
  return p.head<2>() / p.z();
}

Eigen::Vector2d MeasuredPixel(const Camera& camera, const Eigen::Vector2d& ideal) {
  if (!camera.HasDistortion()) return ideal;
  const Eigen::Vector3d n = camera.K().inverse() * Eigen::Vector3d(ideal.x(), ideal.y(), 1.0);
  return camera.NormalizedToPixel(n.head<2>() / n.z());
}

}  // namespace roofsweep
