#pragma once

#include <Eigen/Core>
#include <vector>

// Plan-view (xy) polygon algebra for the evaluator. The types are plain Eigen
// so that CGAL (exact Boolean operations) stays inside plan_geometry.cc.

namespace roofsweep::eval {

// A ring without a repeated closing vertex; any orientation on input.
using Ring2 = std::vector<Eigen::Vector2d>;

struct Polygon2 {
  Ring2 outer;
  std::vector<Ring2> holes;
};

// A plan-view region: the union of its polygons. As made by MakeRegion,
// each polygon has a simple, counter-clockwise outer ring and simple
// clockwise holes; polygons may touch or overlap each other. The pieces are
// kept as they came rather than merged, because a merged outline rounded to
// doubles can touch itself or cross (seen on Berlin LoD2 roofs), and exact
// clipping needs simple rings. Area and IntersectionArea merge exactly.
using MultiPolygon2 = std::vector<Polygon2>;

struct Box2 {
  Eigen::Vector2d min{0, 0};
  Eigen::Vector2d max{-1, -1};  // empty until extended

  bool Empty() const { return max.x() < min.x() || max.y() < min.y(); }
  void Extend(const Eigen::Vector2d& p);
  void Extend(const Box2& b);
  bool Intersects(const Box2& b, double margin = 0) const;
};

Box2 BoundsOf(const MultiPolygon2& m);

// How many input polygons MakeRegion had to leave out.
struct UnionStats {
  int degenerate = 0;  // fewer than 3 distinct vertices or no area
  int invalid = 0;     // outer ring or a hole not simple (self-touching or crossing)
};

// The region covered by `polygons` (any ring orientation). Degenerate and
// non-simple polygons are left out and counted, because clipping is
// undefined for them; a non-simple hole is left out, its polygon kept.
MultiPolygon2 MakeRegion(const std::vector<Polygon2>& polygons, UnionStats* stats = nullptr);

// The merged outline of a region, for drawing and for vertex distances:
// disjoint polygons, collinear vertices (within 0.1 mm) removed. Rings may
// touch themselves, so this is not a region to clip with.
MultiPolygon2 Outline(const MultiPolygon2& region);

// True when p lies inside the region (even-odd per polygon: inside its outer
// ring and in none of its holes); on a boundary either way.
bool Contains(const MultiPolygon2& region, const Eigen::Vector2d& p);

double Area(const MultiPolygon2& region);  // of the union, m²
double IntersectionArea(const MultiPolygon2& a, const MultiPolygon2& b);
// Smallest distance between the two regions (0 when they touch or overlap).
double Distance(const MultiPolygon2& a, const MultiPolygon2& b);

}  // namespace roofsweep::eval
