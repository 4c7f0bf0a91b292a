#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "algorithms/buildings/assemble_buildings.h"
#include "algorithms/sweep/sweep_half_planes.h"

namespace roofsweep {

// Options of the grouping of half-planes into planes (Baillard & Zisserman
// 2000, §4). Lengths in metres.
struct GroupingOptions {
  // A half-plane joins a plane when its normal is within max_angle_deg of
  // the plane's, both end points of its line lie within max_distance_m of
  // the plane, and its patch comes within max_gap_m of the plane's patch in
  // plan view (coplanar faces of different buildings stay apart).
  // max_distance_m is about 2.5 times the height error of a matched line at
  // 5 cm GSD and base-to-height 0.3. At 0.25 m, roofs 0.15-0.25 m apart
  // (neighbours in a row, a renewed roof beside an old one) joined, and the
  // refit tilted the plane between them: from matched lines over 30 runs
  // (session 25), 0.15 m raised plane quality by 0.56 +- 0.20 and building
  // quality by 0.82 +- 0.26 points; 0.10 m gained less.
  double max_angle_deg = 5.0;
  double max_distance_m = 0.15;
  double max_gap_m = 1.0;
  // A half-plane's patch is the strip from its line to the sweep's reach
  // (HalfPlane::extent_m), at least min_extent_m wide.
  double min_extent_m = 1.0;
  // Conflict management (§5, ResolveConflicts): two planes whose plan-view
  // patches overlap by more than max_overlap of the smaller patch cannot
  // both be roof (coplanar ones were merged by the grouping); the one with
  // the lower score is dropped.
  double max_overlap = 0.5;
  // Unless they are two faces that meet: each patch on its own side of
  // the line where the planes intersect (at most conflict_meet_max_across
  // of either across), an overlap of at most conflict_meet_max_overlap, and
  // a supporting line of each plane, virtual_min_length_m or longer, along
  // that line (within conflict_meet_line_offset_m in plan view). That is
  // a gable whose two patches both run past the ridge; a small plane
  // inside the spill of a larger one overlaps it almost wholly and stays
  // its rival. conflict_meet_max_across = 0 turns this off.
  double conflict_meet_max_across = 0.45;
  double conflict_meet_max_overlap = 0.7;
  double conflict_meet_line_offset_m = 0.5;
  // A weaker plane that meets a stronger one in a convex crease (each
  // plane above the other beyond the line where they intersect: a hip, a
  // ridge, a mansard's break) is cut back to its side of that line rather
  // than dropped, when the line parts their supporting lines (none of
  // either more than conflict_meet_line_offset_m across it), parts their
  // patches and they overlap as above, and the weaker plane stands as a face
  // (conflict_cut_min_lines lines, one at least conflict_replace_min_line_m
  // long). The steep south face of a mansard (`realistic` s1), its patch
  // run over the faces of the top by half, lost to them, and the corners
  // of the side faces lay 1.6 m off where it was missing. Parting the
  // patches alone, without the lines, let false steep planes in beside
  // flat roofs (session 21).
  bool conflict_cut_at_crease = true;
  int conflict_cut_min_lines = 2;
  // A kept plane gives way to rejected planes that overlap it when they
  // conflict with no other kept plane nor with each other, each has a
  // verified similarity higher by conflict_replace_min_gain (a clear
  // preference, as VerifyOptions::min_margin; nearly coplanar pieces of one
  // terraced row's face are not), and together they hold more evidence
  // (score): one plane carried over the faces of two terraced houses whose
  // ridges differ by a metre beats each face by its area alone. Each of
  // them must have min_lines lines, one at least conflict_replace_min_line_m
  // long: faces that stand on their own, not fragments of one (as
  // AssemblyOptions::min_line_length_m).
  bool conflict_replace_by_several = true;
  // Then the conflicts are settled again without the replaced plane, the
  // faces that replaced it decided first: the planes it had pushed out may
  // come in where they clash with no kept plane (on `realistic-7` s1 a
  // mansard's top face had lost to a 7 deg plane of one line across the
  // top, which its two faces then replaced).
  bool conflict_redecide = true;
  double conflict_replace_min_gain = 0.1;
  // ... or, instead of the gain, one of its supporting lines runs inside
  // the kept plane's patch at least conflict_replace_min_step_m above or
  // below the kept plane: that plane cannot be the roof there. 0 turns
  // this off.
  double conflict_replace_min_step_m = 0.4;
  double conflict_replace_min_line_m = 3.0;
  // Where such faces hold too little evidence to replace the kept plane
  // whole, they still replace it across their width: a kept plane whose
  // patch they cross along its fall line, or along the steepest face's
  // when it is flat (at least conflict_cut_min_slope_deg; their hull at
  // least conflict_cut_min_span of the patch's depth there), is
  // cut at their hull's sides, the pieces beside it kept where at least
  // conflict_cut_min_width_m wide, and the conflicts are settled again.
  // One shed-roof plane carried across a terraced row over a gabled house
  // between two shed roofs (`realistic-17` s1: 183 m2 at 13 deg over the
  // gable's 43 deg faces, whose ridge runs 3.9 m above it) outweighed the
  // gable's two faces by its area. The faces must fit the images at least
  // as well as the kept plane, turn from it by conflict_cut_min_slope_deg
  // at least, together span conflict_cut_min_width_m across it and cover
  // conflict_cut_min_cover of the part cut away (a wrong 7 m2 sliver of a
  // gable over a flat roof beside it cut 34 m2 out of that roof). With a
  // line off the plane the cut needs no more evidence; with better fits
  // alone their scores must exceed the kept plane's similarity times the
  // area cut away. A cut whose faces do not all stay is undone.
  bool conflict_cut_across_fall = true;
  double conflict_cut_min_slope_deg = 10.0;
  double conflict_cut_min_span = 0.6;
  double conflict_cut_min_width_m = 3.0;
  double conflict_cut_min_cover = 0.5;
  // A derived plane (a completion's proposal) yields in conflicts to every
  // found plane, however small: a 63 m² face of a roof model beyond a ridge
  // lost to a 4 m² plane that the assembly later dropped (its longest line
  // 1.4 m), a 103 m² shed roof over a footprint to a 22 m² fragment. Where
  // every kept plane a rejected derived one conflicts with is found and
  // smaller than this fraction of its area, the derived plane takes their
  // place (as two found planes would settle it, by area x score). Over 30
  // paired runs (10 blocks x matching seeds 1-3): plane quality with
  // footprints +0.82 +- 0.23 (14 runs up, 2 down), correctness +0.67 +-
  // 0.21, building quality +1.63 +- 0.58 (12 / 0); from matched lines +0.22
  // +- 0.15 (4 / 2). 0 turns it off.
  double derived_displaces_fraction = 0.25;
  // ... and it also takes the place of smaller found planes that are
  // coplanar with it (normals within max_angle_deg, and within
  // max_distance_m of it at their patch's centre): §5's rule for coplanar
  // conflicts is to merge, and such a plane is a fragment of the derived
  // face (a gable face found only along part of its ridge, against its
  // mirror image of the opposite face, whole). Unless one of its lines
  // runs more than derived_absorbs_max_line_depth_m inside the derived
  // patch: there it bounds something (a mirrored face carried past the
  // verges of a neighbour's roof, its source plane's overshoot).
  bool derived_absorbs_coplanar = true;
  double derived_absorbs_max_line_depth_m = 1.0;
  // §5: "at least two lines (one of them can be virtual) are required to
  // accept a plane", an efficient culling of erroneous one-line half-planes
  // (tree crowns, shadows). Applied by DropWeaklySupported after the
  // coplanar lines have joined.
  int min_lines = 2;
  // The virtual line: where a plane meets another plane's patch along its
  // own border, their intersection counts as one line of it (a gable face
  // whose eave and verges were not matched still borders the other face at
  // the ridge). It must run at least virtual_min_length_m within both
  // patches grown by max_gap_m, with the two patches on opposite sides of it
  // (no more than virtual_max_across of either patch's area across), and
  // the planes must differ by at least virtual_min_angle_deg. A hip cuts a
  // corner off a face's rectangular patch, a quarter of it across: at 0.2
  // hip ends went as orphans (`realistic-7` BLDG_0022 on every seed); at
  // 0.3, over 30 paired runs plane quality +0.17 +- 0.09 from matched lines
  // and +0.12 +- 0.12 with footprints, vertex RMS -0.04 and -0.12 GSD
  // (sweep README, session 76). At 0.45 a wall's plane under a garden
  // shed's face got one too and pushed out the shed's other face.
  bool virtual_lines = true;
  double virtual_min_length_m = 2.0;
  double virtual_max_across = 0.3;
  double virtual_min_angle_deg = 10.0;
};

// A plane with the half-planes and lines that support it.
struct PlaneGroup {
  Eigen::Vector4d plane = Eigen::Vector4d::Zero();  // n . X + d = 0, unit n, n_z >= 0
  std::vector<int> half_planes;                     // indices into the sweep's result
  std::vector<int> lines;                           // distinct input lines
  double longest_line_m = 0;
  std::vector<Eigen::Vector2d> patch;  // plan view, convex, counter-clockwise
  double score = 0;                    // sum of patch area x similarity
  double similarity = 0;               // mean Sim of the half-planes
};

struct GroupingResult {
  std::vector<PlaneGroup> planes;
};

// Groups the candidate half-planes, accepted ones first, then by
// reliability (Sim x curvature),
// into planes: a half-plane joins the first compatible plane (see
// GroupingOptions), whose parameters are then refitted by orthogonal
// regression over its lines' end points and the far edges of their
// strips; otherwise it starts a new plane. Deterministic.
GroupingResult GroupHalfPlanes(const std::vector<SweepLine>& lines,
                               const std::vector<HalfPlane>& half_planes,
                               const GroupingOptions& options = {});

// Conflict management: strongest first (RoofPlaneHypothesis::score, e.g.
// patch area x verified photometric score; planes accepted on their lines
// after those the images confirmed, derived planes after all found ones),
// a plane whose patch overlaps a kept one's by more than max_overlap
// is dropped, unless the two meet along a line that parts their patches
// (conflict_meet_max_across); then a dropped derived plane takes the place
// of the small found planes that kept it out (derived_displaces_fraction),
// or of the smaller ones coplanar with it (derived_absorbs_coplanar);
// then a kept plane that several of the dropped ones explain better
// together is replaced by them
// (conflict_replace_by_several; better: a clearly higher similarity, or a
// line of theirs the kept plane passes far above or below), or cut across
// its fall line where they cross it (conflict_cut_across_fall), and the
// conflicts settled again. Returns the reasons, those of the cuts first.
std::vector<std::string> ResolveConflicts(std::vector<RoofPlaneHypothesis>* planes,
                                          const GroupingOptions& options);

// True when p and q meet along a virtual line (see GroupingOptions).
bool VirtualLine(const PlaneGroup& p, const PlaneGroup& q, const GroupingOptions& options);

// Removes the planes with fewer than min_lines distinct lines, a virtual
// line with another of the planes counting as one (see GroupingOptions);
// returns one reason per removed plane.
std::vector<std::string> DropWeaklySupported(std::vector<PlaneGroup>* planes,
                                             const GroupingOptions& options);

// §4-§5 "updates propagated to neighbours and virtual lines": after the
// verification and the conflicts, a plane kept for a virtual line (fewer
// than min_lines real lines) whose partner has since been rejected is
// removed, until no such plane is left; returns one reason per removed
// plane. Planes with min_lines real lines are never touched.
std::vector<std::string> DropOrphanedPlanes(std::vector<RoofPlaneHypothesis>* planes,
                                            const GroupingOptions& options);

// §5 for the verified planes: the orphans (DropOrphanedPlanes) among all
// of them first, then the conflicts (ResolveConflicts), then the planes the
// conflicts left orphaned. A plane without a partner among all the
// verified planes has none among the fewer the conflicts leave, so it goes
// whatever the conflicts decide; dropped first, it cannot push out a plane
// that would have stayed. Returns the reasons, in that order.
std::vector<std::string> SettleVerifiedPlanes(std::vector<RoofPlaneHypothesis>* planes,
                                              const GroupingOptions& options);

// The groups as the building assembly takes them; with `lines` (the
// grouping's input) each carries the plan view of its lines.
std::vector<RoofPlaneHypothesis> ToRoofPlanes(const std::vector<PlaneGroup>& groups,
                                              const std::vector<SweepLine>* lines = nullptr);

// Plan-view patch of one half-plane: the strip from the line to its reach.
std::vector<Eigen::Vector2d> HalfPlanePatch(const SweepLine& line, const HalfPlane& half_plane,
                                            double min_extent_m);

}  // namespace roofsweep
