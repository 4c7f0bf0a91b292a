#pragma once

#include <Eigen/Core>

#include "algorithms/edges/segment2d.h"

namespace roofsweep {

// Distance from a point to the segment (not its line).
double PointSegmentDistance(const Eigen::Vector2d& p, const Segment2D& s);

// Smallest distance between two segments (0 when they cross).
double SegmentDistance(const Segment2D& a, const Segment2D& b);

// Angle between the two segments' lines in degrees, in [0, 90]
// (orientation ignored).
double LineAngleDeg(const Segment2D& a, const Segment2D& b);

// The fraction of `target`'s length that `candidate` covers: 0 when their
// lines differ by more than `max_angle_deg`; otherwise `candidate` is
// projected onto `target`'s line, clipped to `target`, and the clipped part
// counts when both its ends lie within `max_distance` of `target`'s line.
// Orientation is ignored. Used for "already present" in the fusion step
// and for comparing with reference segments.
// The part of `target` that `candidate` covers, by the rule of
// CoveredFraction, as distances [lo, hi] from target.p0 along it; false when
// it covers nothing.
bool CoveredInterval(const Segment2D& target, const Segment2D& candidate, double max_distance,
                     double max_angle_deg, double& lo, double& hi);

double CoveredFraction(const Segment2D& target, const Segment2D& candidate, double max_distance,
                       double max_angle_deg);

}  // namespace roofsweep
