#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "algorithms/buildings/assemble_buildings.h"
#include "algorithms/buildings/footprint.h"
#include "algorithms/buildings/footprint_roofs.h"
#include "algorithms/geometry/block.h"
#include "algorithms/sweep/verify_planes.h"

namespace roofsweep {

// Options of RoofsOverBareFootprints.
struct BareFootprintRoofOptions {
  // false: the flat roof only (the behaviour before the roof models).
  bool models = true;
  RoofModelOptions model;
  // A sloped model replaces the flat roof only where it fits the images
  // better by this (mean Cor+): a model with more parameters fits noise
  // better.
  double min_gain = 0.05;
  // The eaves lie this high above the ground at least (m).
  double min_height_m = 1.5;
};

// Roof hypotheses over the footprints that no plane covers
// (BareFootprints): every roof model over each (RoofModelsOver) at the
// height the views agree on best (BestModelHeights). The flat roof's height
// is searched from min_height_m to the block's maximum building height; a
// sloped model's eaves lie below it by at most the model's rise, which
// bounds their search (a tenth of the cost). The best model per footprint
// gives its faces, derived, for the caller to verify each like any plane.
// `tried`: how many bare footprints had a ground height. Deterministic.
std::vector<RoofPlaneHypothesis> RoofsOverBareFootprints(
    const Block& block, const std::vector<cv::Mat>& images,
    const std::vector<RoofPlaneHypothesis>& planes, const std::vector<Footprint>& footprints,
    const BareFootprintRoofOptions& options, const VerifyOptions& verify, int* tried);

}  // namespace roofsweep
