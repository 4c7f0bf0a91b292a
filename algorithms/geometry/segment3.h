#pragma once

#include <Eigen/Core>
#include <algorithm>

namespace roofsweep {

// A straight 3D line segment between two end points (metres, same frame as
// the city model). 3D line reconstruction produces them; the evaluator
// compares them with model edges.
struct Segment3 {
  Eigen::Vector3d a = Eigen::Vector3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();

  double Length() const { return (b - a).norm(); }
  // Unit direction from a to b; zero for a degenerate segment.
  Eigen::Vector3d Direction() const {
    const Eigen::Vector3d d = b - a;
    const double n = d.norm();
    return n > 0 ? Eigen::Vector3d(d / n) : Eigen::Vector3d::Zero();
  }
  // Point at parameter t in [0, 1] (a at 0, b at 1).
  Eigen::Vector3d At(double t) const { return a + t * (b - a); }
  // Euclidean distance from p to the closest point of the segment.
  double Distance(const Eigen::Vector3d& p) const {
    const Eigen::Vector3d d = b - a;
    const double l2 = d.squaredNorm();
    const double t = l2 > 0 ? std::clamp((p - a).dot(d) / l2, 0.0, 1.0) : 0.0;
    return (a + t * d - p).norm();
  }
};

}  // namespace roofsweep
