#pragma once

#include <vector>

#include "algorithms/buildings/assemble_buildings.h"
#include "algorithms/buildings/footprint.h"

namespace roofsweep {

// Options of ExtensionsAlongFootprints. Lengths in metres, areas in m².
struct FootprintGrowthOptions {
  // Only sloped planes grow: their contour lines say which way the face
  // runs (a flat plane's patch gives no direction to grow in).
  double min_slope_deg = 5.0;
  // A plane is over a footprint when its patch covers this much of it.
  double min_piece_m2 = 2.0;
  // Strips smaller than this are not proposed (too few samples to verify).
  double min_strip_m2 = 2.0;
  // Another plane's patch stops the growth where this much of it lies in
  // the band; planes within coplanar_angle_deg of the grown one do not.
  double stop_min_m2 = 1.0;
  double coplanar_angle_deg = 5.0;
  // Also propose the corners of the face's own rectangle in the footprint
  // (the band by the piece's extent along it) that its patch leaves out,
  // unless another face's patch lies there: the hull of an eave and a verge
  // is a triangle, half the face, and a face seen over less than half its
  // reference is not matched at all. Over 30 paired runs with footprints
  // (10 blocks x matching seeds 1-3) plane quality rose by 0.41 +- 0.15
  // (9 runs up, 1 down), completeness by 0.46 +- 0.14 (9 / 0), building
  // quality by 0.29 +- 0.12 (5 / 0); correctness -0.05 +- 0.07.
  bool fill_band = true;
};

// A strip of a footprint proposed as the continuation of planes[plane].
struct PatchExtension {
  int plane = -1;
  RoofPlaneHypothesis strip;  // the plane, with the strip as its patch
};

// Growth along footprints: a sloped face the sweep saw over part of its
// footprint runs on along its contour lines until the footprint ends or
// another face begins. Its patch is often less than that: the hull of an
// eave line and one verge is a triangle, and a plane found across a row of
// houses is cut at each footprint where its patch tapers off. The assembly
// then outlines such a face by its patch, not by the footprint, because a
// face seen over part of a footprint is more often one side of a missed
// gable than a shed roof over all of it.
//
// For each sloped plane and each footprint it covers, the band its patch
// spans down the fall line is followed along the contour lines to both
// sides, within the footprint, up to the nearest patch of another
// (non-coplanar) plane over the footprint that reaches into the band; and
// the corners of that band the patch leaves out (fill_band). These strips
// are proposals only: the caller verifies each against the images and
// grows the plane's patch by those confirmed.
// Deterministic.
std::vector<PatchExtension> ExtensionsAlongFootprints(
    const std::vector<RoofPlaneHypothesis>& planes, const std::vector<Footprint>& footprints,
    const FootprintGrowthOptions& options = {});

}  // namespace roofsweep
