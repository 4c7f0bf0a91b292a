#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "algorithms/buildings/city_model.h"
#include "algorithms/eval/line_eval.h"
#include "algorithms/eval/plan_view.h"
#include "algorithms/geometry/segment3.h"

// Compares a reconstructed city model with a reference (ground truth) the
// way the ISPRS urban classification and 3D building reconstruction benchmark
// does (Rottensteiner et al. 2014; Rutzinger et al. 2009), on polygons
// instead of a label image. Both models must be in the same frame, metres.
//
// Rules, exactly:
// * A roof plane is a set of roof polygons of one building that are coplanar
//   and touch in plan view (RoofPlaneOptions). Roof polygons steeper than
//   vertical_roof_deg are not planes (no plan area); they are counted.
// * Overlap is the plan-view (xy) area of the intersection of two planes'
//   projections. Unlike ISPRS' label image, a plane hidden under another one
//   (overhang) counts with its full area.
// * A reference plane is a true positive (TP_ref) when ONE result plane
//   overlaps at least plane_overlap_fraction of the REFERENCE plane's area and
//   their upward normals differ by at most max_normal_angle_deg. A result
//   plane is TP_rec symmetrically (fraction of the RESULT plane's area).
//   completeness = TP_ref / N_ref, correctness = TP_rec / N_rec,
//   quality = TP_ref / (TP_ref + FN + FP) with FN = N_ref - TP_ref and
//   FP = N_rec - TP_rec (equals 1 / (1/compl + 1/corr - 1) when TP_ref = TP_rec).
//   Also over the planes of at least large_plane_m2 alone (ISPRS Cm,10 and
//   Cr,10), matched as before against all planes of the other model.
// * Segmentation (topological clarification): a result and a reference plane
//   are linked when their overlap is at least segmentation_overlap_fraction
//   of the SMALLER plane's area (no normal test). n_1_to_m: reference planes
//   linked to more than one result plane (over-segmentation); n_n_to_1:
//   result planes linked to more than one reference plane
//   (under-segmentation); n_n_to_m: linked clusters with several of both.
// * Each plane's counterpart is, among the planes that make it TP, the one
//   of largest intersection-over-union (so a nested plane of the other model
//   does not take the place of the true twin).
// * A plane without a counterpart is told by what covers it (UnmatchedKind):
//   not covered, covered at another slope, or covered only by several
//   (at its slope or not).
// * Geometry over matched pairs (each TP reference plane with its
//   counterpart): normal angle
//   median/RMS; vertex RMS = RMS of the plan distances from each vertex of
//   the result plane's outline to the nearest edge of the reference plane's
//   outline, distances above vertex_max_distance_m left out as outliers
//   (counted); in GSD units when gsd_m > 0.
// * RMSZ: both models' roofs rasterised on a grid (rmsz_grid_m), highest roof
//   per cell; RMS of z_result - z_reference over cells both cover.
// * Buildings: footprints (GroundSurface union, else roof projection); TP by
//   the same one-counterpart rule with building_overlap_fraction, no normal
//   test. Roof-type agreement: fraction of TP reference buildings with a known
//   (non-zero) roof_type whose counterpart (largest IoU) has the same SIG3D
//   code.
// * Ratios with a zero denominator are undefined: empty optionals here, null
//   in JSON, "n/a" in the table; the counts beside them say why.

