#pragma once

#include <Eigen/Core>
#include <vector>

// Plan-view (xy) polygon algebra for the evaluator. The types are plain Eigen
// so that Boost.Geometry stays inside plan_geometry.cc (it is header-heavy).

namespace roofsweep::eval {

// A ring without a repeated closing vertex; any orientation on input.
using Ring2 = std::vector<Eigen::Vector2d>;

struct Polygon2 {
  Ring2 outer;
  std::vector<Ring2> holes;
};

// Disjoint polygons; what Union returns is valid (outer rings
// counter-clockwise, holes clockwise, no repeated closing vertex).
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

// How many input polygons Union had to leave out.
struct UnionStats {
  int degenerate = 0;  // fewer than 3 distinct vertices or no area
  int invalid = 0;     // self-intersecting after orientation repair
};

// Union of plan-view polygons (touching, overlapping or apart). Rings are
// re-oriented as needed; degenerate and self-intersecting polygons are left
// out and counted, because a clipping library gives undefined answers for
// them. Collinear vertices (closer than 0.1 mm to the line through their
// neighbours) are removed, so that coplanar pieces merge into clean outlines.
MultiPolygon2 Union(const std::vector<Polygon2>& polygons, UnionStats* stats = nullptr);

double Area(const MultiPolygon2& m);
double IntersectionArea(const MultiPolygon2& a, const MultiPolygon2& b);
// Smallest distance between the two areas (0 when they touch or overlap).
double Distance(const MultiPolygon2& a, const MultiPolygon2& b);

}  // namespace roofsweep::eval
