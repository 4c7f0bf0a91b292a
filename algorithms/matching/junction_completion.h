#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "algorithms/matching/epipolar.h"
#include "algorithms/matching/match_lines.h"
#include "algorithms/matching/match_options.h"
#include "algorithms/matching/view_features.h"

namespace roofsweep {

// Lines that stereo cannot reach, completed from their junctions.
//
// A segment nearly parallel to the epipolar lines of every view that sees
// it (an eave or ridge along the flight line where one strip sees the
// building) has no depth of its own: every height is consistent with every
// view. Its ends, though, usually meet lines that stereo did reconstruct
// (the verges at the corners). The 3D line is then the segment's
// interpretation plane cut by those neighbours: each end's junction is
// where the anchoring 3D line pierces the plane. This is the structural
// (relational) evidence of the ATOMI matching, used where the paper's
// "use another view" finds no view.
//
// For every segment of every view that no 3D line uses: at each end, the
// anchor is the 3D line whose projection the end meets within junction_px
// and which pierces the plane at an angle of at least junction_min_angle,
// within junction_gap_m of one of its own ends (an L-junction: a line
// meeting another in its middle, like a tile course between two verges, is
// no corner). With distinct anchors at both ends, the hypothesis must pass
// the same verification in the other views as a stereo pair (ViewSupport),
// with at least one detected segment, and reproject within max_residual.
// Hypotheses are taken greedily (most supporting segments, then longest),
// one-to-one over (view, segment) with the existing lines.
//
// With junction_horizontal, a segment anchored at one end only is completed
// as a horizontal line: its free end where the ray through it meets the
// anchor's height. The roof edges along the flight line are mostly eaves
// and ridges, which are horizontal; the other corner must still be seen
// again in another view, which a wrong height fails wherever the line is not
// exactly along the epipolar lines.
struct JunctionCompletion {
  std::vector<Line3D> lines;
  long long candidates = 0;  // unused segments with an anchor at both ends (or at one, horizontal)
  long long verified = 0;    // ... whose hypothesis passed the verification
  int horizontal = 0;        // lines from one junction, assumed horizontal
};
JunctionCompletion CompleteAtJunctions(const std::vector<ViewFeatures>& views,
                                       const std::vector<Line3D>& lines,
                                       const std::optional<SceneHeights>& z_range,
                                       const MatchOptions& options);

}  // namespace roofsweep
