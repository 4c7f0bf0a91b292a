#include "plugin/cli/eval_lib.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <opencv2/imgproc.hpp>
#include <optional>

#include "algorithms/core/error.h"
#include "algorithms/eval/eval_report.h"
#include "algorithms/eval/overlay.h"
#include "algorithms/eval/seen_planes.h"
#include "algorithms/geometry/slope.h"
#include "algorithms/simulate/scene_truth.h"
#include "io/citymodel/citymodel_io.h"
#include "io/citymodel/ogr_citymodel.h"
#include "io/citymodel/output_file.h"
#include "io/citymodel/plane_layer_reader.h"
#include "io/citymodel/segments_json.h"
#include "io/citymodel/visibility_json.h"
#include "io/core/block_manifest.h"
#include "io/core/crs_identity.h"
#include "io/core/image_io.h"

namespace fs = std::filesystem;

namespace roofsweep {
namespace {

void CheckSameCrs(const std::string& a, const std::string& what_a, const std::string& b,
                  const std::string& what_b) {
  if (!a.empty() && !b.empty() && !SameHorizontalCrs(a, b)) {
    throw Error(what_a + " is in " + a + " but " + what_b + " is in " + b +
                "; convert one of them first");
  }
}

}  // namespace

EvalReport RunEval(const EvalRequest& r) {
  std::string truth_path = r.truth, edges_path, visibility_path;
  EvalOptions options = r.options;
  std::optional<BlockManifest> manifest;
  if (fs::is_directory(r.truth)) {
    truth_path = (fs::path(r.truth) / "groundtruth.gml").string();
    if (!fs::exists(truth_path)) {
      throw Error(r.truth + ": no groundtruth.gml (not a folder written by roofsweep simulate)");
    }
    const fs::path edges = fs::path(r.truth) / "groundtruth_edges.json";
    if (fs::exists(edges)) edges_path = edges.string();
    const fs::path visibility = fs::path(r.truth) / "groundtruth_visibility.json";
    if (fs::exists(visibility)) visibility_path = visibility.string();
    // Lines on the simulated terrain (its height or its DTM) lie on a true
    // surface.
    const fs::path block_json = fs::path(r.truth) / "block.json";
    if (fs::exists(block_json)) manifest = ReadManifest(block_json.string());
    const fs::path meta = fs::path(r.truth) / "simulation.json";
    if (options.gsd_m <= 0 && fs::exists(meta)) {
      std::ifstream f(meta);
      const auto j = nlohmann::json::parse(f, nullptr, false);
      if (j.is_object() && j.contains("gsd_m")) options.gsd_m = j["gsd_m"].get<double>();
    }
  }
  if (!r.png.empty()) CheckOutputPath(r.png, r.overwrite);
  FeatureLayerOptions vertex_layer;
  vertex_layer.overwrite = r.overwrite;
  vertex_layer.description =
      "roofsweep eval: vertices of the matched result roof planes against the reference outlines";
  if (!r.vertices.empty()) {
    CheckFeatureLayerOutput(r.vertices, vertex_layer);
    options.keep_vertices = true;
  }

  CityModel result = ReadCityModel(r.result);
  CityModel truth = ReadCityModel(truth_path);
  // One building per building, its parts together, for every figure below
  // (Evaluate would merge them itself; the plane losses index its buildings).
  MergeBuildingParts(&result);
  MergeBuildingParts(&truth);
  // LoD1 blocks are scored apart: they are not LoD2 models.
  CityModel blocks = TakeLod1Buildings(&result);
  CheckSameCrs(result.crs, r.result, truth.crs, truth_path);
  if (truth.buildings.empty()) throw Error(truth_path + ": the ground truth has no buildings");

  const auto bounds = truth.Bounds();
  const Eigen::Vector3d origin(std::floor(bounds(0)), std::floor(bounds(1)), 0.0);
  // Coordinates of projected CRSs are large (5e6 m): the evaluator's plan
  // geometry works on coordinates relative to a common origin.
  const auto shift = [&](const Eigen::Vector3d& v) { return Eigen::Vector3d(v - origin); };
  result.TransformVertices(shift);
  blocks.TransformVertices(shift);
  truth.TransformVertices(shift);

  std::vector<Segment3> lines, extra, clutter;
  if (!r.lines.empty()) {
    const SegmentSet set = ReadSegments(r.lines);
    CheckSameCrs(set.crs, r.lines, truth.crs, truth_path);
    for (const auto& s : set.segments)
      lines.push_back({s.segment.a - origin, s.segment.b - origin});
  }
  if (manifest && !r.lines.empty() && !options.lines.ground.Known()) {
    // Over the model and the lines, sampled in CRS coordinates; the grid
    // then moves to the evaluator's origin like them.
    Eigen::Vector4d box(bounds(0), bounds(1), bounds(3), bounds(4));
    for (const Segment3& l : lines)
      for (const Eigen::Vector3d& p : {l.a, l.b}) {
        box.head<2>() = box.head<2>().cwiseMin(p.head<2>() + origin.head<2>());
        box.tail<2>() = box.tail<2>().cwiseMax(p.head<2>() + origin.head<2>());
      }
    options.lines.ground = ManifestGroundInCrs(*manifest, box + Eigen::Vector4d(-5, -5, 5, 5));
    if (options.lines.ground.grid) {
      options.lines.ground.grid->x0 -= origin.x();
      options.lines.ground.grid->y0 -= origin.y();
    }
  }
  if (!edges_path.empty()) {
    // Wall edges, ground markings and the props' edges are true scene
    // edges too: a 3D line on them is correct, though it completes no roof
    // edge. The roof edges come from the model itself.
    for (const auto& s : ReadSegmentsJson(edges_path).segments) {
      const auto kind = sim::EdgeKindFromName(s.kind);
      if (kind && sim::IsRoofEdge(*kind)) continue;
      (kind == sim::EdgeKind::kProp ? clutter : extra)
          .push_back({s.segment.a - origin, s.segment.b - origin});
    }
  }

  EvalReport report;
  report.result = Evaluate(result, truth, options, r.lines.empty() ? nullptr : &lines,
                           extra.empty() ? nullptr : &extra, clutter.empty() ? nullptr : &clutter);
  report.table = FormatTable(report.result);
  report.json = ToJson(report.result);
  std::optional<SeenPlaneScores> seen;
  if (!visibility_path.empty()) {
    std::vector<SeenPolygon> polygons;
    for (RoofVisibilityFile::Polygon& p : ReadRoofVisibilityJson(visibility_path).polygons)
      polygons.push_back({p.centroid - origin, std::move(p.seen)});
    seen = ScoreSeenPlanes(truth, report.result, polygons);
    const SeenPlaneOptions so;
    char buf[256];
    std::snprintf(
        buf, sizeof buf,
        "\nRoof planes the images show (%d+ views see half of each)\n"
        "  completeness                       %5.1f %%  %d of %d reference\n"
        "  seen by fewer views                   %4d  planes, %d of them matched%s\n",
        so.min_views, 100 * seen->Completeness(), seen->seen_true_positive, seen->seen,
        seen->unseen, seen->unseen_true_positive,
        seen->unknown ? (", " + std::to_string(seen->unknown) + " not in the file").c_str() : "");
    report.table += buf;
    report.json["roof_planes_seen"] = {{"min_views", so.min_views},
                                       {"min_fraction", so.min_fraction},
                                       {"reference", seen->seen},
                                       {"true_positive", seen->seen_true_positive},
                                       {"completeness", seen->Completeness()},
                                       {"unseen", seen->unseen},
                                       {"unseen_true_positive", seen->unseen_true_positive},
                                       {"unknown", seen->unknown}};
  }
  if (!blocks.buildings.empty()) {
    const Lod1Scores lod1 = EvaluateLod1(blocks, truth, report.result, options);
    report.table += FormatLod1Table(lod1);
    report.json["lod1"] = Lod1ToJson(lod1);
  }
  if (!r.planes.empty()) {
    PlaneHypothesisSet hyps = ReadPlaneHypotheses(r.planes);
    CheckSameCrs(hyps.crs, r.planes, truth.crs, truth_path);
    for (PlaneHypothesisRecord& h : hyps.planes)
      for (Eigen::Vector3d& v : h.patch) v = shift(v);
    const PlaneLosses losses = ClassifyMissedPlanes(truth, report.result, hyps.planes);
    report.table += "\n" + FormatPlaneLosses(losses);
    nlohmann::json& j = report.json["missed_roof_planes"];
    j = nlohmann::json::object();
    for (const auto& [stage, n] : losses.count)
      j[stage] = {{"count", n}, {"area_m2", losses.area_m2.at(stage)}};
    // Per plane, so that a person can find each loss on the overlay: the
    // counts alone do not tell a hip end from a dormer.
    nlohmann::json& list = report.json["missed_roof_plane_list"];
    list = nlohmann::json::array();
    for (size_t i = 0; i < losses.stage.size(); ++i) {
      if (losses.stage[i].empty()) continue;
      const PlaneRecord& p = report.result.reference_planes[i];
      const Building& b = truth.buildings[p.building];
      const double slope = SlopeDeg(p.normal);
      list.push_back({{"reference_plane", i},
                      {"building_id", p.building_id},
                      {"roof_type", RoofTypeName(b.roof_type)},
                      {"plan_area_m2", p.plan_area},
                      {"slope_deg", slope},
                      {"kind", UnmatchedKindKey(p.unmatched)},
                      {"stage", losses.stage[i]}});
      if (seen && seen->views[i] >= 0) list.back()["views_seen"] = seen->views[i];
    }
  }
  // Per false result plane, so that a person can find each on the overlay
  // (its building id): which kind of error is behind the correctness.
  nlohmann::json& false_list = report.json["false_roof_plane_list"];
  false_list = nlohmann::json::array();
  for (size_t i = 0; i < report.result.result_planes.size(); ++i) {
    const PlaneRecord& p = report.result.result_planes[i];
    if (p.true_positive) continue;
    false_list.push_back({{"result_plane", i},
                          {"building_id", p.building_id},
                          {"plan_area_m2", p.plan_area},
                          {"slope_deg", SlopeDeg(p.normal)},
                          {"kind", UnmatchedKindKey(p.unmatched)},
                          {"counterpart_overlap_fraction", p.overlap_fraction},
                          {"angle_deg", p.angle_deg}});
  }
  report.json["inputs"] = {{"result", r.result}, {"truth", truth_path}};
  if (!r.vertices.empty()) {
    std::vector<LayerFeature> features;
    for (const VertexRecord& v : report.result.vertices) {
      LayerFeature f;
      f.point = v.position + origin;
      const PlaneRecord& res = report.result.result_planes[v.result_plane];
      const PlaneRecord& ref = report.result.reference_planes[v.reference_plane];
      f.strings["building_id"] = res.building_id;
      f.strings["reference_building_id"] = ref.building_id;
      f.integers["result_plane"] = v.result_plane;
      f.integers["reference_plane"] = v.reference_plane;
      f.reals["distance_m"] = v.distance_m;
      if (options.gsd_m > 0) f.reals["distance_gsd"] = v.distance_m / options.gsd_m;
      f.strings["place"] = VertexPlaceName(v.place);
      features.push_back(std::move(f));
    }
    vertex_layer.crs = truth.crs;
    WriteFeatureLayer(r.vertices, "vertices", LayerGeometry::kPointZ, features, vertex_layer);
  }
  if (!r.png.empty()) {
    cv::Mat bgr = RenderOverlay(result, truth, report.result, {}, &blocks), rgb;
    cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
    WriteImage(r.png, rgb);
  }
  return report;
}

}  // namespace roofsweep
