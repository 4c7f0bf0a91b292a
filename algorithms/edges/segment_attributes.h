#pragma once

#include <opencv2/core.hpp>

#include "algorithms/edges/gradient.h"
#include "algorithms/edges/line_pieces.h"
#include "algorithms/edges/segment2d.h"

namespace roofsweep {

// Endpoints (the extreme edge points projected onto the fitted line, moved
// out by half a pixel: each point stands for one pixel's piece of edge),
// contrast (mean fused magnitude of its points), RMS residual, support, and
// the carrying band: for kMax the band with the largest summed magnitude
// over the points, kFused for Di Zenzo, kGrey for grey (gradient.method).
Segment2D PieceToSegment(const LinePiece& piece, const EdgeMap& map, const GradientField& gradient);

// Mean colour along the lines parallel to the segment at `distance` px on
// either side, one bilinear sample per pixel of length; samples outside
// the image are skipped (zero colour when none). `image` is the CV_32FC3
// or CV_32FC1 input.
void MeasureSideColours(Segment2D& segment, const cv::Mat& image, double distance);

}  // namespace roofsweep
