#pragma once

#include <optional>
#include <string>
#include <vector>

#include "algorithms/core/progress.h"
#include "algorithms/edges/edge_options.h"
#include "algorithms/eval/line_surface.h"
#include "algorithms/eval/match_eval.h"
#include "algorithms/matching/match_lines.h"
#include "algorithms/matching/match_options.h"
#include "io/citymodel/ogr_citymodel.h"

namespace roofsweep {

struct MatchRequest {
  std::string block;   // anything OpenBlockManifest accepts
  std::string output;  // lines3d layer file (.gpkg, .fgb, ...)
  std::string format;  // GDAL driver; empty: from the extension
  bool overwrite = false;
  std::vector<std::string> dataset_options, layer_options;  // -dsco, -lco NAME=VALUE
  std::string assign_crs;  // -a_srs: CRS written without transforming (block CRS otherwise)
  std::string target_crs;  // -t_srs: reproject the lines from the block CRS (excludes -a_srs)
  // Optional ground truth: groundtruth_edges.json of `roofsweep simulate`
  // (adds the true-pair counts to the funnel and scores the lines), or the
  // folder of an Oxford VGG set (scores the matches against its annotated
  // line correspondences, nview-lines, and the 3D lines against l3d).
  std::string truth;
  // With a simulator's truth: every true edge written to this file as a
  // LineStringZ layer "truth_edges" with how far matching got on it
  // (TruthEdgeReach, the reach category of the summary, the length the 3D
  // lines cover within 10 cm and 10 deg); empty: none.
  std::string truth_edges_output;
  // One tile of the block in the block CRS (min x, min y, max x, max y),
  // replacing the manifest's aoi; as for `run`, only the views and image
  // windows that see it and tile_buffer_m around it are read, so that a
  // city block's manifest never loads every image.
  std::optional<Eigen::Vector4d> aoi;
  double tile_buffer_m = 30;
  MatchOptions match;
  EdgeOptions edges;
};

struct MatchSummary {
  MatchResult result;
  double read_s = 0, write_s = 0;
  // With truth: length-based scores within 10 cm / 10 degrees.
  std::optional<double> precision, completeness, roof_edge_completeness;
  // Roof-edge length by how far matching could reach it (metres): a true
  // pair of segments was a candidate (the ceiling of roof-edge
  // completeness), only along the epipolar lines of every pair that holds
  // it, held by segments of fewer than two views, or none of these
  // (fragments too short to overlap, or cut by the scene's height range).
  double roof_edge_m = 0, roof_reachable_m = 0, roof_along_epipolar_m = 0, roof_one_view_m = 0;
  // With a VGG set as truth.
  std::optional<eval::MatchScores> annotated;
  // When the block has a surface model (ground/dsm): the 3D lines against it.
  std::optional<eval::SurfaceAgreement> surface;
  // With truth_edges_output: one feature per true edge.
  std::vector<LayerFeature> truth_edge_features;
};

// `roofsweep match`: reads the block and its images, extracts segments,
// matches them and writes the 3D lines as a LineStringZ layer "lines3d" in
// the block's CRS (fields: views, rms_px, length_m, colour_left,
// colour_right). An empty result is written as an empty layer. With a tile
// (aoi), the lines of the tile and its buffer; their observations name
// the views but no segment (-1), since the segments are those of the
// windows, not of the whole images. With
// target_crs the lines are reprojected from the block CRS (checked before
// any matching work); assign_crs only relabels them.
MatchSummary RunMatch(const MatchRequest& request, Progress& progress);

std::string FormatMatchSummary(const MatchSummary& summary);

// The lines against the block's surface model (block.surface must be set),
// and that figure as one line (without its newline) of the summaries of
// `match` and `run`.
eval::SurfaceAgreement LinesOnSurfaceModel(const Block& block, const std::vector<Line3D>& lines);
std::string FormatSurfaceAgreement(const eval::SurfaceAgreement& agreement);

// One feature of the lines3d layer, as `match` and `run -lines3d` write it:
// the line from a to b (output coordinates) with views, rms_px, length_m,
// depth_from, the two sides' colours and the observations by image name,
// which `run -lines` reads back to restrict each line's reference views.
// Without whole_images (the segments were those of a tile's windows) the
// observations name no segment (id -1).
LayerFeature Line3DFeature(const Line3D& line, const Block& block, const Eigen::Vector3d& a,
                           const Eigen::Vector3d& b, bool whole_images);

}  // namespace roofsweep
