#pragma once

#include "algorithms/edges/segment2d.h"

namespace roofsweep {

// The fusion step of Scholze et al. (2000, §2.3): appends to `base` every
// segment of `extra` that is not already present, i.e. that no segment of
// `base` (including ones appended earlier) covers to at least
// `min_overlap` of its length within `max_distance` px and `max_angle_deg`
// (CoveredFraction). Neighbours are found with a SegmentIndex. Returns the
// number of segments added.
int AddMissingSegments(Segments2D& base, const Segments2D& extra, double max_distance,
                       double max_angle_deg, double min_overlap);

// The coarse-scale fusion (EdgeOptions::coarse_fusion): appends to `base`
// the parts of each segment of `extra` that the segments of `base` (as
// given, not what this call appends) leave uncovered, i.e. where no
// segment of `base` lies within `max_distance` px and `max_angle_deg` of it
// (the union of their CoveredInterval), when such a part is at least
// `min_length` long. The parts keep the attributes of their segment.
// Returns the number of segments added.
int AddUncoveredParts(Segments2D& base, const Segments2D& extra, double max_distance,
                      double max_angle_deg, double min_length);

}  // namespace roofsweep
