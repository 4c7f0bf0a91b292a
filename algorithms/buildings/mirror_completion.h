#pragma once

#include <vector>

#include "algorithms/buildings/assemble_buildings.h"
#include "algorithms/buildings/footprint.h"
#include "algorithms/buildings/footprint_completion.h"

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
  // Without such a line, the ridge is where the face meets a plane that
  // falls the other way (uphill directions within virtual_ridge_max_turn_deg
  // of opposite, at its slope range, its patch within virtual_ridge_gap_m
  // and beyond the line): the intersection, when it is level in the face
  // as above and has ridge_min_below of the patch below it. The matched
  // piece of a ridge is often shorter than 2 m where the two faces are of
  // one colour, while the other face's plane is found along part of it.
  bool virtual_ridges = true;
  double virtual_ridge_max_turn_deg = 20.0;
  double virtual_ridge_gap_m = 1.0;
  // No proposal where a plane within same_angle_deg covers same_cover of
  // the mirrored patch already, nor for mirrored patches under min_patch_m2.
  // The verification decides on a proposal, so the floor only spares it
  // patches too small to hold any face. At 4 m2 it kept out the gabled
  // garden sheds (faces of about 1.2 x 2.6 m), whose one face found was
  // then under the buildings' minimum footprint of 5 m2 and the shed was
  // lost; at 2 m2, 30 paired runs (ten blocks x matching seeds 1-3) gained
  // plane quality +0.18 +- 0.10 from matched lines and +0.63 +- 0.19 with
  // footprints, every plane added a true one, none lost (1 m2: the same).
  double same_angle_deg = 5.0;
  double same_cover = 0.5;
  double min_patch_m2 = 2.0;
  // The proposal's height along the ridge is that of the face it mirrors,
  // which passed the verification's height test: the caller verifies it
  // without one (VerifyOptions::height_test). With the test, shaded faces
  // of weak texture were refused because the plane moved 0.6 m down scored
  // a little better; 30 paired runs gained plane quality +0.36 +- 0.11
  // from matched lines (9 up, 0 down) and +0.12 +- 0.10 with footprints
  // (sweep README, session 65).
  bool height_from_ridge = true;
};

// Completion by symmetry: most pitched roofs are symmetric about the ridge,
// and the sweep often finds one face of a gable or hip roof and not the
// other (too few lines on it, its half-planes weak). Each face with a
// ridge line at its top (or, without one, a plane falling the other way
// that meets it there: virtual_ridges) proposes its mirror image about the ridge's
// vertical plane: the same slope falling the other way from the same
// ridge, over its own patch reflected across the ridge. The ridge is the
// proposal's supporting line. A proposal is a hypothesis only (derived):
// the caller verifies it photometrically like any other plane, and in
// conflicts it yields to every plane found directly. Deterministic.
std::vector<RoofPlaneHypothesis> MirroredFaces(const std::vector<RoofPlaneHypothesis>& planes,
                                               const MirrorCompletionOptions& options = {});

// Options of MirroredHipEnds. Angles in degrees, lengths in metres.
struct HipEndMirrorOptions {
  // Hip ends and the long faces beside them in this slope range.
  double min_slope_deg = 15.0;
  double max_slope_deg = 65.0;
  // The long faces: two planes falling opposite ways (uphill directions
  // within opposite_max_turn_deg of opposite), each within max_gap_m of
  // the hip end's patch. The hip end rises along their ridge (its uphill
  // direction within end_max_turn_deg of it).
  double opposite_max_turn_deg = 20.0;
  double end_max_turn_deg = 25.0;
  double max_gap_m = 1.0;
  // The point where the three planes meet (the ridge's end) lies within
  // max_gap_m of each patch, and within apex_max_dz_m of the end's top.
  double apex_max_dz_m = 0.5;
  // The hip end lies at one end of the long faces' extent along the ridge:
  // its centroid within end_fraction of that extent from the end it falls
  // towards.
  double end_fraction = 0.35;
  // As MirrorCompletionOptions: no proposal where a plane within
  // same_angle_deg covers same_cover of the mirrored patch, nor for
  // patches under min_patch_m2.
  double same_angle_deg = 5.0;
  double same_cover = 0.5;
  double min_patch_m2 = 1.0;
};

