#include "algorithms/matching/line_triangulation.h"

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <cmath>
#include <limits>

namespace roofsweep {

Eigen::Vector2d LineResidual(const LineObservation& o, const Eigen::Vector3d& A,
                             const Eigen::Vector3d& B) {
  const Eigen::Vector3d a = o.P * A.homogeneous(), b = o.P * B.homogeneous();
  Eigen::Vector3d l = a.cross(b);
  const double n = l.head<2>().norm();
  if (n < 1e-15) return Eigen::Vector2d(1e6, 1e6);
  l /= n;
  return {l.dot(o.q0.homogeneous()), l.dot(o.q1.homogeneous())};
}

namespace {

Eigen::VectorXd Residuals(const std::vector<LineObservation>& obs,
                          const Eigen::Matrix<double, 6, 1>& x) {
  Eigen::VectorXd r(2 * obs.size());
  for (size_t i = 0; i < obs.size(); ++i)
    r.segment<2>(2 * i) = LineResidual(obs[i], x.head<3>(), x.tail<3>());
  return r;
}

// Camera centre and ray direction of an ideal pixel, from P = M [I | -C].
void Ray(const Eigen::Matrix<double, 3, 4>& P, const Eigen::Vector2d& q, Eigen::Vector3d* c,
         Eigen::Vector3d* d) {
  const Eigen::Matrix3d M = P.leftCols<3>();
  const Eigen::Matrix3d Minv = M.inverse();
  *c = -Minv * P.col(3);
  *d = Minv * q.homogeneous();
  // Points in front have positive depth: flip the ray when det(M) < 0.
  if (M.determinant() < 0) *d = -*d;
}

// Position along the line A + t dir (|dir| = 1) of its point closest to the
// ray of the ideal pixel q; NaN when they are parallel.
double AlongLine(const Eigen::Matrix<double, 3, 4>& P, const Eigen::Vector2d& q,
                 const Eigen::Vector3d& A, const Eigen::Vector3d& dir) {
  Eigen::Vector3d c, d;
  Ray(P, q, &c, &d);
  const Eigen::Vector3d w = A - c;
  const double b = dir.dot(d), dd = d.dot(d);
  const double den = dd - b * b;
  if (den < 1e-12 * dd) return std::numeric_limits<double>::quiet_NaN();
  return (b * d.dot(w) - dd * dir.dot(w)) / den;
}

}  // namespace

std::vector<std::pair<double, double>> ObservationSpans(const std::vector<LineObservation>& obs,
                                                        const Segment3& line) {
  std::vector<std::pair<double, double>> spans;
  const Eigen::Vector3d dir = (line.b - line.a).normalized();
  for (const LineObservation& o : obs) {
    const double t0 = AlongLine(o.P, o.q0, line.a, dir), t1 = AlongLine(o.P, o.q1, line.a, dir);
    spans.emplace_back(std::min(t0, t1), std::max(t0, t1));
    if (!std::isfinite(t0) || !std::isfinite(t1))
      spans.back().first = spans.back().second = std::numeric_limits<double>::quiet_NaN();
  }
  return spans;
}

LineEstimate TriangulateLine(const std::vector<LineObservation>& obs, const Segment3& initial,
                             int iterations) {
  LineEstimate out;
  if (obs.size() < 2 || initial.Length() <= 0) return out;
  Eigen::Matrix<double, 6, 1> x;
  x << initial.a, initial.b;
  // Scale of the finite differences: relative to the segment length.
  const double eps = std::max(1e-6, 1e-6 * initial.Length());
  Eigen::VectorXd r = Residuals(obs, x);
  double cost = r.squaredNorm();
  double lambda = 1e-3;
  for (int it = 0; it < iterations; ++it) {
    Eigen::MatrixXd J(r.size(), 6);
    for (int k = 0; k < 6; ++k) {
      Eigen::Matrix<double, 6, 1> xp = x, xm = x;
      xp[k] += eps;
      xm[k] -= eps;
      J.col(k) = (Residuals(obs, xp) - Residuals(obs, xm)) / (2 * eps);
    }
    const Eigen::Matrix<double, 6, 6> JtJ = J.transpose() * J;
    const Eigen::Matrix<double, 6, 1> g = J.transpose() * r;
    bool improved = false;
    for (int tries = 0; tries < 10; ++tries) {
      Eigen::Matrix<double, 6, 6> A = JtJ;
      for (int k = 0; k < 6; ++k) A(k, k) += lambda * (JtJ(k, k) + 1e-9);
      const Eigen::Matrix<double, 6, 1> dx = A.ldlt().solve(-g);
      const Eigen::Matrix<double, 6, 1> xn = x + dx;
      const Eigen::VectorXd rn = Residuals(obs, xn);
      const double cn = rn.squaredNorm();
      if (std::isfinite(cn) && cn < cost) {
        x = xn;
        r = rn;
        const double rel = (cost - cn) / std::max(cost, 1e-30);
        cost = cn;
        lambda = std::max(lambda * 0.3, 1e-9);
        improved = true;
        if (rel < 1e-10) it = iterations;
        break;
      }
      lambda *= 10;
    }
    if (!improved) break;
  }
  const Eigen::Vector3d A = x.head<3>(), B = x.tail<3>();
  const Eigen::Vector3d dir = (B - A).normalized();
  if (!dir.allFinite()) return out;
  // Endpoints: closest points of the line to the rays of all endpoints.
  double tmin = std::numeric_limits<double>::infinity(), tmax = -tmin;
  for (const LineObservation& o : obs)
    for (const Eigen::Vector2d& q : {o.q0, o.q1}) {
      const double t = AlongLine(o.P, q, A, dir);
      if (!std::isfinite(t)) continue;
      tmin = std::min(tmin, t);
      tmax = std::max(tmax, t);
    }
  if (!(tmax > tmin)) return out;
  out.segment.a = A + tmin * dir;
  out.segment.b = A + tmax * dir;
  out.rms_px = std::sqrt(cost / static_cast<double>(r.size()));
  out.valid = true;
  return out;
}

}  // namespace roofsweep
