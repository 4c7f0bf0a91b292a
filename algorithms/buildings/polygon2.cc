#include "algorithms/buildings/polygon2.h"

// Boost.Geometry's rescale policy trips GCC's -Wmaybe-uninitialized in
// release builds (a false positive inside Boost, reported at the
// instantiation in this file).
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <algorithm>
#include <boost/geometry.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>
#include <cmath>
#include <limits>

namespace roofsweep {
namespace {

namespace bg = boost::geometry;
using Point = bg::model::d2::point_xy<double>;
// Counter-clockwise, open rings: the convention of Ring2.
using Polygon = bg::model::polygon<Point, /*ClockWise=*/false, /*Closed=*/false>;

Polygon ToBoost(const Ring2& r) {
  Polygon p;
  for (const auto& v : r) p.outer().emplace_back(v.x(), v.y());
  bg::correct(p);
  return p;
}

double Cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  const Eigen::Vector2d u = b - a, v = c - a;
  return u.x() * v.y() - u.y() * v.x();
}

// True when the closed segments p1-p2 and q1-q2 have a point in common
// (crossing, touching, or overlapping when collinear).
bool SegmentsMeet(const Eigen::Vector2d& p1, const Eigen::Vector2d& p2, const Eigen::Vector2d& q1,
                  const Eigen::Vector2d& q2) {
  if (std::max(p1.x(), p2.x()) < std::min(q1.x(), q2.x()) ||
      std::max(q1.x(), q2.x()) < std::min(p1.x(), p2.x()) ||
      std::max(p1.y(), p2.y()) < std::min(q1.y(), q2.y()) ||
      std::max(q1.y(), q2.y()) < std::min(p1.y(), p2.y()))
    return false;
  const double d1 = Cross(q1, q2, p1), d2 = Cross(q1, q2, p2);
  const double d3 = Cross(p1, p2, q1), d4 = Cross(p1, p2, q2);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
    return true;
  // Collinear end points: on the other segment when inside its box.
  auto on = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
               double d) {
    return d == 0 && std::min(a.x(), b.x()) <= c.x() && c.x() <= std::max(a.x(), b.x()) &&
           std::min(a.y(), b.y()) <= c.y() && c.y() <= std::max(a.y(), b.y());
  };
  return on(q1, q2, p1, d1) || on(q1, q2, p2, d2) || on(p1, p2, q1, d3) || on(p1, p2, q2, d4);
}

}  // namespace

Eigen::Vector4d RingBounds(const Ring2& r) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  Eigen::Vector4d b(kInf, kInf, -kInf, -kInf);
  for (const auto& p : r) {
    b[0] = std::min(b[0], p.x()), b[1] = std::min(b[1], p.y());
    b[2] = std::max(b[2], p.x()), b[3] = std::max(b[3], p.y());
  }
  return b;
}

bool BoundsMeet(const Eigen::Vector4d& a, const Eigen::Vector4d& b) {
  return a[0] <= b[2] && b[0] <= a[2] && a[1] <= b[3] && b[1] <= a[3];
}

namespace {

// Appends `ring` to `out` without repeated vertices, when it has area.
void AddPiece(const std::vector<Eigen::Vector2d>& ring, std::vector<Ring2>* out) {
  Ring2 r;
  for (const Eigen::Vector2d& q : ring)
    if (r.empty() || (q - r.back()).norm() > 1e-9) r.push_back(q);
  while (r.size() > 1 && (r.front() - r.back()).norm() <= 1e-9) r.pop_back();
  if (r.size() >= 3 && SignedArea(r) > 1e-9) out->push_back(std::move(r));
}

Ring2 CounterClockwise(Ring2 r) {
  if (SignedArea(r) < 0) std::reverse(r.begin(), r.end());
  return r;
}

}  // namespace

std::vector<Ring2> IntersectPolygons(const Ring2& a, const Ring2& b) {
  std::vector<Ring2> out;
  if (a.size() < 3 || b.size() < 3) return out;
  // Two convex rings (most patches and footprints): the exact convex clip.
  // Boost's overlay returned no piece at all for a convex outline running
  // along a footprint's edge within millimetres.
  if (IsConvexRing(a) && IsConvexRing(b)) {
    AddPiece(IntersectConvex(CounterClockwise(a), CounterClockwise(b)), &out);
    return out;
  }
  std::vector<Polygon> pieces;
  bg::intersection(ToBoost(a), ToBoost(b), pieces);
  for (const Polygon& p : pieces) {
    std::vector<Eigen::Vector2d> ring;
    for (const Point& v : p.outer()) ring.emplace_back(v.x(), v.y());
    AddPiece(ring, &out);
  }
  return out;
}

