#pragma once

#include <vector>

#include "algorithms/edges/edge_points.h"

namespace roofsweep {

// Links edge points into chains (lists of indices into map.points, ordered
// along the edge). Each point gets at most one neighbour on either side of
// its tangent: among its 8 neighbouring edge points whose gradient
// direction differs by less than `max_angle_deg` (mod 180°, so the sign
// ambiguity of the Di Zenzo gradient does not matter) and which lie more
// along the tangent than across it, the nearest one. A link is kept only
// when it is mutual, which breaks chains at junctions instead of letting
// them zig-zag between branches. Closed contours come out as one chain
// starting at their lowest index. Chains of fewer than `min_points` points
// are not returned (most chains are a few texture points; not storing them
// saves their allocations). Deterministic.
std::vector<std::vector<int>> LinkEdgePoints(const EdgeMap& map, double max_angle_deg,
                                             int min_points = 1);

}  // namespace roofsweep
