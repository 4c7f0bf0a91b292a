#include "algorithms/sweep/plane_fit.h"

#include <Eigen/Eigenvalues>
#include <algorithm>

namespace roofsweep {

Eigen::Vector4d FitPlane(const std::vector<WeightedPoint>& pts, const Eigen::Vector4d& fallback) {
  double sw = 0;
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const auto& p : pts) sw += p.w, c += p.w * p.x;
  if (sw <= 0) return fallback;
  c /= sw;
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const auto& p : pts) cov += p.w * (p.x - c) * (p.x - c).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov / sw);
  const Eigen::Vector3d ev = es.eigenvalues();  // ascending
  if (!(ev[1] > 1e-4 * std::max(ev[2], 1e-12))) return fallback;
  Eigen::Vector3d n = es.eigenvectors().col(0);
  if (n.z() < 0) n = -n;
  return {n.x(), n.y(), n.z(), -n.dot(c)};
}

}  // namespace roofsweep
