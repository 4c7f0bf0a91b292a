#pragma once

#include <Eigen/Core>
#include <array>
#include <map>
#include <string>
#include <vector>

#include "algorithms/buildings/city_model.h"
#include "algorithms/buildings/footprint.h"
#include "algorithms/geometry/block.h"

namespace roofsweep {

// A delineated roof plane as the sweep's grouping and delineation hand it on
// (Baillard & Zisserman 2000, §4-§5): the plane and the plan-view patch
// where the images support it.
struct RoofPlaneHypothesis {
  Eigen::Vector4d plane = Eigen::Vector4d::Zero();  // n . X + d = 0, n unit, n_z > 0
  std::vector<Eigen::Vector2d> patch;  // convex, counter-clockwise seen from above (x, y)
  double score = 0;                    // reliability (larger is better)
  int lines = 0;                       // supporting 3D lines
  double longest_line_m = 0;           // length of the longest of them
  double similarity = 0;               // mean Sim of its half-planes
  std::string id;                      // for the log ("plane 12")
  // Plan view (x, y) of its supporting 3D lines: where one runs along the
  // building's outline, the outline follows the line (B&Z §5 delineation
  // by border lines) rather than the edge of the patches.
  std::vector<std::array<Eigen::Vector2d, 2>> lines_xy;
  // Plan segments down the fall line where the face's colour changes
  // across its whole depth (FindColourBreaks): a party wall that no line
  // marks. The assembly cuts at them as at a line down the face
  // (split_at_party_lines); they support nothing else.
  std::vector<std::array<Eigen::Vector2d, 2>> colour_breaks;
  // Proposed by a completion step from another plane rather than found by
  // the sweep over this patch: in conflicts it yields to every found plane
  // (completion fills gaps, it does not overrule direct evidence).
  bool derived = false;
  // Accepted without the verification's height test (the images could not
  // tell its height; its lines placed it): in conflicts it yields to every
  // plane whose height the images confirmed.
  bool height_from_lines = false;
  // RMS reprojection residual (px) of those of its supporting 3D lines
  // that have one, and how many do (0: residual unknown).
  double reprojection_rms_px = 0;
  int reprojection_lines = 0;
};

// Options of AssembleBuildings. Lengths in metres.
struct AssemblyOptions {
  // Planes steeper than this are walls or errors, not roofs.
  double max_roof_slope_deg = 70.0;
  // A roof plane must lie at least this high above the ground at its patch
  // centre (lower planes are ground, cars, hedges). 2 m sits above cars
  // (1.4-1.9 m) and below garages, carports and sheds (2.0-2.6 m); at 2.5 m
  // the simulator's garages were lost even from true edges (5-7 roof planes
  // per `realistic` block), with no gain in correctness from matched lines.
  double min_height_m = 2.0;
  // A roof face is bounded by straight edges: a plane whose longest
  // supporting 3D line is shorter than this is dropped. Tree crowns, roof
  // furniture and shadows give only short lines (on the `realistic` block
  // 3 m kept plane completeness and raised correctness from 68 % to 88 %);
  // the cost is garden sheds under 3 m, below the 6 m buildings.
  double min_line_length_m = 3.0;
  // ... unless it meets a plane that passes (within adjacency_gap_m, the
  // heights within max_step_m there) and its longest line reaches this:
  // dormers, hip ends and porches of 1-7 m2 have lines of 2-3 m (14 true
  // faces of `realistic` seed 1 from true edges were lost to the 3 m).
  double min_attached_line_length_m = 1.5;
  // ... or when two of its lines, each at least corner_min_arm_m long,
  // meet at a right angle (within corner_max_angle_deg, their crossing
  // within adjacency_gap_m of both): garages and sheds of 2-3 m stand
  // alone, and tree crowns, hedges and shadows do not draw square corners
  // (on the six eval blocks from matched lines, 23 of the 26 short-lined
  // planes this keeps were true, against 15 of 53 among the others).
  bool keep_right_corners = true;
  double corner_min_arm_m = 1.0;
  double corner_max_angle_deg = 10.0;
  // ... and a short-lined plane that meets one kept for its square corner
  // is kept when the two are the faces of one gable (see GableFaces in the
  // .cc): a garden shed's gable, one face holding its eave and verge, the
  // other, often mirrored from it, only the ridge. On 30 paired runs (ten
  // blocks x matching seeds 1-3) from matched lines plane quality +0.53 +-
  // 0.19 (7 up, none down), every added plane true; joining any plane to
  // them (not only the gable's other face) grew tree crowns facet by facet
  // (`realistic` s1: six false planes on each seed; correctness -0.93 +-
  // 0.32 over the 30).
  bool join_gable_to_corners = true;
  double gable_min_slope_deg = 10.0;
  double gable_max_slope_difference_deg = 5.0;
  double gable_max_azimuth_deg = 10.0;
  // Without footprints, a building hypothesis left with one short-lined
  // plane that was kept only for meeting others (the two rules above), all
  // of which the assembly dropped on the way, is dropped too: it no longer
  // joins a roof (a tree crown's facet beside a false face the envelope
  // rejected). A porch split off its house as a convex part of its own
  // stays, its house being kept. On 30 paired runs from matched lines
  // (session 57) plane quality +0.13 +- 0.06 (5 up, none down),
  // completeness unchanged, building quality +0.28 +- 0.12; every plane
  // it dropped was false.
  bool drop_lone_companions = true;
  // Two patches belong to one building when they come within adjacency_gap_m
  // of each other in plan view and their planes meet there (height
  // difference below max_step_m): a lower neighbour across a party wall is a
  // separate building.
  double adjacency_gap_m = 1.0;
  double max_step_m = 0.7;
  // Planes meeting at a valley (concave junction) go into separate convex
  // parts, each a solid of its own with the attribute building_group in
  // common (the parts overlap in plan near the valley); false: one lower
  // envelope per building, which drops the higher wing of an L or T.
  bool split_at_valleys = true;
  // Two planes of one convex part meet along the line where they cross, so
  // in plan that line runs along the strip where their grown patches
  // overlap, as a ridge or hip does. Terraced houses of different roof
  // types (a gable beside a shed roof rising the same way) meet at a party
  // wall instead, and their planes cross along a line that runs across
  // that strip: one envelope over both would lay a strip of each plane
  // across the whole row. Such planes go into separate convex parts when
  // the crossing line covers less than edge_min_along of the strip's
  // longest extent (planes whose gradients differ by less than 0.1, nearly
  // parallel, and lines missing the strip keep the centroid test alone).
  // The split comes after the envelope has dropped the planes it cannot
  // support: a false plane in the gap between two roofs that crosses them
  // across is dropped there as before, not built as a part of its own.
  // Without footprints only: with them the footprints divide the row, and
  // parts of one footprint would be buildings of their own.
  bool split_across_edges = true;
  double edge_min_along = 0.5;
  // Roof faces of the lower envelope smaller than this, or lying mostly
  // outside their own patch (less than min_support of their area inside
  // the patch grown by adjacency_gap_m), are dropped and the envelope
  // recomputed: a plane may bound the roof only where the images saw it.
  double min_face_area_m2 = 1.0;
  double min_support = 0.3;
  // A plane whose face in the envelope is less than hidden_max_fraction of
  // its patch was seen where the others' extensions lie below it: it is no
  // part of their roof but a neighbouring roof at another height (terraced
  // houses of different heights join into one hypothesis at the party
  // wall). It goes on as a hypothesis of its own, like the pieces of a
  // split at a valley, before any face is dropped; false: it is dropped
  // like a sliver.
  bool split_hidden = true;
  double hidden_max_fraction = 0.25;
  // ... unless more than hidden_duplicate_overlap of its patch lies in the
  // others' patches: hidden where they were seen too, it is a second fit
  // of their face (two planes 3 deg apart from the lines of one face,
  // overlapping too little for the conflicts), and is dropped like a
  // sliver instead of becoming a shed roof of its own inside the other
  // roof. As the conflicts' GroupingOptions::max_overlap; 1 turns it off.
  double hidden_duplicate_overlap = 0.5;
  // Party walls: terraced houses often share one plane across their roofs
  // (same eave, ridge and pitch), which the sweep groups into one; where
  // the neighbours' roofs differ (material, colour, a seam), matching finds
  // a line down the shared plane at the party wall. A supporting line of a
  // sloped plane (at least party_min_slope_deg), within the face, that runs
  // down its fall line (within party_max_angle_deg) over at least
  // party_min_span of the face's depth there (at least party_min_depth_m:
  // a porch roof or a dormer's face does not run through a building), with
  // at least party_min_width_m of the face on either side, cuts
  // its building hypothesis in two along it (without footprints; with them
  // the footprints cut). The cut reaches one face depth past the line at
  // either end (into the facing face over the ridge); planes beyond go
  // whole with the side that holds more of them. Verges lie at a face's
  // edge, dormers, chimneys and roof windows span a part of its depth.
  bool split_at_party_lines = true;
  double party_min_slope_deg = 10.0;
  double party_max_angle_deg = 10.0;
  double party_min_span = 0.6;
  double party_min_width_m = 3.0;
  double party_min_depth_m = 2.5;
  // Every other face the cut runs through (not coplanar with the line's)
  // must carry a line along the cut, at least party_confirm_length_m long
  // within party_confirm_offset_m of it: real city models divide one face
  // and not the facing one (Berlin 3910_5819).
  double party_confirm_length_m = 1.0;
  double party_confirm_offset_m = 0.5;
  // Buildings whose outline is smaller than this are logged and dropped.
  double min_footprint_m2 = 5.0;
  // With footprints, a plane over one needs only these height and line
  // length instead of min_height_m and min_line_length_m: the footprint
  // already says a building stands there, so the heuristics that keep
  // hedges, cars and tree crowns out can let garages and garden sheds in
  // (on `realistic` seed 2 from the simulator's edges plane completeness
  // 66 -> 76 %, correctness 86 -> 88 %).
  double footprint_min_height_m = 1.5;
  double footprint_min_line_length_m = 1.5;
  // With footprints: a plane is kept when at least footprint_min_inside of
  // its patch lies over footprints, and cut into one plane per footprint
  // it covers by at least footprint_min_piece_m2 (smaller overlaps are
  // eaves and registration error, not roof).
  double footprint_min_inside = 0.5;
  double footprint_min_piece_m2 = 2.0;
  // A footprint holding one convex roof part becomes the building's
  // outline when every roof face over it is seen (inside its grown patch)
  // over at least this fraction of its area; else the outline is the hull
  // of the patches cut at the footprint, with min_support. Higher than
  // min_support: one side of a gable seen alone, its patch grown by
  // adjacency_gap_m, covers 0.55-0.7 of a 6-20 m wide footprint and must
  // not become a shed roof over all of it; faces seen on both sides are
  // covered 0.9-1.
  double footprint_min_support = 0.75;
  // ... except for a footprint whose one plane is (nearly) horizontal, at
  // most footprint_flat_max_slope_deg: a flat roof has no other side that
  // its extension could hide, and it covers its building whole. It then
  // needs footprint_flat_min_support only. Flat roofs of one weak texture
  // (a green roof beside a lawn, bitumen) are seen where their structures
  // are, and the building was built over that part of its footprint alone.
  double footprint_flat_max_slope_deg = 5.0;
  double footprint_flat_min_support = 0.3;
  // With footprints: the solids built over one footprint become the parts
  // of one building (CityGML BuildingParts) with the footprint's id and the
  // attributes of the whole (building_parts, summed roof_planes,
  // supporting_lines, reliability and footprint_m2, photometric_score over
  // all faces, the parts' outline values joined by "; ", the roof type of
  // its largest part, or gabled where the parts' faces together make a
  // gable, the height of the whole); a footprint
  // roofed by one solid stays a plain building.
  // false: each solid is a building of its own, labelled with the id.
  bool join_parts_per_footprint = true;
  // Without footprints: the convex parts of one adjacency group (the wings
  // of an L split at its valley; they share building_group) become the
  // parts of one building, which holds building_group and the figures of
  // the whole as above. Pieces split off a group (a hidden neighbour at
  // another height, a roof beyond an edge, pieces that no longer touch)
  // stay buildings of their own: joined too, they made a terraced row one
  // building and cost 60 correct roof types over 30 runs (session 23).
  bool join_parts_per_group = true;
  // ... and two shed-roof solids of one adjacency group that meet back to
  // back at a common ridge (slopes facing apart within 20 deg, ridge
  // heights within gable_ridge_max_step_m and gable_ridge_max_offset_m
  // apart in plan, overlapping over half the shorter ridge): the two faces
  // of one gable, built apart when the lower envelope of a row hid one of
  // them. They become the parts of one building whose roof type is gabled.
  bool join_gable_halves = true;
  double gable_ridge_max_step_m = 0.3;
  double gable_ridge_max_offset_m = 0.5;
  // Border lines: a supporting line within border_max_offset_m of an edge
  // of the outline (the convex hull of the patches) and within
  // border_max_angle_deg of it, over at least half its length, moves that
  // edge onto itself; the patches stop short of their lines (the sweep's
  // windows keep off them) or run past the eaves.
  bool border_lines = true;
  double border_max_offset_m = 1.0;
  double border_max_angle_deg = 10.0;
  // Square corners: where two outline edges of at least corner_min_side_m
  // meet at a right angle (within corner_max_angle_deg, as above) through a chain of
  // shorter edges that no supporting line lies along, the chain is a corner
  // the patches rounded off or a hull edge cut across (the sweep's windows
  // keep away from corners, where two faces meet), and the two edges are
  // extended to meet when their corner lies within corner_max_fill_m of the
  // outline. Roofs in plan have right-angled corners far more often than cut
  // ones; a cut corner long enough to carry a line stays.
  bool square_corners = true;
  double corner_min_side_m = 1.5;
  double corner_max_fill_m = 1.5;
  // Without footprints: two buildings whose outlines overlap by more than
  // this in plan (m²; 0: any overlap stays) are one roof over the other.
  // Terraced houses whose heights differ by more than max_step_m are
  // buildings of their own, and the convex hull of one house's patches
  // reached over its neighbour wherever one of its lines did (the eaves of
  // two houses 1.2 m apart in height as one 3D line): over the 30 eval runs
  // from matched lines, 264 pairs of buildings overlapped by 2168 m², 72 m²
  // a block. The building whose faces' patches cover less of the overlap
  // (the images saw the other there) is built again over its outline less
  // the other's, dropping the faces that no longer have support; it goes
  // whole when less than min_footprint_m2 is left. The parts of one
  // building (join_parts_per_group) overlap near their valley by design
  // and are left alone.
  double max_building_overlap_m2 = 1.0;
  // ... when the other's faces were seen over at least this share of the
  // overlap more than its own. Where both were seen there alike (their
  // patches overlap: a face carried past a party wall over a roof at
  // another height, two faces of one roof split into two buildings) the
  // outlines say nothing of which roof is there, and the overlap stays: on
  // the 30 eval runs such near-ties took 79 of 169 decisions, and in the
  // nine that could be judged against the reference the smaller building
  // (the first rule tried) was the right one to keep six times.
  double overlap_min_seen_margin = 0.25;
  // ... and what is left of its outline narrower than this is taken off
  // with the overlap (the other's outline runs along its edge within
  // centimetres, and a sliver 3 cm wide ran on 2.7 m past a house).
  double overlap_min_width_m = 0.3;
  // Vertices closer than this are welded so that neighbouring faces share
  // them exactly.
  double weld_m = 1e-3;
};

// What became of each input plane and each building hypothesis.
struct AssemblyResult {
  CityModel model;  // local frame, crs empty
  // One line per plane or building hypothesis that did not become (part
  // of) a building, with the reason ("plane 7: 1.2 m above ground < 2.5 m").
  std::vector<std::string> rejected;
  // Per input plane: the id of the building it roofs, empty if none; and
  // when its building hypothesis failed as a whole, that reason (a plane
  // dropped on its own has its reason in `rejected`).
  std::vector<std::string> plane_building, plane_reason;
  // Per footprint id without an LoD2 building: why, and the index of its
  // line in `rejected` ("footprint ID: why", or "footprint ID (building B):
  // why" for a building dropped after the assembly, which sets it too).
  // Steps that act on such footprints (the LoD1 fallback, which may give
  // one a flat block after all) read it here. The indices hold only while
  // `rejected` is appended to, never reordered or erased from.
  struct FootprintRejection {
    std::string why;
    size_t line = 0;
  };
  std::map<std::string, FootprintRejection> footprint_rejection;
  int planes_in = 0, planes_used = 0, hypotheses = 0;
  int party_cuts = 0;  // hypotheses cut in two at a party line
};

// Turns roof planes into closed LoD2 buildings: planes are grouped by
// adjacency; each group's outline is the convex hull of its patches; the
// roof is the lower envelope of the group's planes over the outline (exact
// for the convex roof shapes: flat, shed, gable, hip, half-hip, pyramid,
// mansard — concave roofs with valleys are not represented, a known
// limitation). A plane whose face the images did not see is dropped and
// the envelope recomputed, unsupported faces before hidden ones; a
// hypothesis that falls apart when a plane is dropped goes on as one per
// connected piece. Walls run from every outline edge down to the ground
// (GroundModel at the outline, the lowest value for the whole building so
// the ground surface is planar); the solid is closed and outward oriented
// by construction and checked with CheckBuildingSolid. Roof type from the
// face count and orientations. Per-building quality in double_attributes:
// roof_planes, supporting_lines, photometric_score (mean verification score
// of its faces), reliability, footprint_m2 and, when the lines carry one,
// reprojection_rms_px (RMS over the lines of its faces, a line shared by two
// faces counted twice). Deterministic.
//
// With footprints (local frame) planes are cut at them and only planes over
// the same footprint form a building, which carries the footprint's id
// (string attribute footprint_id) and says what its walls stand on
// (attribute outline: "footprint", "roof planes cut at the footprint");
// several solids over one footprint are the parts of its one building
// (join_parts_per_footprint); every footprint ends as a building or a
// reason in `rejected`.
AssemblyResult AssembleBuildings(const std::vector<RoofPlaneHypothesis>& planes,
                                 const GroundModel& ground, const AssemblyOptions& options = {},
                                 const std::vector<Footprint>& footprints = {});

// The options AssembleBuildings applies: with footprints,
// footprint_min_height_m and footprint_min_line_length_m replace
// min_height_m and min_line_length_m.
AssemblyOptions AssemblyOptionsFor(const AssemblyOptions& options, bool with_footprints);

// Why plane p cannot be a roof whatever the other planes are (options as
// AssemblyOptionsFor gives them): a degenerate plane or patch, steeper than
// max_roof_slope_deg, no ground height at its patch centre or less than
// min_height_m above it there, or a longest line too short even for a
// plane meeting a roof. Empty when none holds. AssembleBuildings refuses
// such planes first; the sweep drops them before its conflicts, so that a
// plane the assembly refuses anyway cannot push out one it would keep.
std::string RoofRefusal(const RoofPlaneHypothesis& p, const GroundModel& ground,
                        const AssemblyOptions& options);

// Removes from `planes` those with a RoofRefusal, keeping the order of the
// others; returns "id: refusal" for each. Where (*spare_short)[i] is set,
// planes[i]'s short lines do not refuse it: a plane that can still merge
// with a coplanar neighbour brings its lines to that face, and only the
// merged plane's longest line counts.
std::vector<std::string> DropRefusedRoofs(std::vector<RoofPlaneHypothesis>* planes,
                                          const GroundModel& ground, const AssemblyOptions& options,
                                          const std::vector<char>* spare_short = nullptr);

// With footprints: removes from `planes` those the assembly would drop as
// lying mostly outside every footprint (footprint_min_inside,
// footprint_min_piece_m2), keeping the order of the others; returns "id:
// reason" for each. Like DropRefusedRoofs, for before the conflicts.
std::vector<std::string> DropOutsideFootprints(std::vector<RoofPlaneHypothesis>* planes,
                                               const std::vector<Footprint>& footprints,
                                               const AssemblyOptions& options);

}  // namespace roofsweep
