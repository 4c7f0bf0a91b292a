#pragma once

#include <string>

#include "algorithms/buildings/convex_polygon2.h"

namespace roofsweep {

// A building footprint (cadastre, OSM, BAG, ...) in the local frame's plan
// view. Footprints restrict and label the reconstruction: roof planes are
// kept and cut where they lie over a footprint, each footprint becomes at
// most one building with its walls on the footprint, and the building
// carries the footprint's id.
struct Footprint {
  std::string id;  // the layer's id field, else its FID, as text
  Ring2 outline;   // exterior ring, counter-clockwise, first vertex not repeated
  // Inner rings (courtyards) are not modelled yet: the building covers
  // them. Counted so that the log can say so.
  int holes = 0;
};

}  // namespace roofsweep
