#pragma once

#include <Eigen/Core>
#include <utility>
#include <vector>

namespace roofsweep {

// Small double-precision routines on convex plan-view polygons
// (counter-clockwise, first vertex not repeated). Written here rather than
// taken from OpenCV, whose convexHull/intersectConvexConvex work in float
// (0.03 mm at 500 m from the origin is too coarse to weld shared roof
// vertices reliably), or CGAL, whose headers would put minutes of compile
// time into every unit that includes this one.
using Ring2 = std::vector<Eigen::Vector2d>;

// Convex hull (Andrew's monotone chain), counter-clockwise, without
// collinear vertices.
Ring2 ConvexHull(std::vector<Eigen::Vector2d> points);

// Signed area (> 0 counter-clockwise).
double SignedArea(const Ring2& ring);
// The ring of largest signed area (the first of equal ones); empty when
// there is none.
Ring2 LargestRing(const std::vector<Ring2>& rings);
// Area times centroid (the first moments) of a ring, signed as SignedArea:
// the centroid is FirstMoment(ring) / SignedArea(ring).
Eigen::Vector2d FirstMoment(const Ring2& ring);

// The part of `ring` where a.x + b.y + c <= 0 (Sutherland-Hodgman against
// one half-plane; convex in, convex out; may return fewer than 3 vertices).
Ring2 ClipHalfPlane(const Ring2& ring, double a, double b, double c);

// The part of the convex ring where lo <= across . x <= hi.
Ring2 ConvexSlab(const Ring2& ring, const Eigen::Vector2d& across, double lo, double hi);

// The least and greatest of d . x over the ring's vertices; {inf, -inf}
// for an empty ring.
std::pair<double, double> ConvexExtent(const Ring2& ring, const Eigen::Vector2d& d);

// The extent along `along` of the chord of the convex ring on the line
// across . x = s; {inf, -inf} when the line misses it.
std::pair<double, double> ConvexChord(const Ring2& ring, const Eigen::Vector2d& across,
                                      const Eigen::Vector2d& along, double s);

// Intersection of two convex polygons.
Ring2 IntersectConvex(const Ring2& p, const Ring2& q);

// True when p lies inside or on the boundary of the convex ring.
bool InsideConvex(const Ring2& ring, const Eigen::Vector2d& p);

// Distance between two convex polygons (0 when they overlap).
double ConvexDistance(const Ring2& p, const Ring2& q);

// The convex polygon grown by `d` (the hull of its vertices moved by d
// along the two normals of their edges; an outer approximation good enough
// for adjacency tests).
Ring2 GrowConvex(const Ring2& ring, double d);

// Distance from p to the segment a-b.
double PointSegmentDistance(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                            const Eigen::Vector2d& b);

}  // namespace roofsweep
