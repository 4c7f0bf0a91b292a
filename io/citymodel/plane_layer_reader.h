#pragma once

#include <string>
#include <vector>

#include "algorithms/eval/plane_losses.h"

namespace roofsweep {

struct PlaneHypothesisSet {
  std::vector<PlaneHypothesisRecord> planes;
  std::string crs;  // empty: none recorded
};

// The roof_planes layer that `roofsweep run -planes` writes (any OGR
// dataset holding it). Throws Error naming the file when it cannot be
// opened, has no such layer, or the layer lacks a status field.
PlaneHypothesisSet ReadPlaneHypotheses(const std::string& path);

}  // namespace roofsweep
