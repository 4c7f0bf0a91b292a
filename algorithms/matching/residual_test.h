#pragma once

#include <vector>

namespace roofsweep {

// The reprojection residual of a 3D line as a significance test, against a
// noise level the block itself provides (no pixel threshold to tune per
// camera or per orientation quality).
//
// A line fitted to n image segments leaves, per observation, the distances
// of the segment's two endpoints to the reprojected line: 2n residuals for 4
// degrees of freedom of a 3D line. With endpoint noise sigma across the
// segment, their sum of squares (2n * rms²) is sigma² chi²(2n - 4). A
// mismatched segment adds a systematic offset, which this tests for: in the
// simulated blocks, wrong lines (off every surface) have 2–3 times the
// residual of lines on a true edge in the same number of views. Lines in
// two views fit exactly and cannot be tested (2n - 4 = 0).
struct LineFitResidual {
  double rms_px = 0;
  int observations = 0;
};

struct ResidualNoise {
  double sigma_px = 0;  // 0: not estimated (too few lines in three or more views)
  int lines = 0;        // lines in three or more views the estimate rests on
};

// sigma from the median of the normalised residuals 2n rms² / (2n - 4),
// each divided by the median of chi²(k)/k: robust to the wrong lines as long
// as they are fewer than half. Needs `min_lines` lines with three or more
// observations.
ResidualNoise EstimateResidualNoise(const std::vector<LineFitResidual>& fits, int min_lines = 20);

// False when the residual exceeds the (1 - alpha) quantile of
// sigma² chi²(2n - 4); lines with fewer than three observations pass.
bool ResidualConsistent(const LineFitResidual& fit, double sigma_px, double alpha);

}  // namespace roofsweep
