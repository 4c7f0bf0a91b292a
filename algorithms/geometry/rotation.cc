#include "algorithms/geometry/rotation.h"

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace roofsweep {
namespace {
constexpr double kDeg = M_PI / 180.0;
}

Eigen::Matrix3d OpkToRotation(double omega_deg, double phi_deg, double kappa_deg) {
  const double o = omega_deg * kDeg, p = phi_deg * kDeg, k = kappa_deg * kDeg;
  Eigen::Matrix3d rx, ry, rz;
  rx << 1, 0, 0, 0, std::cos(o), -std::sin(o), 0, std::sin(o), std::cos(o);
  ry << std::cos(p), 0, std::sin(p), 0, 1, 0, -std::sin(p), 0, std::cos(p);
  rz << std::cos(k), -std::sin(k), 0, std::sin(k), std::cos(k), 0, 0, 0, 1;
  return rx * ry * rz;
}

Eigen::Vector3d RotationToOpk(const Eigen::Matrix3d& r) {
  const double phi = std::asin(std::clamp(r(0, 2), -1.0, 1.0));
  const double omega = std::atan2(-r(1, 2), r(2, 2));
  const double kappa = std::atan2(-r(0, 1), r(0, 0));
  return Eigen::Vector3d(omega, phi, kappa) / kDeg;
}

Eigen::Matrix3d PatbToCv(const Eigen::Matrix3d& r_patb) {
  return Eigen::Vector3d(1, -1, -1).asDiagonal() * r_patb.transpose();
}

Eigen::Matrix3d CvToPatb(const Eigen::Matrix3d& r_cv) {
  return (Eigen::Vector3d(1, -1, -1).asDiagonal() * r_cv).transpose();
}

Eigen::Matrix3d QuaternionToRotation(double w, double x, double y, double z) {
  return Eigen::Quaterniond(w, x, y, z).normalized().toRotationMatrix();
}

Eigen::Vector4d RotationToQuaternion(const Eigen::Matrix3d& r) {
  Eigen::Quaterniond q(r);
  q.normalize();
  if (q.w() < 0) q.coeffs() *= -1;
  return {q.w(), q.x(), q.y(), q.z()};
}

Eigen::Matrix3d AxisAngleToRotation(const Eigen::Vector3d& v) {
  const double angle = v.norm();
  if (angle < 1e-15) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(angle, v / angle).toRotationMatrix();
}

Eigen::Vector3d RotationToAxisAngle(const Eigen::Matrix3d& r) {
  const Eigen::AngleAxisd aa(r);
  return aa.axis() * aa.angle();
}

Eigen::Matrix3d NearestRotation(const Eigen::Matrix3d& m) {
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(m, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  d(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0 ? -1 : 1;
  return svd.matrixU() * d * svd.matrixV().transpose();
}

double RotationAngleDeg(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  const double c = std::clamp(((a.transpose() * b).trace() - 1) / 2, -1.0, 1.0);
  return std::acos(c) / kDeg;
}

}  // namespace roofsweep
