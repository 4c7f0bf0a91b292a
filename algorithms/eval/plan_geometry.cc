#include "algorithms/eval/plan_geometry.h"

// CGAL's Boolean_set_operations_2 with the exact-constructions kernel, not
// Boost.Geometry: Boost.Geometry 1.74 (Debian bookworm) returned the whole
// of the smaller polygon as the intersection of two roof planes of a Berlin
// LoD2 tile that only touch (vertices 2 mm apart), in projected and in local
// coordinates alike. An evaluator must not miscount like that; exact
// arithmetic cannot. CGAL stays in this one file (compile cost).
#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

namespace roofsweep::eval {
namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using CPoint = K::Point_2;
using CPolygon = CGAL::Polygon_2<K>;
using CPolygonWithHoles = CGAL::Polygon_with_holes_2<K>;
using CSet = CGAL::Polygon_set_2<K>;

// Removes consecutive duplicates (and the closing repeat) so that a ring of
// fewer than three distinct points is recognised as degenerate.
Ring2 Distinct(const Ring2& r) {
  Ring2 out;
  for (const auto& p : r)
    if (out.empty() || (p - out.back()).norm() > 1e-9) out.push_back(p);
  while (out.size() > 1 && (out.front() - out.back()).norm() <= 1e-9) out.pop_back();
  return out;
}

double Cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// Drops vertices within `tol` of the line through their neighbours, until
// none is left, so that merged coplanar pieces give clean outlines.
Ring2 DropCollinear(Ring2 r, double tol) {
  bool changed = true;
  while (changed && r.size() > 3) {
    changed = false;
    for (size_t i = 0; i < r.size() && r.size() > 3; ++i) {
      const Eigen::Vector2d& a = r[(i + r.size() - 1) % r.size()];
      const Eigen::Vector2d& b = r[(i + 1) % r.size()];
      const Eigen::Vector2d d = b - a;
      const double len = d.norm();
      const Eigen::Vector2d ap = r[i] - a;
      const double off = len > 0 ? std::abs(d.x() * ap.y() - d.y() * ap.x()) / len : ap.norm();
      const double t = len > 0 ? ap.dot(d) / (len * len) : 0;
      if (off <= tol && t > 0 && t < 1) {
        r.erase(r.begin() + static_cast<long>(i));
        changed = true;
      }
    }
  }
  return r;
}

// Relative to the first vertex: with projected coordinates (~6e6 m) the
// plain shoelace sum loses all but a few bits of a small roof's area.
double SignedArea(const Ring2& r) {
  double a = 0;
  for (size_t i = 1; i + 1 < r.size(); ++i) a += Cross2(r[i] - r[0], r[i + 1] - r[0]);
  return 0.5 * a;
}

CPolygon ToCgal(const Ring2& r) {
  CPolygon p;
  for (const auto& v : r) p.push_back(CPoint(v.x(), v.y()));
  return p;
}

Ring2 FromCgal(const CPolygon& p) {
  Ring2 r;
  for (auto it = p.vertices_begin(); it != p.vertices_end(); ++it)
    r.emplace_back(CGAL::to_double(it->x()), CGAL::to_double(it->y()));
  return r;
}

// A region's pieces as one exact point set. MakeRegion has checked that
// every ring is simple, which CGAL requires (unchecked in release builds).
CSet ToSet(const MultiPolygon2& m) {
  CSet s;
  for (const auto& p : m) {
    CPolygon outer = ToCgal(p.outer);
    if (outer.orientation() != CGAL::COUNTERCLOCKWISE) outer.reverse_orientation();
    CSet piece(outer);
    // Holes by difference: robust to holes that touch the outer ring or
    // each other, which a Polygon_with_holes_2 may not have.
    for (const auto& h : p.holes) {
      CPolygon hole = ToCgal(h);
      if (hole.orientation() != CGAL::COUNTERCLOCKWISE) hole.reverse_orientation();
      piece.difference(hole);
    }
    s.join(piece);
  }
  return s;
}

MultiPolygon2 FromSet(const CSet& s) {
  std::vector<CPolygonWithHoles> parts;
  s.polygons_with_holes(std::back_inserter(parts));
  MultiPolygon2 out;
  for (const auto& pwh : parts) {
    if (pwh.is_unbounded()) continue;
    Polygon2 p;
    p.outer = DropCollinear(FromCgal(pwh.outer_boundary()), 1e-4);
    for (auto h = pwh.holes_begin(); h != pwh.holes_end(); ++h)
      p.holes.push_back(DropCollinear(FromCgal(*h), 1e-4));
    out.push_back(std::move(p));
  }
  return out;
}

double AreaOfSet(const CSet& s) {
  std::vector<CPolygonWithHoles> parts;
  s.polygons_with_holes(std::back_inserter(parts));
  double a = 0;
  for (const auto& pwh : parts) {
    a += std::abs(CGAL::to_double(pwh.outer_boundary().area()));
    for (auto h = pwh.holes_begin(); h != pwh.holes_end(); ++h)
      a -= std::abs(CGAL::to_double(h->area()));
  }
  return a;
}

double PointSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d d = b - a;
  const double l2 = d.squaredNorm();
  const double t = l2 > 0 ? std::clamp((p - a).dot(d) / l2, 0.0, 1.0) : 0.0;
  return (a + t * d - p).norm();
}