std::vector<Ring2> DifferencePolygons(const Ring2& a, const Ring2& b, double min_width,
                                      bool* holed) {
  std::vector<Ring2> out;
  if (holed) *holed = false;
  if (a.size() < 3) return out;
  bg::model::multi_polygon<Polygon> pieces;
  if (b.size() < 3)
    pieces.push_back(ToBoost(a));
  else
    bg::difference(ToBoost(a), ToBoost(b), pieces);
  if (min_width > 0 && !pieces.empty()) {
    const bg::strategy::buffer::side_straight side;
    const bg::strategy::buffer::join_miter join;
    const bg::strategy::buffer::end_flat end;
    const bg::strategy::buffer::point_square point;
    bg::model::multi_polygon<Polygon> shrunk, opened;
    bg::buffer(pieces, shrunk, bg::strategy::buffer::distance_symmetric<double>(-0.5 * min_width),
               side, join, end, point);
    if (!shrunk.empty())
      bg::buffer(shrunk, opened, bg::strategy::buffer::distance_symmetric<double>(0.5 * min_width),
                 side, join, end, point);
    pieces = std::move(opened);
  }
  for (const Polygon& p : pieces) {
    if (!p.inners().empty()) {
      if (holed) *holed = true;
      continue;
    }
    std::vector<Eigen::Vector2d> ring;
    for (const Point& v : p.outer()) ring.emplace_back(v.x(), v.y());
    AddPiece(ring, &out);
  }
  return out;
}

double AreaOfPieces(const std::vector<Ring2>& pieces) {
  double area = 0;
  for (const Ring2& r : pieces) area += std::abs(SignedArea(r));
  return area;
}

double IntersectionArea(const Ring2& a, const Ring2& b) {
  return AreaOfPieces(IntersectPolygons(a, b));
}

Ring2 LargestIntersection(const Ring2& a, const Ring2& b) {
  return LargestRing(IntersectPolygons(a, b));
}

bool IsConvexRing(const Ring2& r) {
  const size_t n = r.size();
  if (n < 3) return false;
  int sign = 0;
  for (size_t i = 0; i < n; ++i) {
    const double c = Cross(r[i], r[(i + 1) % n], r[(i + 2) % n]);
    // Relative tolerance: collinear vertices of long edges are not turns.
    const double scale = (r[(i + 1) % n] - r[i]).norm() * (r[(i + 2) % n] - r[(i + 1) % n]).norm();
    if (std::abs(c) <= 1e-9 * scale) continue;
    const int s = c > 0 ? 1 : -1;
    if (sign != 0 && s != sign) return false;
    sign = s;
  }
  return sign != 0;
}

bool RingSelfIntersects(const Ring2& r, std::pair<size_t, size_t>* edges) {
  const size_t n = r.size();
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // adjacent through the closing vertex
      if (SegmentsMeet(r[i], r[i + 1], r[j], r[(j + 1) % n])) {
        if (edges) *edges = {i, j};
        return true;
      }
    }
  return false;
}

bool InsideRing(const Ring2& r, const Eigen::Vector2d& p) {
  bool in = false;
  for (size_t i = 0, j = r.size() - 1; i < r.size(); j = i++)
    if ((r[i].y() > p.y()) != (r[j].y() > p.y()) &&
        p.x() < r[j].x() + (p.y() - r[j].y()) * (r[i].x() - r[j].x()) / (r[i].y() - r[j].y()))
      in = !in;
  return in;
}

double DistanceToRing(const Ring2& r, const Eigen::Vector2d& p) {
  double d = std::numeric_limits<double>::infinity();
  for (size_t i = 0, j = r.size() - 1; i < r.size(); j = i++)
    d = std::min(d, PointSegmentDistance(p, r[j], r[i]));
  return d;
}

}  // namespace roofsweep
