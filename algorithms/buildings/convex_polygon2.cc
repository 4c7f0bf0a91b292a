#include "algorithms/buildings/convex_polygon2.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace roofsweep {
namespace {

double Cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

bool SegmentsCross(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                   const Eigen::Vector2d& d) {
  const double d1 = Cross(a, b, c), d2 = Cross(a, b, d), d3 = Cross(c, d, a), d4 = Cross(c, d, b);
  return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0));
}

}  // namespace

bool InsideConvex(const Ring2& ring, const Eigen::Vector2d& p) {
  const size_t n = ring.size();
  if (n < 3) return false;
  for (size_t i = 0; i < n; ++i)
    if (Cross(ring[i], ring[(i + 1) % n], p) < -1e-12) return false;
  return true;
}

Ring2 ConvexHull(std::vector<Eigen::Vector2d> pts) {
  std::sort(pts.begin(), pts.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  if (pts.size() < 3) return pts;
  Ring2 hull(2 * pts.size());
  size_t k = 0;
  for (size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && Cross(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
    hull[k++] = pts[i];
  }
  for (size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && Cross(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
    hull[k++] = pts[i];
  }
  hull.resize(k - 1);
  return hull;
}

double SignedArea(const Ring2& r) {
  double a = 0;
  for (size_t i = 0, n = r.size(); i < n; ++i) {
    const Eigen::Vector2d& p = r[i];
    const Eigen::Vector2d& q = r[(i + 1) % n];
    a += p.x() * q.y() - q.x() * p.y();
  }
  return 0.5 * a;
}

Ring2 LargestRing(const std::vector<Ring2>& rings) {
  const auto largest = std::max_element(
      rings.begin(), rings.end(),
      [](const Ring2& a, const Ring2& b) { return SignedArea(a) < SignedArea(b); });
  return largest == rings.end() ? Ring2{} : *largest;
}

Eigen::Vector2d FirstMoment(const Ring2& r) {
  Eigen::Vector2d m = Eigen::Vector2d::Zero();
  for (size_t i = 0, n = r.size(); i < n; ++i) {
    const Eigen::Vector2d& p = r[i];
    const Eigen::Vector2d& q = r[(i + 1) % n];
    m += (p.x() * q.y() - q.x() * p.y()) * (p + q) / 6.0;
  }
  return m;
}

Ring2 ClipHalfPlane(const Ring2& ring, double a, double b, double c) {
  Ring2 out;
  const size_t n = ring.size();
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d& p = ring[i];
    const Eigen::Vector2d& q = ring[(i + 1) % n];
    const double fp = a * p.x() + b * p.y() + c, fq = a * q.x() + b * q.y() + c;
    if (fp <= 0) out.push_back(p);
    if ((fp < 0 && fq > 0) || (fp > 0 && fq < 0)) {
      const double t = fp / (fp - fq);
      out.push_back(p + t * (q - p));
    }
  }
  return out;
}

Ring2 ConvexSlab(const Ring2& ring, const Eigen::Vector2d& across, double lo, double hi) {
  return ClipHalfPlane(ClipHalfPlane(ring, -across.x(), -across.y(), lo), across.x(), across.y(),
                       -hi);
}

std::pair<double, double> ConvexExtent(const Ring2& ring, const Eigen::Vector2d& d) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Eigen::Vector2d& x : ring) lo = std::min(lo, d.dot(x)), hi = std::max(hi, d.dot(x));
  return {lo, hi};
}

std::pair<double, double> ConvexChord(const Ring2& ring, const Eigen::Vector2d& across,
                                      const Eigen::Vector2d& along, double s) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (size_t k = 0; k < ring.size(); ++k) {
    const Eigen::Vector2d& p = ring[k];
    const Eigen::Vector2d& q = ring[(k + 1) % ring.size()];
    const double sp = across.dot(p) - s, sq = across.dot(q) - s;
    if ((sp > 0 && sq > 0) || (sp < 0 && sq < 0)) continue;
    const double t = sp == sq ? 0.0 : sp / (sp - sq);
    const double f = along.dot(p + t * (q - p));
    lo = std::min(lo, f), hi = std::max(hi, f);
  }
  return {lo, hi};
}

Ring2 IntersectConvex(const Ring2& p, const Ring2& q) {
  Ring2 out = p;
  const size_t n = q.size();
  for (size_t i = 0; i < n && out.size() >= 3; ++i) {
    const Eigen::Vector2d& a = q[i];
    const Eigen::Vector2d& b = q[(i + 1) % n];
    // Inside = left of a -> b: cross(b - a, x - a) >= 0.
    const double ea = (b.y() - a.y()), eb = -(b.x() - a.x());
    out = ClipHalfPlane(out, ea, eb, -(ea * a.x() + eb * a.y()));
  }
  return out.size() >= 3 ? out : Ring2{};
}

double PointSegmentDistance(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                            const Eigen::Vector2d& b) {
  const Eigen::Vector2d d = b - a;
  const double l2 = d.squaredNorm();
  const double t = l2 > 0 ? std::clamp((p - a).dot(d) / l2, 0.0, 1.0) : 0.0;
  return (a + t * d - p).norm();
}

double ConvexDistance(const Ring2& p, const Ring2& q) {
  if (p.empty() || q.empty()) return std::numeric_limits<double>::infinity();
  if (InsideConvex(p, q[0]) || InsideConvex(q, p[0])) return 0.0;
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < p.size(); ++i) {
    const Eigen::Vector2d& a = p[i];
    const Eigen::Vector2d& b = p[(i + 1) % p.size()];
    for (size_t j = 0; j < q.size(); ++j) {
      const Eigen::Vector2d& c = q[j];
      const Eigen::Vector2d& d = q[(j + 1) % q.size()];
      if (SegmentsCross(a, b, c, d)) return 0.0;
      best = std::min({best, PointSegmentDistance(a, c, d), PointSegmentDistance(c, a, b)});
    }
  }
  return best;
}

Ring2 GrowConvex(const Ring2& ring, double d) {
  std::vector<Eigen::Vector2d> pts;
  const size_t n = ring.size();
  if (n < 2) {
    for (const auto& p : ring)
      for (int k = 0; k < 8; ++k)
        pts.push_back(p + d * Eigen::Vector2d(std::cos(k * M_PI / 4), std::sin(k * M_PI / 4)));
    return ConvexHull(pts);
  }
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d& a = ring[i];
    const Eigen::Vector2d& b = ring[(i + 1) % n];
    const Eigen::Vector2d e = (b - a).normalized();
    const Eigen::Vector2d out(e.y(), -e.x());  // right of a -> b = outside for CCW
    pts.push_back(a + d * out);
    pts.push_back(b + d * out);
  }
  return ConvexHull(pts);
}

}  // namespace roofsweep
