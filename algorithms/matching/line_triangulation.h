#pragma once

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "algorithms/geometry/segment3.h"

namespace roofsweep {

// One 2D observation of a 3D line: the segment's endpoints in ideal pixel
// coordinates of a view with projection matrix P (x = P X).
struct LineObservation {
  Eigen::Matrix<double, 3, 4> P;
  Eigen::Vector2d q0, q1;
};

struct LineEstimate {
  Segment3 segment;   // endpoints from the union of the observations
  double rms_px = 0;  // RMS endpoint distance to the projected line
  bool valid = false;
};

// The 3D line minimising the squared distances of all observed endpoints to
// the projected infinite line (Levenberg-Marquardt on two points of the
// line, numerical derivatives: 6 parameters, the 2 gauge freedoms of
// sliding the points along the line damped by LM), from `initial`. The
// result's endpoints are the extreme points of the line closest to the
// back-projected rays of all observed endpoints (the union of the 2D
// supports). Written here rather than with Ceres (not a dependency) as the
// problem is tiny.
LineEstimate TriangulateLine(const std::vector<LineObservation>& observations,
                             const Segment3& initial, int iterations = 20);

// Where each observation lies along `line`: the positions (metres from
// line.a towards line.b) of the points of the line closest to the rays of
// its two endpoints, as (lower, upper). An observation whose rays run
// parallel to the line gets (NaN, NaN).
std::vector<std::pair<double, double>> ObservationSpans(
    const std::vector<LineObservation>& observations, const Segment3& line);

// Residual of one observation for the line through A and B, in pixels:
// (distance of q0, distance of q1) to the projected line.
Eigen::Vector2d LineResidual(const LineObservation& o, const Eigen::Vector3d& A,
                             const Eigen::Vector3d& B);

}  // namespace roofsweep