// Completion by symmetry along the ridge: a hipped (or half-hipped) roof
// has an end at each end of its ridge, and the sweep often finds one and
// not the other (a hip end is small and steep, and its hips are edges
// between faces of one colour). Each face that is the end of two long
// faces falling opposite ways proposes its mirror image across the
// vertical plane halfway along the long faces' extent, perpendicular to
// their ridge, with the mirror images of its lines. A proposal is a
// hypothesis only (derived): the caller verifies it photometrically, and
// in conflicts it yields to every plane found directly; where the long
// faces run on over it, it meets them in the convex creases of its hips.
// Deterministic.
std::vector<RoofPlaneHypothesis> MirroredHipEnds(const std::vector<RoofPlaneHypothesis>& planes,
                                                 const HipEndMirrorOptions& options = {});

// Options of FacesMirroredAcrossFootprints. Angles in degrees, lengths in
// metres.
struct FootprintMirrorOptions {
  // Faces in this slope range are mirrored. A flat face mirrors onto its
  // own plane; 75° takes in the steep lower faces of a mansard (60-72°),
  // whose top is no ridge that MirroredFaces could mirror them about.
  double min_slope_deg = 5.0;
  double max_slope_deg = 75.0;
  // An axis of the footprint: through its centroid along its longest edge
  // or across it, when the footprint reflected across it covers at least
  // min_symmetry of itself (a rectangle; not an L).
  double min_symmetry = 0.95;
  // The face lies over the footprint: at least min_inside of its patch.
  double min_inside = 0.8;
  // The face falls across the axis, away from it (its downhill direction
  // in plan within max_turn_deg of the axis's normal, pointing away), and
  // its patch's centroid lies at least min_offset_m from the axis (a face
  // across the axis, a shed over the whole footprint, is its own mirror
  // image).
  double max_turn_deg = 20.0;
  double min_offset_m = 0.5;
  // As MirrorCompletionOptions: no proposal where a plane within
  // same_angle_deg covers same_cover of the mirrored patch already, nor for
  // mirrored patches under min_patch_m2.
  double same_angle_deg = 5.0;
  double same_cover = 0.5;
  double min_patch_m2 = 1.0;
  // A footprint that holds one sloped face (FootprintsBeyondRidges with
  // `beyond`) is left to the roof models beyond its ridge
  // (RoofsOverBareFootprints), which roof the whole part beyond it: the
  // mirror image of a partial face covers only as much as the face, and on
  // `realistic-23` a gable so completed covered too little of its
  // footprint to be matched. False where those models do not run.
  bool leave_one_face = true;
  BeyondRidgeOptions beyond;
};

// Completion by the footprint's symmetry: a house on a rectangular
// footprint is mostly symmetric about its axes, the faces on one side
// mirror images of those on the other. MirroredFaces mirrors a face about
// its own ridge and MirroredHipEnds a hip end along its ridge; neither
// reaches the faces of a mansard, whose steep lower faces meet no ridge and
// whose shallow upper ones (10-22°) are too flat for them, and these were
// where the vertex error with footprints came from (sweep README, session
// 77). Each face over a symmetric footprint that falls across one of its
// axes proposes its mirror image across that axis's vertical plane: the
// normal and the patch reflected, the height kept, the face's plan lines
// mirrored. A proposal is a hypothesis only (derived): the caller verifies
// it photometrically, and in conflicts it yields to every plane found
// directly. Ids say where a proposal comes from. Deterministic.
std::vector<RoofPlaneHypothesis> FacesMirroredAcrossFootprints(
    const std::vector<RoofPlaneHypothesis>& planes, const std::vector<Footprint>& footprints,
    const FootprintMirrorOptions& options = {});

}  // namespace roofsweep
