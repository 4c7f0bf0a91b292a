#include "algorithms/edges/segment_geometry.h"

#include <algorithm>
#include <cmath>

namespace roofsweep {
namespace {

constexpr double kPi = 3.14159265358979323846;

double Cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

bool Crosses(const Segment2D& a, const Segment2D& b) {
  const Eigen::Vector2d da = a.p1 - a.p0;
  const Eigen::Vector2d db = b.p1 - b.p0;
  const double s1 = Cross(da, b.p0 - a.p0);
  const double s2 = Cross(da, b.p1 - a.p0);
  const double s3 = Cross(db, a.p0 - b.p0);
  const double s4 = Cross(db, a.p1 - b.p0);
  return ((s1 > 0) != (s2 > 0)) && ((s3 > 0) != (s4 > 0)) && s1 != 0 && s2 != 0 && s3 != 0 &&
         s4 != 0;
}

}  // namespace

double PointSegmentDistance(const Eigen::Vector2d& p, const Segment2D& s) {
  const Eigen::Vector2d d = s.p1 - s.p0;
  const double len2 = d.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - s.p0).dot(d) / len2, 0.0, 1.0) : 0.0;
  return (p - (s.p0 + t * d)).norm();
}

double SegmentDistance(const Segment2D& a, const Segment2D& b) {
  if (Crosses(a, b)) return 0;
  return std::min({PointSegmentDistance(a.p0, b), PointSegmentDistance(a.p1, b),
                   PointSegmentDistance(b.p0, a), PointSegmentDistance(b.p1, a)});
}

double LineAngleDeg(const Segment2D& a, const Segment2D& b) {
  const Eigen::Vector2d da = a.p1 - a.p0;
  const Eigen::Vector2d db = b.p1 - b.p0;
  return std::atan2(std::fabs(Cross(da, db)), std::fabs(da.dot(db))) * 180.0 / kPi;
}

bool CoveredInterval(const Segment2D& target, const Segment2D& candidate, double max_distance,
                     double max_angle_deg, double& lo, double& hi) {
  const double length = target.Length();
  if (!(length > 0) || !(candidate.Length() > 0)) return false;
  if (LineAngleDeg(target, candidate) > max_angle_deg) return false;
  const Eigen::Vector2d d = target.Direction();
  const Eigen::Vector2d n(d.y(), -d.x());
  const double t0 = (candidate.p0 - target.p0).dot(d);
  const double t1 = (candidate.p1 - target.p0).dot(d);
  const double r0 = (candidate.p0 - target.p0).dot(n);
  const double r1 = (candidate.p1 - target.p0).dot(n);
  lo = std::max(std::min(t0, t1), 0.0);
  hi = std::min(std::max(t0, t1), length);
  if (hi <= lo) return false;
  // The candidate's offset from the target line is linear in t.
  auto offset_at = [&](double t) { return t1 == t0 ? r0 : r0 + (r1 - r0) * (t - t0) / (t1 - t0); };
  return std::fabs(offset_at(lo)) <= max_distance && std::fabs(offset_at(hi)) <= max_distance;
}

double CoveredFraction(const Segment2D& target, const Segment2D& candidate, double max_distance,
                       double max_angle_deg) {
  double lo = 0, hi = 0;
  if (!CoveredInterval(target, candidate, max_distance, max_angle_deg, lo, hi)) return 0;
  return (hi - lo) / target.Length();
}

}  // namespace roofsweep
