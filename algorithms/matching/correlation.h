#pragma once

#include "algorithms/matching/epipolar.h"

namespace roofsweep {

// Mean pointwise chromatic similarity h = ncc_a* + ncc_b* (Scholze et al.
// 2000, eq. 7-8), or with MatchOptions::correlate_lightness (the default)
// h = 2/3 (ncc_a* + ncc_b* + ncc_L*), along the common part of a pair, for one side of si
// (side: 0 left, 1 right). The areas are the parallelograms bounded by the
// common part, its parallel at the region width and the epipolar lines
// through its ends; in view j the area is stretched across the segment by
// each scale in [1/max_scale, max_scale] and the best mean is returned.
// Cells beyond a neighbouring contour or with outlying L* are left out.
// Grey views correlate L* (h = 2 ncc_L). Returns -9 when no window had
// enough pixels.
double SideCorrelation(const ViewFeatures& vi, const ViewFeatures& vj, const PairGeometry& g,
                       const PairHypothesis& h, int side, const MatchOptions& options);

// Normalised cross-correlation of two equally long samples; 0 when either
// has no variance.
double Ncc(const float* a, const float* b, int n);

}  // namespace roofsweep
