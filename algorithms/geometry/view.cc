#include "algorithms/geometry/view.h"

#include <Eigen/Dense>
#include <cmath>

namespace roofsweep {

Matrix34d ProjectionMatrix(const Camera& camera, const Pose& pose) {
  Matrix34d rt;
  rt.leftCols<3>() = pose.R;
  rt.col(3) = pose.Translation();
  return camera.K() * rt;
}

std::optional<Eigen::Vector2d> Project(const Camera& camera, const Pose& pose,
                                       const Eigen::Vector3d& world) {
  const Eigen::Vector3d x = pose.ToCamera(world);
  if (!(x.z() > 0)) return std::nullopt;
  return camera.NormalizedToPixel(x.head<2>() / x.z());
}

Ray BackProject(const Camera& camera, const Pose& pose, const Eigen::Vector2d& pixel) {
  const Eigen::Vector2d n = camera.PixelToNormalized(pixel);
  const Eigen::Vector3d d = pose.R.transpose() * Eigen::Vector3d(n.x(), n.y(), 1.0);
  return {pose.C, d.normalized()};
}

std::optional<Eigen::Vector3d> IntersectHorizontalPlane(const Ray& ray, double height) {
  if (std::abs(ray.direction.z()) < 1e-12) return std::nullopt;
  const double t = (height - ray.origin.z()) / ray.direction.z();
  if (!(t > 0)) return std::nullopt;
  return ray.origin + t * ray.direction;
}

std::optional<Eigen::Vector3d> IntersectPlane(const Ray& ray, const Eigen::Vector4d& plane,
                                              double min_incidence) {
  const double denom = plane.head<3>().dot(ray.direction);
  if (!(std::abs(denom) >= min_incidence)) return std::nullopt;
  const double t = -(plane.head<3>().dot(ray.origin) + plane[3]) / denom;
  if (!(t > 0)) return std::nullopt;
  return ray.origin + t * ray.direction;
}

void DecomposeProjection(const Matrix34d& P_in, Eigen::Matrix3d* K, Eigen::Matrix3d* R,
                         Eigen::Vector3d* C) {
  Matrix34d P = P_in;
  // The centre is the right null vector of P.
  Eigen::JacobiSVD<Matrix34d> svd(P, Eigen::ComputeFullV);
  const Eigen::Vector4d c = svd.matrixV().col(3);
  *C = c.head<3>() / c(3);

  // RQ of M via QR of the row-reversed transpose.
  Eigen::Matrix3d M = P.leftCols<3>();
  if (M.determinant() < 0) {
    P = -P;
    M = -M;
  }
  Eigen::Matrix3d flip;
  flip << 0, 0, 1, 0, 1, 0, 1, 0, 0;
  Eigen::HouseholderQR<Eigen::Matrix3d> qr((flip * M).transpose());
  Eigen::Matrix3d q = qr.householderQ();
  Eigen::Matrix3d r = qr.matrixQR().triangularView<Eigen::Upper>();
  Eigen::Matrix3d k = flip * r.transpose() * flip;
  Eigen::Matrix3d rot = flip * q.transpose();
  // Make K's diagonal positive; each sign flip is mirrored in R.
  Eigen::Matrix3d s = Eigen::Matrix3d::Identity();
  for (int i = 0; i < 3; ++i)
    if (k(i, i) < 0) s(i, i) = -1;
  k = k * s;
  rot = s * rot;
  *K = k / k(2, 2);
  *R = rot;
}

}  // namespace roofsweep
