#include "algorithms/eval/plan_geometry.h"

// Boost.Geometry rather than CGAL's Boolean_set_operations_2: the evaluator
// needs areas of intersections and unions of many small polygons in double
// precision, which Boost.Geometry does robustly (its rescaling policy) at a
// fraction of CGAL's compile cost, and with no exact-kernel conversions. It
// comes with libboost-dev, which CGAL already depends on.
#include <algorithm>
#include <boost/geometry.hpp>
#include <boost/geometry/geometries/multi_polygon.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>
#include <cmath>

namespace roofsweep::eval {
namespace bg = boost::geometry;
namespace {

using BPoint = bg::model::d2::point_xy<double>;
using BPolygon = bg::model::polygon<BPoint, /*ClockWise=*/false, /*Closed=*/true>;
using BMulti = bg::model::multi_polygon<BPolygon>;
using BRing = BPolygon::ring_type;

// Removes consecutive duplicates (and the closing repeat) so that a ring of
// fewer than three distinct points is recognised as degenerate.
Ring2 Distinct(const Ring2& r) {
  Ring2 out;
  for (const auto& p : r)
    if (out.empty() || (p - out.back()).norm() > 1e-9) out.push_back(p);
  while (out.size() > 1 && (out.front() - out.back()).norm() <= 1e-9) out.pop_back();
  return out;
}

BRing ToBoost(const Ring2& r) {
  BRing out;
  for (const auto& p : r) out.push_back(BPoint(p.x(), p.y()));
  if (!r.empty()) out.push_back(BPoint(r.front().x(), r.front().y()));
  return out;
}

BMulti ToBoost(const MultiPolygon2& m) {
  BMulti out;
  for (const auto& p : m) {
    BPolygon bp;
    bp.outer() = ToBoost(p.outer);
    for (const auto& h : p.holes) bp.inners().push_back(ToBoost(h));
    out.push_back(std::move(bp));
  }
  return out;
}

Ring2 FromBoost(const BRing& r) {
  Ring2 out;
  for (size_t i = 0; i + 1 < r.size(); ++i) out.emplace_back(bg::get<0>(r[i]), bg::get<1>(r[i]));
  return out;
}

MultiPolygon2 FromBoost(const BMulti& m) {
  MultiPolygon2 out;
  for (const auto& bp : m) {
    Polygon2 p;
    p.outer = FromBoost(bp.outer());
    for (const auto& h : bp.inners()) p.holes.push_back(FromBoost(h));
    out.push_back(std::move(p));
  }
  return out;
}

}  // namespace

void Box2::Extend(const Eigen::Vector2d& p) {
  if (Empty()) {
    min = max = p;
  } else {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
}

void Box2::Extend(const Box2& b) {
  if (b.Empty()) return;
  Extend(b.min);
  Extend(b.max);
}

bool Box2::Intersects(const Box2& b, double margin) const {
  if (Empty() || b.Empty()) return false;
  return min.x() <= b.max.x() + margin && b.min.x() <= max.x() + margin &&
         min.y() <= b.max.y() + margin && b.min.y() <= max.y() + margin;
}

Box2 BoundsOf(const MultiPolygon2& m) {
  Box2 b;
  for (const auto& p : m)
    for (const auto& v : p.outer) b.Extend(v);
  return b;
}

MultiPolygon2 Union(const std::vector<Polygon2>& polygons, UnionStats* stats) {
  UnionStats local;
  BMulti acc;
  for (const auto& in : polygons) {
    const Ring2 outer = Distinct(in.outer);
    if (outer.size() < 3) {
      ++local.degenerate;
      continue;
    }
    BPolygon bp;
    bp.outer() = ToBoost(outer);
    for (const auto& h : in.holes) {
      const Ring2 hole = Distinct(h);
      if (hole.size() >= 3) bp.inners().push_back(ToBoost(hole));
    }
    bg::correct(bp);  // orientation and closure as the polygon type wants
    if (std::abs(bg::area(bp)) < 1e-9) {
      ++local.degenerate;
      continue;
    }
    if (!bg::is_valid(bp)) {
      ++local.invalid;
      continue;
    }
    BMulti next;
    bg::union_(acc, bp, next);
    acc.swap(next);
  }
  BMulti simplified;
  bg::simplify(acc, simplified, 1e-4);
  // simplify may in rare cases spoil validity; fall back to the exact union.
  if (!bg::is_valid(simplified)) simplified = acc;
  if (stats) *stats = local;
  return FromBoost(simplified);
}

double Area(const MultiPolygon2& m) { return bg::area(ToBoost(m)); }

double IntersectionArea(const MultiPolygon2& a, const MultiPolygon2& b) {
  if (a.empty() || b.empty() || !BoundsOf(a).Intersects(BoundsOf(b))) return 0;
  BMulti out;
  bg::intersection(ToBoost(a), ToBoost(b), out);
  return std::max(0.0, static_cast<double>(bg::area(out)));
}

double Distance(const MultiPolygon2& a, const MultiPolygon2& b) {
  return bg::distance(ToBoost(a), ToBoost(b));
}

}  // namespace roofsweep::eval
