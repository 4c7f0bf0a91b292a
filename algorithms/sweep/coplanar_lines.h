#pragma once

#include <vector>

#include "algorithms/sweep/plane_grouping.h"
#include "algorithms/sweep/sweep_half_planes.h"

namespace roofsweep {

// Plane hypotheses from the 3D lines themselves, beside those the sweep
// gives. Baillard & Zisserman 2000 §4 associate "any line which is
// neighbouring and coplanar with the current plane" with it, and §7 call
// for combining their one-line method with the classical grouping of two
// neighbouring coplanar lines (Bignone et al. 1996, Moons et al. 1998): a
// face whose half-planes the sweep could not confirm (weak texture, small
// baselines) is still proposed when two of its edges were matched. Every
// such hypothesis goes through the §5 photometric verification like the
// sweep's. Lengths in metres.
struct CoplanarOptions {
  // A line lies on a plane when both end points are within max_distance_m
  // of it. Joining a plane may not turn it by more than max_angle_deg (the
  // paper's rule against short or nearby lines).
  double max_distance_m = 0.25;
  double max_angle_deg = 5.0;
  // A line joins a plane whose patch it comes within max_gap_m of in plan
  // (the sweep's support often stops short of the eave).
  double max_gap_m = 2.0;
  // Lines shorter than this are not used (too short to fix a plane).
  double min_line_length_m = 1.5;
  // Two non-parallel lines make a plane when they meet: their closest
  // points are within max_distance_m in 3D and within junction_gap_m of
  // both segments (lines stop short of junctions). Two parallel lines
  // (within parallel_angle_deg) make one when they overlap by at least
  // min_overlap of the shorter and lie min_pair_distance_m to
  // max_pair_distance_m apart in plan (a roof face's width), with no third
  // long parallel line between them (the ridge between two eaves, the
  // inner verges between the verges of two neighbouring houses).
  double junction_gap_m = 1.5;
  double parallel_angle_deg = 5.0;
  double min_junction_angle_deg = 20.0;
  double min_overlap = 0.5;
  double min_pair_distance_m = 1.0;
  double max_pair_distance_m = 15.0;
  double max_slope_deg = 70.0;
  double min_area_m2 = 2.0;
  // A hypothesis is refused when other lines run over its patch off the
  // plane by more than crossing_offset_m for at least crossing_fraction of
  // the longest line in all (and at least crossing_min_m): the ridge and
  // hips above the plane through two eaves. Dormers are shorter.
  double crossing_offset_m = 0.5;
  double crossing_fraction = 0.5;
  double crossing_min_m = 3.0;
  // A pair is refused when one of its lines is horizontal and bounds this
  // plane on its far side: that line's half-plane facing away from the
  // other line is a sweep candidate within continuation_angle_deg of the
  // pair's plane, and the one facing the other line is not. The pair would
  // continue a face the sweep found past its edge: a house's roof face
  // continued beyond its eave onto the edge of a garage near its extension
  // (on `realistic` s1 the pair was 5 deg steeper than the face). The two
  // faces of a ridge differ by twice the pitch, 20 deg and more above a
  // 10 deg pitch, so a ridge does not count as a face continued. Needs the
  // half-planes (PlanesFromLinePairs' `half_planes`).
  bool refuse_past_bounding_line = true;
  double continuation_angle_deg = 10.0;
  // AttachCoplanarLines leaves out a line whose half-plane on the plane's
  // side (where its patch's centre lies) is a sweep candidate more than
  // continuation_angle_deg off the plane while neither of its half-planes
  // lies within it: the images see another face beside that line. A
  // terraced row's flat roofs at the eave height of the gabled houses
  // beside them have their edge collinear with the eave, on the gable
  // face's plane; attached, it grew that face's patch over the flat roofs
  // (`realistic` s2). Needs the half-planes.
  bool refuse_other_face = true;
};

// Adds to `planes` every line that is coplanar with a plane and within
// max_gap_m of its patch; refits the plane by orthogonal regression over
// its lines (the previous plane as a weak prior at its patch corners) and
// grows the patch by the line. Lines in `planes` index `lines`. Returns the
// number of lines attached. Deterministic. With `half_planes` (the sweep's),
// a line that bounds another face is left out (refuse_other_face).
int AttachCoplanarLines(const std::vector<SweepLine>& lines, std::vector<PlaneGroup>* planes,
                        const CoplanarOptions& options = {},
                        const std::vector<HalfPlane>* half_planes = nullptr);

// Plane hypotheses from pairs of neighbouring coplanar lines (see
// CoplanarOptions). One that is coplanar with another or with one of
// `existing` and overlaps it by min_overlap of the smaller patch is the
// same face: its lines join that plane instead. Deterministic.
// `half_planes` (optional): the sweep's result over `lines`, for
// CoplanarOptions::refuse_past_bounding_line.
std::vector<PlaneGroup> PlanesFromLinePairs(const std::vector<SweepLine>& lines,
                                            std::vector<PlaneGroup>* existing,
                                            const CoplanarOptions& options = {},
                                            const std::vector<HalfPlane>* half_planes = nullptr);

}  // namespace roofsweep
