#pragma once

#include <vector>

#include "algorithms/edges/edge_options.h"
#include "algorithms/edges/edge_points.h"
#include "algorithms/edges/line_fit.h"

namespace roofsweep {

// A straight run of edge points and its fitted line, oriented like
// Segment2D: the gradient points to the left normal (fit.Normal()).
struct LinePiece {
  std::vector<int> points;  // indices into EdgeMap::points
  LineFit fit;
};

Points2 PiecePositions(const std::vector<int>& ids, const EdgeMap& map);

// Fits and orients a piece.
LinePiece MakePiece(std::vector<int> ids, const EdgeMap& map);
// Orients a piece whose line is already fitted.
LinePiece OrientPiece(std::vector<int> ids, const LineFit& fit, const EdgeMap& map);

// Chains -> straight pieces (SplitIntoStraightPieces on each chain).
std::vector<LinePiece> ChainsToPieces(const std::vector<std::vector<int>>& chains,
                                      const EdgeMap& map, const EdgeOptions& options);

// Merges collinear pieces across small gaps: candidate pairs (endpoints
// within merge_max_gap, found with an R-tree over the endpoints) are tried
// in order of increasing gap; a pair merges when both point the same way
// (merge_max_angle, same polarity), each end lies within
// merge_max_offset of the other line, the gap along the line is at most
// merge_max_gap, and the refitted union still passes fit_max_deviation and
// the curvature test. Merged pieces keep merging (union-find). Pieces keep
// their order of first appearance.
std::vector<LinePiece> MergeCollinearPieces(std::vector<LinePiece> pieces, const EdgeMap& map,
                                            const EdgeOptions& options);

}  // namespace roofsweep
