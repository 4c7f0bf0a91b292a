#pragma once

#include <utility>
#include <vector>

#include "algorithms/edges/segment2d.h"
#include "algorithms/geometry/segment3.h"
#include "algorithms/matching/match_options.h"
#include "algorithms/matching/view_features.h"

namespace roofsweep {

// Evidence for a 3D segment in the views that did not propose it (the
// trifocal-style verification of Scholze et al. 2000, §3, over a block).
struct ViewSupport {
  int seeing = 0;         // views where the projection is >= verify_min_length inside the image
  int supporting = 0;     // ... with a detected segment along it
  int gradient_only = 0;  // ... without a segment but with a gradient along it
  std::vector<std::pair<int, int>> segments;  // (view, segment) of the supporting segments

  // Every further view that sees the hypothesis is a chance to refute it,
  // so the support needed grows with them: at least min_support_segments
  // detected segments (or all seeing views when fewer see it), and a
  // support of min_support_fraction of the seeing views, where a gradient
  // without a segment counts half. True when no further view sees it.
  bool Accepted(const MatchOptions& o) const;
};

// The support of `line` in every view of `views` except those in `exclude`.
ViewSupport SupportInViews(const std::vector<ViewFeatures>& views, const Segment3& line,
                           const std::vector<int>& exclude, const MatchOptions& o);

// A detected segment of view v supporting the projection `proj` (ideal
// pixels): the one overlapping it most, or -1.
int SupportingSegment(const ViewFeatures& v, const Segment2D& proj, const MatchOptions& o);

// Clips the segment a-b (ideal pixels) to the image rectangle; false when
// nothing is left.
bool ClipToImage(const ViewFeatures& v, Eigen::Vector2d* a, Eigen::Vector2d* b);

}  // namespace roofsweep
