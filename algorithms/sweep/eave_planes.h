#pragma once

#include <string>
#include <vector>

#include "algorithms/buildings/assemble_buildings.h"

namespace roofsweep {

struct EavePlaneOptions {
  double max_flat_slope_deg = 5.0;   // the planes looked at
  double min_face_slope_deg = 10.0;  // the faces whose eaves they continue
  double min_line_m = 1.0;           // lines of the flat plane that count
  double probe_m = 1.0;              // how far beyond the line the face is looked for
  double max_height_step_m = 0.3;    // the line at the face's height
  double min_rise_m = 0.3;           // the face higher beyond the line than at it
};

// Flat planes that only continue the eaves of sloped faces outwards: every
// supporting line of the flat plane lies at the foot of a kept sloped face
// beyond it (the face at the line's height there, and higher further
// away), and the flat patch lies on the other side. The two eaves that meet
// in the inner corner of an L-shaped house give such a plane at eave height
// over the yard, and texture along the eaves lets it pass the verification.
// Returns, per plane, why it is such a plane (empty for the others).
std::vector<std::string> FlatPlanesBeyondEaves(const std::vector<RoofPlaneHypothesis>& planes,
                                               const EavePlaneOptions& options = {});

}  // namespace roofsweep
