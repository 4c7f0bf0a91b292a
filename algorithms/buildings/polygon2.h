#pragma once

#include <utility>
#include <vector>

#include "algorithms/buildings/convex_polygon2.h"

namespace roofsweep {

// Plan-view operations on simple polygons that may be non-convex (building
// footprints). Boost.Geometry does the clipping: footprints are arbitrary
// simple polygons, and the convex routines of convex_polygon2.h are exact
// only for convex ones. Kept in this one translation unit because the
// Boost.Geometry set operations are heavy to compile.

// Plan-view bounding box (min x, min y, max x, max y); for an empty ring
// min > max, which meets nothing.
Eigen::Vector4d RingBounds(const Ring2& ring);
// True when two bounding boxes overlap or touch.
bool BoundsMeet(const Eigen::Vector4d& a, const Eigen::Vector4d& b);

// The pieces of a ∩ b, each counter-clockwise, first vertex not repeated;
// empty when they do not overlap. Either ring may have either orientation.
// Two convex rings are clipped exactly by IntersectConvex, others by Boost.
std::vector<Ring2> IntersectPolygons(const Ring2& a, const Ring2& b);

// Total plan area of pieces (m², either orientation).
double AreaOfPieces(const std::vector<Ring2>& pieces);

// Area of a ∩ b (m²).
double IntersectionArea(const Ring2& a, const Ring2& b);
// The largest piece of a ∩ b (the first of equal ones), counter-clockwise;
// empty when they do not overlap.
Ring2 LargestIntersection(const Ring2& a, const Ring2& b);

// The pieces of a \ b without holes (a piece of a with b inside it is
// left out whole: a hole is no building outline), each counter-clockwise,
// first vertex not repeated; a itself when they do not overlap. With
// min_width > 0 the parts narrower than it are taken off (an opening:
// shrunk and grown back by half of it, corners kept square): where a and b
// share an edge to within centimetres, the difference leaves a sliver
// along it.
// `holed` (optional) is set when a piece was left out for a hole.
std::vector<Ring2> DifferencePolygons(const Ring2& a, const Ring2& b, double min_width = 0,
                                      bool* holed = nullptr);

// True when p lies inside the ring (even-odd rule: either orientation,
// not necessarily convex; InsideConvex assumes a convex ring).
bool InsideRing(const Ring2& ring, const Eigen::Vector2d& p);
// Plan distance from p to the ring's edges (infinity for an empty ring).
double DistanceToRing(const Ring2& ring, const Eigen::Vector2d& p);

// True when the ring (either orientation) turns one way only (collinear
// vertices allowed).
bool IsConvexRing(const Ring2& ring);

// True when two non-adjacent edges of the ring cross, touch or overlap
// (also spikes: an edge folding back over its predecessor); `edges`
// receives the first such pair of edge indices. O(n²), fine for footprints.
bool RingSelfIntersects(const Ring2& ring, std::pair<size_t, size_t>* edges = nullptr);

}  // namespace roofsweep