namespace roofsweep {

// Where a vertex of a matched result plane lies against its reference
// plane: on its outline (within 2 GSD, or vertex_on_outline_m without a
// GSD), inside it (the face was cut short), or past it over another
// reference roof (a missed neighbour's place, or a terraced neighbour) or
// over no roof at all (past an eave).
enum class VertexPlace { kOnOutline = 0, kInside, kOverAnotherRoof, kOverNoRoof };
constexpr int kVertexPlaces = 4;
const char* VertexPlaceName(VertexPlace place);

struct EvalOptions {
  eval::RoofPlaneOptions planes;               // what a roof plane is
  double plane_overlap_fraction = 0.5;         // ISPRS: at least 50 % of the plane's own area
  double max_normal_angle_deg = 10.0;          // normals must agree this well to match
  double segmentation_overlap_fraction = 0.5;  // of the smaller plane, for N:M links
  double vertex_max_distance_m = 3.0;          // outlier cut for the vertex RMS
  double gsd_m = 0;                            // > 0: also report vertex RMS in GSD
  double vertex_on_outline_m = 0.10;           // VertexPlace::kOnOutline without a GSD
  bool keep_vertices = false;                  // fill EvalResult::vertices
  double rmsz_grid_m = 0.25;                   // RMSZ sampling grid
  double building_overlap_fraction = 0.5;      // footprints, of the building's own area
  double building_top_tolerance_m = 2.0;       // BuildingScores::top_off
  // Completeness and correctness are also given over the planes of at
  // least this plan area (ISPRS benchmark: Cm,10 and Cr,10 over planes
  // larger than 10 m², Rottensteiner et al. 2014); matching still uses all.
  double large_plane_m2 = 10.0;
  eval::LineEvalOptions lines;  // 3D line tolerances (10 cm, 10°)
};

// Why a plane has no counterpart (is not a true positive), from its
// overlaps with the other model's planes:
// * kUncovered: they cover less than plane_overlap_fraction of it. A false
//   result plane off the reference roofs (a tree crown, the ground, a face
//   run on past an eave or over a yard); a missed reference plane that no
//   result roof covers.
// * kOtherSlope: one of them covers that much, but at a normal angle above
//   max_normal_angle_deg (a wrong sweep angle, a flat roof as a shed).
// * kSeveralAtItsSlope: together they cover that much, none alone does,
//   and those at its slope (within max_normal_angle_deg) do too. A result
//   plane across the coplanar roofs of a terraced row, which are the planes
//   of separate reference buildings and which no image parts (footprints
//   do); a reference plane held by fragments.
// * kSeveral: together they cover that much, none alone does, and not at
//   its slope. A result plane across several faces (two faces as one, a
//   face run on over a neighbour's); a reference plane under the pieces of
//   planes at other slopes.
enum class UnmatchedKind { kUncovered = 0, kOtherSlope, kSeveralAtItsSlope, kSeveral };
constexpr int kUnmatchedKinds = 4;
// `result_plane` picks the wording for a false result plane or a missed
// reference plane.
const char* UnmatchedKindName(UnmatchedKind kind, bool result_plane);
// The kind as a JSON key: uncovered, other_slope, several_at_its_slope, several.
const char* UnmatchedKindKey(UnmatchedKind kind);

struct PlaneRecord {
  int building = -1;  // index into the model's buildings
  std::string building_id;
  double plan_area = 0;  // m²
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  bool true_positive = false;
  int counterpart = -1;         // in the other model, largest IoU (-1: none)
  double overlap_fraction = 0;  // of this plane's area, with that counterpart
  double angle_deg = 0;         // with that counterpart
  UnmatchedKind unmatched = UnmatchedKind::kUncovered;  // when not a true positive
};

// Planes without a counterpart by UnmatchedKind: how many, their plan area.
struct UnmatchedPlanes {
  std::array<int, kUnmatchedKinds> count{};
  std::array<double, kUnmatchedKinds> area_m2{};
};

struct RoofPlaneScores {
  int n_reference = 0, n_result = 0;
  int tp_reference = 0, tp_result = 0;
  std::optional<double> completeness, correctness, quality;
  int n_1_to_m = 0, n_n_to_1 = 0, n_n_to_m = 0;
  // The same over reference (completeness) and result (correctness)
  // planes of at least EvalOptions::large_plane_m2.
  int n_reference_large = 0, n_result_large = 0;
  int tp_reference_large = 0, tp_result_large = 0;
  std::optional<double> completeness_large, correctness_large;
  // Why the result planes are false and the reference planes missed.
  UnmatchedPlanes false_result, missed_reference;
};

struct GeometryScores {
  int matched_pairs = 0;
  std::optional<double> angle_median_deg, angle_rms_deg, angle_max_deg;
  int vertices = 0;         // result outline vertices used
  int vertex_outliers = 0;  // left out: farther than vertex_max_distance_m
  std::optional<double> vertex_rms_m, vertex_rms_gsd;
  // The RMS is ruled by a few vertices metres off, and the cut-off decides
  // which of them count; the median and the share within 2 GSD (over all
  // vertices, outliers included) show how the rest lie.
  std::optional<double> vertex_median_m, vertex_within_2gsd;
  // Per VertexPlace, over the same vertices as the median: how many, and
  // their share of the sum of squared distances within
  // vertex_max_distance_m (what makes the RMS).
  std::array<int, kVertexPlaces> vertex_place_count{};
  std::array<double, kVertexPlaces> vertex_place_sum2{};
  long long rmsz_cells = 0;  // grid cells both models cover
  long long rmsz_cells_result_only = 0, rmsz_cells_reference_only = 0;
  std::optional<double> rmsz_m, dz_mean_m;
};

struct BuildingScores {
  int n_reference = 0, n_result = 0;
  int tp_reference = 0, tp_result = 0;
  std::optional<double> completeness, correctness, quality;
  int roof_type_compared = 0, roof_type_same = 0;
  std::optional<double> roof_type_agreement;
  // The compared buildings by (reference, result) SIG3D code: where the
  // roof types go wrong.
  std::map<std::pair<int, int>, int> roof_type_pairs;
  // The buildings are matched in plan only: a garage roofed metres too high
  // (the tree crown over it) counts as found. Of the matched pairs, how
  // many have both roof tops, how many of those lie more than
  // EvalOptions::building_top_tolerance_m apart, and the RMS of the
  // differences.
  int top_compared = 0, top_off = 0;
  std::optional<double> top_rms_m;
};

struct Lines3dScores {
  bool evaluated = false;  // false when no lines were given
  eval::LineScores raw;
  std::optional<double> precision, completeness, roof_edge_completeness;
  // Share of the result length on a true surface but no edge (see
  // LineScores::result_on_surface_m), and off every surface.
  std::optional<double> on_surface, off_surface;
  // Share on the edges of clutter (part of the precision; see
  // LineScores::result_on_clutter_m), when clutter edges were given.
  std::optional<double> on_clutter;
};

// Roof polygons each model had to leave out (see RoofPlaneSet).
struct InputCounts {
  int roof_polygons = 0, vertical = 0, degenerate = 0, invalid = 0, downward = 0;
};

// One vertex of a matched result plane's outline (EvalOptions::keep_vertices).
struct VertexRecord {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // on the result plane
  int result_plane = -1, reference_plane = -1;         // in EvalResult's plane lists
  double distance_m = 0;  // plan distance to the reference plane's outline
  VertexPlace place = VertexPlace::kOnOutline;
};

struct EvalResult {
  RoofPlaneScores roof_planes;
  GeometryScores geometry;
  BuildingScores buildings;
  Lines3dScores lines3d;
  InputCounts result_input, reference_input;
  std::vector<PlaneRecord> result_planes,
      reference_planes;  // per plane, in ExtractRoofPlanes order
  std::vector<int> result_building_matched, reference_building_matched;  // 1: TP
  std::vector<VertexRecord> vertices;  // with EvalOptions::keep_vertices
  EvalOptions options;                 // as used
};

// `lines`: reconstructed 3D segments (optional). `extra_reference_segments`:
// reference segments besides the roof edges, e.g. ground markings (optional).
// `clutter_segments`: true edges of objects outside the model, which the
// lines' precision counts and their completeness does not (optional; see
// eval::EvaluateLines).
// A building made of parts counts as one building, its parts' surfaces
// together (MergeBuildingParts): the reference models buildings so, and a
// footprint's building is one cadastral object however many solids it has.
// Throws roofsweep::Error for options out of range.
EvalResult Evaluate(const CityModel& result, const CityModel& truth, const EvalOptions& options,
                    const std::vector<Segment3>* lines = nullptr,
                    const std::vector<Segment3>* extra_reference_segments = nullptr,
                    const std::vector<Segment3>* clutter_segments = nullptr);

}  // namespace roofsweep
