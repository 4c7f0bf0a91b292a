#pragma once

#include <string>
#include <vector>

#include "algorithms/buildings/assemble_buildings.h"
#include "algorithms/edges/segment2d.h"
#include "algorithms/geometry/block.h"

namespace roofsweep {

// Options of FindEaves. Lengths in metres, in plan, unless named _px.
struct EaveSearchOptions {
  // The faces searched: sloped ones (a flat roof has no fall line).
  double min_slope_deg = 10.0;
  // The eave is looked for across this range down the fall line, from the
  // lowest point of the face's lines (a verge's or a hip's lower end, where
  // the eave begins): a little inside, and out to a verge that stops
  // short of the eave by an overhang's width or a detector's gap. Further
  // out, edges on the ground and the facades below come within reach of
  // the lift (a 6 m wall seen 12 degrees off nadir lies 1.3 m out).
  double search_from_m = -0.5;
  double search_to_m = 0.5;
  // The lowest point must end a line at least min_edge_m long that runs
  // down the face: within acos(min_edge_cos) of the fall line in plan (a
  // verge runs along it, a hip between equal pitches at 45 degrees).
  double min_edge_m = 1.0;
  double min_edge_cos = 0.6;
  // A face with a line at least min_length_m long whose ends both lie
  // within this distance of the lowest point of its lines, down the fall
  // line, has its eave and is not searched.
  double level_line_m = 0.3;
  // Image segments lifted onto the plane count for one eave position when
  // their lifts lie within this distance of it down the fall line (1.5 px
  // at 5 cm), and run along the face's level direction within the angle.
  double position_tolerance_m = 0.08;
  double max_angle_deg = 5.0;
  // Segments shorter than this (px) are left out: they say little of an
  // edge's direction.
  double min_segment_px = 10.0;
  // Rays meeting the plane at a grazing angle place a lift badly.
  double min_incidence = 0.25;
  // A stretch of the eave counts when this many views see a lifted
  // segment there (each view alone confirms any position of an edge along
  // its own viewing direction).
  int min_views = 2;
  // The eave found must be held over this length, and over this fraction
  // of the patch's extent along it.
  double min_length_m = 2.0;
  double min_fraction = 0.5;
  // The growth fills space no other plane claims: it may take this
  // fraction of the new area from other planes' patches (slivers along a
  // shared edge), else the patch stays as it is. A completion does not
  // overrule a plane found directly, and the growth into a neighbour's
  // patch changes how the assembly groups and roofs both (20 % let a
  // gable face join a false shed over a row on `realistic-13`).
  double max_overlap_fraction = 0.05;
  // ClipFacesAtBorderLines: how far a patch may run past the eave or verge
  // line that bounds the face's lines (the line may lie a gutter's width
  // inside the roof's edge, and its ends are placed to a few centimetres).
  double clip_beyond_m = 0.3;
  // ... and only when the face's lines span this depth down the fall line:
  // a level line alone may be the face's ridge as well as its eave.
  double clip_min_depth_m = 1.0;
  // ... and flat faces across each of their lines of min_length_m, both
  // ways: a flat roof of a terraced row ran 2.6 m over its neighbour's,
  // 0.35 m lower, past the party wall's line that bounded its lines
  // (`realistic` s1, every matching seed).
  bool clip_flat = true;
  // Flat means under this slope. A face of a few degrees has a fall line
  // and an upper edge (a ridge, a shed's top), and the rule for flat faces
  // cut across it as across any edge: with flat up to 10 degrees, a 6
  // degree shed roof on `realistic` s19 lost 16.5 m2 of its patch and its
  // match.
  double flat_max_slope_deg = 3.0;
  // ... and a flat face also where no line lies along that end but at
  // least this many of its lines of min_length_m or more, running towards
  // it, stop there (their outer ends within level_line_m of it): two eaves
  // that end together mark an edge that was not matched (B&Z §5: end
  // points bound the face). A flat garage on `realistic-11` ran 2 m past
  // its unmatched west edge on every seed; over 30 runs from matched lines
  // the vertex RMS fell by 0.20 +- 0.08 GSD (10 better, none worse). Not
  // for sloped faces, whose ridge and eave may stop together short of a
  // gable end (a verge is wanted there): cutting them too cost `hard-1`
  // vertices with footprints on every seed. 0 turns it off.
  int clip_min_line_ends = 2;
  // CutFacesAtHipFeet: a sloped face is cut down the fall line where the lowest point of its
  // lines is the foot of a hip (a line of min_edge_m or more running up
  // the face at between hip_min_cos and hip_max_cos of its fall line in
  // plan; a verge runs along it) at which another face's eave ends: a
  // level line of min_length_m at the bottom of that face's lines, one
  // end within hip_corner_m of the foot in plan and hip_corner_dz_m in
  // height, running from there back up this face (within 45 degrees of
  // it: the corner is convex). A hip ends at the corner of the eaves, so
  // this face's eave passes through its foot. The sweep's strip stands
  // square to the hip and runs past that corner over the ground: the
  // north face of `realistic-7` BLDG_0022, found from its hip alone,
  // reached 2.2 m past its eave on every matching seed. 0 turns it off.
  double hip_corner_m = 0.5;
  double hip_corner_dz_m = 0.3;
  double hip_min_cos = 0.34;
  double hip_max_cos = 0.94;
};

// An eave found for one face.
struct FaceEave {
  int plane = -1;        // index into the planes searched
  Eigen::Vector2d a, b;  // its ends in plan, held by min_views views
  // How far down the fall line it lies past the lowest point of the face's lines.
  double beyond_lines_m = 0;
  double held_m = 0;  // length held by min_views views
  int views = 0;      // views with a lifted segment on it
};

// Baillard & Zisserman (2000, §5) delineate a face by its border lines,
// and a face whose patch stops short of its eave ends as a triangle or a
// sliver: the sweep's patch is the hull of its lines, and an eave along
// the flight line is matched by no pair of views of one strip (the
// epipolar lines run along it). The plane fixes the eave's depth: the
// eave is the level line of the face at its lowest edge, so only its
// position down the fall line is unknown. Every image segment near that
// stretch of the face is lifted onto the plane through its view's ray,
// and the position where lifted segments of min_views views agree over
// the longest stretch is the eave. A view along the eave cannot check
// its depth, but the plane and the search range bound it.
//
// `segments`: per view, the image segments (texture marked; those are left
// out: tile courses run along the eave). Deterministic.
std::vector<FaceEave> FindEaves(const Block& block, const std::vector<Segments2D>& segments,
                                const std::vector<RoofPlaneHypothesis>& planes,
                                const EaveSearchOptions& options = {});

// Grows each face's patch to the hull of the patch and its eave, unless
// the grown part lies over other planes' patches (max_overlap_fraction).
// Returns how many patches grew; `log` (optional) gets one line per eave
// that changed or would have changed its patch.
int ExtendFacesToEaves(const std::vector<FaceEave>& eaves, std::vector<RoofPlaneHypothesis>* planes,
                       const EaveSearchOptions& options = {},
                       std::vector<std::string>* log = nullptr);

// Baillard & Zisserman (2000, §5) bound a face by its border lines; the
// sweep's patch is the hull of its lines and of their half-planes' strips,
// and a strip reaches as far at either end of its line. At the foot of a
// hip or past a gable's verge it then runs over the wall and the ground.
// A face ends at its eave and at its verges when it has them: where a line
// of at least min_length_m lies along the outermost points of the face's
// lines down the fall line, or along the level direction either way (both
// of its ends within level_line_m of them), the part of the patch further
// than clip_beyond_m past them is cut off; down the fall line only when
// the lines span clip_min_depth_m there. Not up the fall line: a ridge
// found with little else below it would cut its face to a sliver. A flat
// face (under flat_max_slope_deg; with clip_flat) is cut the same way across
// each of its lines of min_length_m, both ways, where its lines span
// clip_min_depth_m, and also where clip_min_line_ends of its lines end
// together. Faces between flat_max_slope_deg and min_slope_deg are
// left alone. Returns how many patches were cut; `log` (optional) gets one
// line per cut.
int ClipFacesAtBorderLines(std::vector<RoofPlaneHypothesis>* planes,
                           const EaveSearchOptions& options = {},
                           std::vector<std::string>* log = nullptr);

// A hip ends at the corner of the eaves, so a face whose lowest line is a
// hip has its eave through the hip's foot when another face's eave ends
// there (EaveSearchOptions::hip_corner_m): its patch is cut clip_beyond_m
// past that level line. Run on the planes that the assembly takes, after
// the conflicts: cut before the later conflicts (in ClipFacesAtBorderLines),
// a pavilion roof's north face on `realistic-1` won over its west face with
// footprints on every matching seed. Returns how many patches were cut;
// `log` (optional) gets one line per cut.
int CutFacesAtHipFeet(std::vector<RoofPlaneHypothesis>* planes,
                      const EaveSearchOptions& options = {},
                      std::vector<std::string>* log = nullptr);

}  // namespace roofsweep
