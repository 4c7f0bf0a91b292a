#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "algorithms/buildings/assemble_buildings.h"
#include "algorithms/buildings/fall_line_pieces.h"
#include "algorithms/buildings/footprint_growth.h"
#include "algorithms/buildings/footprint_roofs.h"
#include "algorithms/buildings/lod1_block.h"
#include "algorithms/buildings/mirror_completion.h"
#include "algorithms/core/progress.h"
#include "algorithms/edges/edge_options.h"
#include "algorithms/eval/image_overlay.h"
#include "algorithms/matching/match_options.h"
#include "algorithms/sweep/colour_breaks.h"
#include "algorithms/sweep/coplanar_lines.h"
#include "algorithms/sweep/eave_planes.h"
#include "algorithms/sweep/eave_search.h"
#include "algorithms/sweep/footprint_roof_search.h"
#include "algorithms/sweep/level_lines.h"
#include "algorithms/sweep/lift_lines.h"
#include "algorithms/sweep/merge_coplanar_neighbours.h"
#include "algorithms/sweep/plane_grouping.h"
#include "algorithms/sweep/sweep_options.h"
#include "algorithms/sweep/verify_planes.h"

namespace roofsweep {

struct RunRequest {
  std::string block;   // anything OpenBlockManifest accepts
  std::string output;  // LoD2 model (.gml, .city.json, .gpkg, ...); for `sweep` the half-planes
  std::string format;  // empty: from the extension
  bool overwrite = false;
  bool stop_after_sweep = false;  // `roofsweep sweep`: write the half-planes, no buildings
  // A tile (block CRS: min x, min y, max x, max y) in place of the
  // manifest's aoi. With a tile from either, only the views that see it and
  // `tile_buffer_m` around it are read, each in the window that does, and
  // only the buildings whose ground centre lies in the tile are written, ids
  // prefixed with the tile's tag (tile_lib.h).
  std::optional<Eigen::Vector4d> aoi;
  double tile_buffer_m = 30.0;
  // Optional 3D lines to start from instead of matching (an OGR line layer
  // such as `match` writes, or a segments JSON; block CRS): lines from
  // another tool, or the simulator's true edges to judge the later stages.
  std::string lines_in;
  std::string lines3d;      // optional: also write the 3D lines (OGR layer lines3d)
  std::string half_planes;  // optional: also write the half-planes (OGR layer half_planes)
  // Optional: every roof plane hypothesis that reached the verification,
  // with its patch and what became of it (OGR layer roof_planes).
  std::string planes;
  std::string report;      // optional: JSON with the stage table and every rejection
  std::string target_crs;  // optional: reproject the LoD2 output (PROJ), -t_srs
  // Optional building footprints (any OGR polygon layer); empty: the
  // block's, if it names any. They restrict and label the buildings.
  std::string footprints;
  std::string footprints_layer;
  std::string footprints_id_field;
  EdgeOptions edges;
  MatchOptions match;
  SweepOptions sweep;
  GroupingOptions grouping;
  // Planes also from pairs of coplanar lines (§7 of Baillard & Zisserman);
  // false: the sweep's planes only. Either way every coplanar line joins
  // its plane (§4).
  bool line_planes = true;
  CoplanarOptions coplanar;
  VerifyOptions verify;
  // The verification's score threshold (VerifyOptions::min_score) follows
  // the block's imagery as the sweep's candidate threshold does
  // (SweepOptions::calibration_peak_ratio): scaled by the square root of
  // that threshold's scale, since Sim is a mean of squared correlations.
  // Haze, blur, noise and low contrast lower the correlation of true faces:
  // the median score of the planes built on `hard` is 0.48, on `realistic`
  // 0.77-0.82, and over the 30 eval runs 41 reference planes with
  // footprints were lost to that threshold alone, 33 of them on `hard`.
  bool verify_follows_sweep = true;
  AssemblyOptions assembly;
  // With footprints: a footprint no plane covers gets a flat roof at the
  // height the views agree on best, if the verification confirms it.
  bool footprint_flat_roofs = true;
  // ... or the best of the shed and gable models (RoofsOverBareFootprints)
  // where it fits the images better than the flat roof by
  // roof_model_min_gain.
  bool roof_models_over_footprints = true;
  // ... and over the part of a footprint beyond the one sloped face found over
  // it (BareFootprintRoofOptions::beyond_ridges).
  bool roofs_beyond_ridges = true;
  RoofModelOptions roof_models;
  double roof_model_min_gain = BareFootprintRoofOptions{}.min_gain;
  // The height margin the verification asks of those faces, in place of
  // VerifyOptions::min_margin (0.1): the footprint says a building stands
  // there, so the question is only its height, and the height search has
  // put the model at the best one. Small flat roofs (garages) correlate
  // nearly as well 0.5 m up or down: on `realistic` s1 three were refused
  // at margins of 0.07-0.08. Over 30 paired runs with footprints (session
  // 45) building quality rose by 2.0 +- 0.6 points (14 up, 0 down) and
  // plane quality by 0.8 +- 0.4 (15 / 2).
  double roof_model_min_margin = 0.05;
  // A model's faces refused by the score, height or slope test are
  // accepted with the faces of it that passed when the model pooled passes
  // (JudgeModelsWhole).
  bool roof_models_whole = true;
  // With footprints: a sloped face seen over part of its footprint grows
  // along its contour lines by the strips of the footprint beyond its patch
  // that the verification confirms (ExtensionsAlongFootprints).
  bool footprint_growth = true;
  FootprintGrowthOptions growth;
  // With footprints: the piece of a plane over each footprint it spans is
  // verified apart and cut away where the images refute it
  // (PiecesOverFootprints, CutRefutedPieces).
  bool footprint_pieces = true;
  // Without footprints: the pieces of a sloped face between its lines down
  // the fall line are verified apart and cut away where the images refute
  // them, before the conflicts (PiecesAcrossFallLines,
  // CutRefutedFallLinePieces). Which lines cut is the assembly's party-wall
  // rule (AssemblyOptions::party_*), so the two share one setting.
  bool fall_line_pieces = true;
  // Two planes a few degrees apart that meet without a step are merged
  // where the verification confirms the merged plane
  // (NearCoplanarMerges).
  bool merge_coplanar = true;
  NearCoplanarMergeOptions merge;
  // Completion by symmetry (MirroredFaces): a pitched face with a ridge
  // line proposes the face beyond the ridge, verified like any plane.
  bool mirror_faces = true;
  MirrorCompletionOptions mirror;
  // Completion by symmetry along the ridge (MirroredHipEnds): a hip end
  // proposes the one at the other end of its ridge, verified like any
  // plane (height test included: no line fixes its height).
  bool hip_ends = true;
  HipEndMirrorOptions hip_end;
  // With footprints, completion by the footprint's symmetry
  // (FacesMirroredAcrossFootprints): a face over a rectangular footprint
  // proposes its mirror image across the footprint's axis, verified like
  // any plane.
  bool footprint_mirror = true;
  FootprintMirrorOptions footprint_mirror_options;
  // The height margin the verification asks of those faces, in place of
  // VerifyOptions::min_margin (0.1): the face's height comes from the face
  // it mirrors, which passed the test, so the images need only not prefer
  // the face moved up or down. A mansard's steep lower face, foreshortened
  // in near-nadir views, scores nearly as well 0.5 m up (`realistic-7` s2
  // BLDG_0007: 0.65 against 0.63, 0.67 against 0.64), and the face mirrored
  // about a ridge skips the test altogether (MirrorCompletionOptions::
  // height_from_ridge).
  double footprint_mirror_min_margin = 0.0;
  // A second pass: image segments no 3D line explains are lifted onto the
  // planes the first pass kept (LiftSegmentsOntoPlanes), and the sweep,
  // grouping and verification run again over all lines.
  bool lift_lines = true;
  LiftOptions lift;
  // In the second pass, the segments that neither matching nor the lifts
  // placed and that every view sees along its epipolar lines are placed
  // by the sweep of their faces over height and angle (SweepLevelLines).
  bool level_lines = true;
  LevelLineOptions level;
  // A sloped face whose patch stops short of its eave grows to the eave
  // that image segments lifted onto its plane show (FindEaves).
  bool eave_search = true;
  bool border_clip = true;  // ClipFacesAtBorderLines, CutFacesAtHipFeet
  EaveSearchOptions eaves;
  // Without footprints: terraced houses are cut apart where their shared
  // roof changes colour across its whole depth (FindColourBreaks), as
  // where a 3D line runs down a party wall (AssemblyOptions::
  // split_at_party_lines, which must be on too).
  bool colour_breaks = true;
  ColourBreakOptions colour_break;
  // Every building gets edge_support: the share of its visible roof-edge
  // length over all views that lies on an image edge (BuildingEdgeSupport,
  // as `overlay` measures it). Buildings below min_edge_support are dropped
  // with a reason; 0 drops none.
  ImageEdgeOptions image_edges;
  double min_edge_support = 0;
  // ... and those below min_edge_support_unlined whose roof no 3D line
  // supports: a roof model fitted over a bare footprint (garages, sheds)
  // where the views agree best. Over a shed hidden under a tree crown they
  // agree best on the crown, metres too high, and the crown shows no edges
  // along the footprint's outline at that height. With footprints, over 7
  // `realistic` blocks (seed 1, matching seed 1) the 15 such buildings
  // below 0.45 all lay 3.1-9.8 m off their reference roof, those above 0.8
  // within 1.1 m; 0.5: half of the outline, seen as edges.
  double min_edge_support_unlined = 0.5;
  // Flat planes that only continue sloped faces' eaves outwards are
  // dropped (FlatPlanesBeyondEaves): the yard in the inner corner of an L.
  bool drop_eave_planes = true;
  EavePlaneOptions eave_planes;
  // With footprints: a footprint that ends without an LoD2 building gets an
  // LoD1 block (Lod1Block, Building::lod 1) at the height of the 3D lines
  // over it (Lod1HeightFromLines), where they give one; its reason stays in
  // `rejected`, marked "a flat block instead (LoD1)".
  bool lod1_fallback = true;
  Lod1Options lod1;
};

struct RunStage {
  std::string name;
  std::string result;  // "412 3D lines"
  double seconds = 0;
};

struct RunSummary {
  std::vector<RunStage> stages;
  int lines = 0, sides = 0, accepted = 0, planes = 0, buildings = 0;
  int solids = 0;          // buildings without parts and parts: what the hypotheses became
  int lod1_buildings = 0;  // of `buildings`, LoD1 blocks (RunRequest::lod1_fallback)
  // Every plane or building hypothesis that did not become (part of) a
  // building, with the reason.
  std::vector<std::string> rejected;
  std::vector<std::string> messages;  // warnings of the stages
};

// `roofsweep run` / `roofsweep sweep`: the whole pipeline on a block —
// images, colour segments, 3D lines (Scholze et al. 2000), half-plane sweep
// (Baillard & Zisserman 2000 §3), grouping into planes (§4), conflict
// management, LoD2 buildings with walls to the ground — written in the
// block's CRS. Checks that the outputs may be written before the work
// starts; every output is written atomically.
RunSummary RunPipeline(const RunRequest& request, Progress& progress);

// The stage table and the rejection counts by reason.
std::string FormatRunSummary(const RunSummary& summary);

}  // namespace roofsweep