double SegmentSegment(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                      const Eigen::Vector2d& d) {
  const double d1 = Cross2(b - a, c - a), d2 = Cross2(b - a, d - a);
  const double d3 = Cross2(d - c, a - c), d4 = Cross2(d - c, b - c);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
    return 0;  // proper crossing
  return std::min(
      {PointSegment(a, c, d), PointSegment(b, c, d), PointSegment(c, a, b), PointSegment(d, a, b)});
}

// Even-odd test against one piece (outer ring and its holes).
bool InsidePiece(const Eigen::Vector2d& p, const Polygon2& poly) {
  bool in = false;
  auto ring = [&](const Ring2& r) {
    for (size_t i = 0, j = r.size() - 1; i < r.size(); j = i++)
      if ((r[i].y() > p.y()) != (r[j].y() > p.y()) &&
          p.x() < r[i].x() + (p.y() - r[i].y()) * (r[j].x() - r[i].x()) / (r[j].y() - r[i].y()))
        in = !in;
  };
  ring(poly.outer);
  for (const auto& h : poly.holes) ring(h);
  return in;
}

bool Inside(const Eigen::Vector2d& p, const MultiPolygon2& m) {
  for (const auto& poly : m)
    if (InsidePiece(p, poly)) return true;
  return false;
}

template <typename F>
void ForEachEdge(const MultiPolygon2& m, F f) {
  for (const auto& p : m) {
    auto ring = [&](const Ring2& r) {
      for (size_t i = 0; i < r.size(); ++i) f(r[i], r[(i + 1) % r.size()]);
    };
    ring(p.outer);
    for (const auto& h : p.holes) ring(h);
  }
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

MultiPolygon2 MakeRegion(const std::vector<Polygon2>& polygons, UnionStats* stats) {
  UnionStats local;
  MultiPolygon2 out;
  for (const auto& in : polygons) {
    Polygon2 piece;
    piece.outer = Distinct(in.outer);
    if (piece.outer.size() < 3 || std::abs(SignedArea(piece.outer)) < 1e-9) {
      ++local.degenerate;
      continue;
    }
    if (!ToCgal(piece.outer).is_simple()) {
      ++local.invalid;
      continue;
    }
    if (SignedArea(piece.outer) < 0) std::reverse(piece.outer.begin(), piece.outer.end());
    for (const auto& h : in.holes) {
      Ring2 hole = Distinct(h);
      if (hole.size() < 3 || std::abs(SignedArea(hole)) < 1e-9) continue;
      if (!ToCgal(hole).is_simple()) {
        ++local.invalid;
        continue;
      }
      if (SignedArea(hole) > 0) std::reverse(hole.begin(), hole.end());
      piece.holes.push_back(std::move(hole));
    }
    out.push_back(std::move(piece));
  }
  if (stats) *stats = local;
  return out;
}

MultiPolygon2 Outline(const MultiPolygon2& region) { return FromSet(ToSet(region)); }

double Area(const MultiPolygon2& region) {
  if (region.size() == 1 && region[0].holes.empty()) return std::abs(SignedArea(region[0].outer));
  return AreaOfSet(ToSet(region));
}

double IntersectionArea(const MultiPolygon2& a, const MultiPolygon2& b) {
  if (a.empty() || b.empty() || !BoundsOf(a).Intersects(BoundsOf(b))) return 0;
  CSet s = ToSet(a);
  s.intersection(ToSet(b));
  return std::max(0.0, AreaOfSet(s));
}

double Distance(const MultiPolygon2& a, const MultiPolygon2& b) {
  if (a.empty() || b.empty()) return std::numeric_limits<double>::infinity();
  for (const auto& p : a)
    if (Inside(p.outer[0], b)) return 0;
  for (const auto& p : b)
    if (Inside(p.outer[0], a)) return 0;
  double best = std::numeric_limits<double>::infinity();
  ForEachEdge(a, [&](const Eigen::Vector2d& p, const Eigen::Vector2d& q) {
    ForEachEdge(b, [&](const Eigen::Vector2d& r, const Eigen::Vector2d& s) {
      best = std::min(best, SegmentSegment(p, q, r, s));
    });
  });
  return best;
}

namespace {

bool InsideRing(const Ring2& r, const Eigen::Vector2d& p) {
  bool in = false;
  for (size_t i = 0, j = r.size() - 1; i < r.size(); j = i++)
    if ((r[i].y() > p.y()) != (r[j].y() > p.y()) &&
        p.x() < (r[j].x() - r[i].x()) * (p.y() - r[i].y()) / (r[j].y() - r[i].y()) + r[i].x())
      in = !in;
  return in;
}

}  // namespace

bool Contains(const MultiPolygon2& region, const Eigen::Vector2d& p) {
  for (const Polygon2& poly : region) {
    if (poly.outer.size() < 3 || !InsideRing(poly.outer, p)) continue;
    if (std::none_of(poly.holes.begin(), poly.holes.end(),
                     [&](const Ring2& h) { return h.size() >= 3 && InsideRing(h, p); }))
      return true;
  }
  return false;
}

}  // namespace roofsweep::eval
