#pragma once

#include <vector>

#include "algorithms/buildings/assemble_buildings.h"

namespace roofsweep {

struct MirrorCompletionOptions {
  // Faces this steep or steeper (and no steeper than max_slope_deg) are
  // mirrored; flatter ones are sheds and flat roofs more often than half
  // of a gable.
  double min_slope_deg = 15.0;
  double max_slope_deg = 60.0;
  // The ridge: a supporting line of the face at least this long, level in
  // the plane (its plan direction within ridge_max_angle_deg of the
  // contour direction), with at least ridge_min_below of the patch on its
  // downhill side.
  double ridge_min_length_m = 2.0;
  double ridge_max_angle_deg = 10.0;
  double ridge_min_below = 0.7;
  // No proposal where a plane within same_angle_deg covers same_cover of
  // the mirrored patch already, nor for mirrored patches under min_patch_m2.
  double same_angle_deg = 5.0;
  double same_cover = 0.5;
  double min_patch_m2 = 4.0;
};

// Completion by symmetry: most pitched roofs are symmetric about the ridge,
// and the sweep often finds one face of a gable or hip roof and not the
// other (too few lines on it, its half-planes weak). Each face with a
// ridge line at its top proposes its mirror image about the ridge's
// vertical plane: the same slope falling the other way from the same
// ridge, over its own patch reflected across the ridge. The ridge is the
// proposal's supporting line. A proposal is a hypothesis only (derived):
// the caller verifies it photometrically like any other plane, and in
// conflicts it yields to every plane found directly. Deterministic.
std::vector<RoofPlaneHypothesis> MirroredFaces(const std::vector<RoofPlaneHypothesis>& planes,
                                               const MirrorCompletionOptions& options = {});

}  // namespace roofsweep
