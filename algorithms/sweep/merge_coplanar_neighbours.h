#pragma once

#include <vector>

#include "algorithms/buildings/assemble_buildings.h"

namespace roofsweep {

// Options of NearCoplanarMerges. Lengths in metres.
struct NearCoplanarMergeOptions {
  // Two planes are candidates when their normals are within max_angle_deg,
  // their patches come within max_gap_m of each other, and where they meet
  // (the vertices of each patch within meet_m of the other patch) their
  // heights differ by at most max_step_m: one face fitted twice, not a
  // ridge (the faces of a gable differ by twice their slope) nor a step
  // between two roofs.
  double max_angle_deg = 10.0;
  double max_gap_m = 0.5;
  double meet_m = 1.0;
  double max_step_m = 0.3;
  // Samples of the patches on a grid of this spacing fit the merged plane,
  // so that each part weighs by its area.
  double sample_spacing_m = 0.5;
  // The caller keeps a merge when the verification accepts it and its
  // score is at most min_score_loss below the lower of the two planes'.
  double min_score_loss = 0.05;
  // Two planes in a concave crease (ConcaveCrease) are not one face when,
  // over one of the two patches alone, the merged plane scores more than
  // min_score_loss below that plane's own score: a steep face and a
  // shallower false plane below its eave (over a lawn, down to a shed's
  // eave) score, merged, about as well as the weaker of the two, but the
  // merged plane fits the false part clearly worse than its own plane
  // does. The lower envelope cannot roof both, so the caller keeps the one
  // with the higher verified score.
  bool concave_parts = true;
};

// One proposed merge of planes[a] and planes[b].
struct PlaneMerge {
  int a = -1, b = -1;
  RoofPlaneHypothesis merged;  // refitted plane over the hull of both patches
  // The two meet in a concave crease (ConcaveCrease), with concave_parts:
  // the caller checks the merged plane over each part.
  bool concave = false;
};

// True when each plane lies below the other one over the other's patch (at
// the patch's centroid): a steep face with a shallower plane that meets it
// without a step below its eave, not a gable's ridge nor a mansard's break.
// A building is roofed with the lower envelope of its planes, so it would
// put each of the two over the other's part and lose both faces.
bool ConcaveCrease(const RoofPlaneHypothesis& a, const RoofPlaneHypothesis& b);

// One face often comes out as two planes a few degrees apart: two sets of
// its lines that the grouping kept apart (more than GroupingOptions::
// max_distance_m or max_angle_deg between them), each with a patch over
// part of the face, and the assembly then draws a crease between them, or
// neither covers half of the face. Proposes, strongest pair first (summed
// score) and each plane in one pair at most, the merged plane: the
// orthogonal regression over both patches sampled on their own planes, its
// patch the hull of both, its lines and marks the union, derived or height
// from lines only when both are. A proposal only: the caller verifies it.
// Deterministic.
std::vector<PlaneMerge> NearCoplanarMerges(const std::vector<RoofPlaneHypothesis>& planes,
                                           const NearCoplanarMergeOptions& options = {});

// For each plane: is it a candidate of NearCoplanarMerges with another of
// `planes` (whichever pairing the merges would choose)?
std::vector<char> NearCoplanarNeighbours(const std::vector<RoofPlaneHypothesis>& planes,
                                         const NearCoplanarMergeOptions& options = {});

}  // namespace roofsweep
