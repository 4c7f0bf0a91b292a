#pragma once

#include "algorithms/geometry/block.h"

namespace roofsweep {

// The terrain under a digital surface model (DSM: roofs, tree crowns), by a
// grey-scale morphological opening: the lowest height within a window of
// window_m x window_m around each cell, then the highest of those lows
// within the same window. Every object whose footprint holds no window
// (buildings narrower than window_m, trees, cars) is cut down to the ground
// around it, and planar slopes come through unchanged, which a plain
// minimum filter would lower. Hill crests narrower than the window are cut
// too, and a building wider than the window in both directions stays (a
// hall of 40 x 40 m at the default 30 m): give a bare-earth DTM where
// there is one. The classic DSM filter (Kilian et al. 1996; the first step
// of the progressive morphological filter, Zhang et al. 2003) in a few lines
// of OpenCV, so no point-cloud library (PDAL's filters.pmf) for one step.
// NaN cells (no data) are ignored and stay NaN; cells whose window holds no
// data at all become NaN.
GroundModel::Grid TerrainFromSurfaceModel(const GroundModel::Grid& dsm, double window_m = 30.0);

}  // namespace roofsweep
