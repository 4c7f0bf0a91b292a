#pragma once

#include <vector>

#include "algorithms/matching/match_lines.h"
#include "algorithms/matching/match_options.h"
#include "algorithms/matching/view_features.h"

namespace roofsweep {

// The ends of a 3D line that no stereo pair holds, checked at the line's
// depth.
//
// A line takes its depth from all its observations but its ends from the
// union of its 2D supports (issue 5), so an observation that runs on past
// the others carries the line on at the depth the others gave it. Where a
// collinear edge continues at another depth that is wrong: the eaves of a
// terraced row stepping down a slope are one straight image edge in the
// near-nadir views (the step moves them by less than a pixel) and two
// pieces in the others, and the line of the first house ran on over its
// neighbour's eave at its own height (matching README, "Stepped terraces").
//
// The part that two views hold which see the line at min_epipolar_angle or
// more from their epipolar lines has its depth from stereo; two views of
// one strip do not fix a line along the flight direction (any two views
// when no such pair overlaps). Each end beyond it is kept only when the
// views that did not observe it, but see it, confirm it at the line's depth
// by the rule that verified the matched pair (ViewSupport::Accepted);
// otherwise the line is cut back to the part the pairs hold. An end no
// other view sees is kept: nothing refutes it. Returns the length removed
// (metres).
double CutUnconfirmedEnds(const std::vector<ViewFeatures>& views, const MatchOptions& o,
                          Line3D* line);

}  // namespace roofsweep
