#pragma once

#include <utility>
#include <vector>

#include "algorithms/geometry/segment3.h"

namespace roofsweep {

// When one 3D line hypothesis ends on another.
struct JunctionSupportOptions {
  // The end lies within this distance of the other line (metres)...
  double distance_m = 0.3;
  // ... which may be prolonged by this much at either end: detectors stop
  // a few pixels short of corners, on both lines of an L.
  double extend_m = 0.5;
  // The two lines differ in direction by at least this (degrees): a
  // collinear neighbour is the same edge, not a junction.
  double min_angle_deg = 20.0;
};

// Per hypothesis, how many of its two ends (0, 1 or 2) end on another
// hypothesis that is a different line: one sharing none of its (view,
// segment) keys. This is the relational evidence of ATOMI's structural
// matching in its simplest form. A match to the wrong period of repeated
// texture (tile courses) lies metres off in depth: its ends, which in the
// first view sit on the roof's verges, miss the verges' 3D lines, while the
// correct match's ends meet them.
std::vector<int> JunctionSupport(const std::vector<Segment3>& lines,
                                 const std::vector<std::vector<std::pair<int, int>>>& keys,
                                 const JunctionSupportOptions& options = {});

}  // namespace roofsweep
