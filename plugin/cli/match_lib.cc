#include "plugin/cli/match_lib.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "algorithms/core/error.h"
#include "algorithms/core/format.h"
#include "algorithms/eval/line_eval.h"
#include "algorithms/geometry/view.h"
#include "algorithms/simulate/scene_truth.h"
#include "io/citymodel/ogr_citymodel.h"
#include "io/citymodel/segments_json.h"
#include "io/core/block_manifest.h"
#include "io/core/crs_transform.h"
#include "io/core/local_frame.h"
#include "io/orientation/block_source.h"
#include "io/orientation/vgg_annotations.h"
#include "plugin/cli/tile_lib.h"

namespace roofsweep {
namespace {

double Since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::string Hex(const Eigen::Vector3f& c) {
  char buf[8];
  auto b = [](float v) { return static_cast<int>(std::lround(std::clamp(v, 0.f, 1.f) * 255)); };
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", b(c.x()), b(c.y()), b(c.z()));
  return buf;
}

bool IsRoofKind(const std::string& k) {
  const auto kind = sim::EdgeKindFromName(k);
  return kind && sim::IsRoofEdge(*kind);
}

// The matches against a VGG set's annotation, its views found by name.
eval::MatchScores ScoreAgainstVgg(const orientation::VggLineAnnotations& a, const Block& block,
                                  const LocalFrame& frame, const MatchResult& result,
                                  const std::string& folder) {
  eval::LineTracks t;
  const int nv = static_cast<int>(block.views.size());
  std::vector<int> column(nv, -1);
  for (int v = 0; v < nv; ++v) {
    const auto it = std::find(a.views.begin(), a.views.end(), block.views[v].name);
    if (it == a.views.end())
      throw Error(folder + ": no annotated lines for view " + block.views[v].name);
    column[v] = static_cast<int>(it - a.views.begin());
    t.lines.push_back(a.lines[column[v]]);
  }
  for (const auto& row : a.rows) {
    std::vector<int> mine(nv);
    for (int v = 0; v < nv; ++v) mine[v] = row[column[v]];
    t.rows.push_back(std::move(mine));
  }
  t.lines3d = a.lines3d;
  t.project = [&block, &frame](int v, const Eigen::Vector3d& crs) {
    const View& view = block.views[v];
    return Project(block.CameraOf(view), view.pose, frame.ToLocal(crs));
  };
  std::vector<std::vector<std::pair<int, int>>> observations;
  std::vector<Segment3> lines;
  for (const Line3D& l : result.lines) {
    observations.push_back(l.observations);
    lines.push_back({frame.ToCrs(l.segment.a), frame.ToCrs(l.segment.b)});
  }
  return eval::EvaluateMatches(result.segments, observations, lines, t);
}

// Names of TruthEdgeReach::stage.
const char* ReachStageName(int stage) {
  static const char* const kNames[] = {"none",        "eligible", "geometric",   "chromatic",
                                       "correlation", "verified", "unambiguous", "one-to-one"};
  return stage >= 0 && stage < 8 ? kNames[stage] : "?";
}

// Why matching could or could not reach an edge, as the summary counts it.
enum class Reach { kWithin, kFewerViews, kAlongEpipolar, kOther };

Reach ReachOf(const TruthEdgeReach& r) {
  if (r.stage >= 1) return Reach::kWithin;
  if (r.views < 2) return Reach::kFewerViews;
  if (r.view_pairs > 0 && r.along_epipolar == r.view_pairs) return Reach::kAlongEpipolar;
  return Reach::kOther;
}

const char* ReachName(Reach r) {
  static const char* const kNames[] = {"within reach", "in fewer than two views",
                                       "along the epipolar lines", "other"};
  return kNames[static_cast<int>(r)];
}

}  // namespace

eval::SurfaceAgreement LinesOnSurfaceModel(const Block& block, const std::vector<Line3D>& lines) {
  std::vector<Segment3> segments;
  std::vector<int> views;
  for (const Line3D& l : lines) {
    segments.push_back(l.segment);
    views.push_back(l.Views());
  }
  return eval::LinesOnSurface(segments, views, *block.surface);
}

std::string FormatSurfaceAgreement(const eval::SurfaceAgreement& a) {
  const eval::SurfaceAgreementOptions o;
  std::string out = StrFormat("3D lines on the surface model (within %.0f m):", o.tolerance_m);
  const char* kinds[2] = {"two views", "three or more"};
  for (int k = 0; k < 2; ++k) {
    if (k > 0) out += ";";
    out += a.length_m[k] > 0
               ? StrFormat(" %s %.1f%% of %.0f m (%d lines)", kinds[k],
                           100 * a.agreeing_m[k] / a.length_m[k], a.length_m[k], a.lines[k])
               : StrFormat(" %s none", kinds[k]);
  }
  return out;
}

MatchSummary RunMatch(const MatchRequest& r, Progress& progress) {
  MatchSummary out;
  if (r.output.empty()) throw Error("match: no output file given (-o)");
  FeatureLayerOptions lo;
  lo.driver = r.format;
  lo.overwrite = r.overwrite;
  lo.dataset_options = r.dataset_options;
  lo.layer_options = r.layer_options;
  // Refuse an existing output, an unknown format or bad creation options
  // before the work, not after it.
  CheckFeatureLayerOutput(r.output, lo);
  FeatureLayerOptions truth_lo;
  truth_lo.overwrite = r.overwrite;
  if (!r.truth_edges_output.empty()) {
    if (r.truth.empty() || std::filesystem::is_directory(r.truth))
      throw Error("-truth_edges needs -truth with the groundtruth_edges.json of a simulated block");
    if (r.truth_edges_output == r.output)
      throw Error("-truth_edges must name another file than -o: " + r.output);
    CheckFeatureLayerOutput(r.truth_edges_output, truth_lo);
  }
  auto t0 = std::chrono::steady_clock::now();
  BlockManifest manifest = OpenBlockManifest(r.block);
  if (r.aoi) manifest.aoi = r.aoi;
  Block block = ManifestToBlock(manifest);
  const LocalFrame frame = ManifestLocalFrame(manifest);
  if (!r.assign_crs.empty() && !r.target_crs.empty())
    throw Error("-a_srs and -t_srs exclude each other: -a_srs assigns a CRS without transforming");
  std::optional<CrsTransform> reproject;
  if (!r.target_crs.empty()) {
    if (manifest.crs.empty()) throw Error(r.block + ": the block has no CRS to reproject from");
    CrsTransformOptions o;
    const FrameInfo info = frame.Info();
    o.area_of_interest = Eigen::Vector4d(info.origin_lon - 0.1, info.origin_lat - 0.1,
                                         info.origin_lon + 0.1, info.origin_lat + 0.1);
    reproject.emplace(manifest.crs, r.target_crs, o);
  }
  auto output_xyz = [&](const Eigen::Vector3d& local) {
    const Eigen::Vector3d crs = frame.ToCrs(local);
    return reproject ? reproject->Forward(crs) : crs;
  };
  std::optional<TileCut> tile;
  if (block.aoi) {
    // The truth covers the whole block; scored against a tile's lines it
    // would count everything outside the tile as missed.
    if (!r.truth.empty())
      throw Error("-truth scores a whole block: give no -aoi, and a block without an aoi");
    if (!(r.tile_buffer_m >= 0)) throw Error("match: the tile buffer must be 0 m or more");
    tile = CutBlockToTile(&block, r.tile_buffer_m, r.block);
  }
  const std::vector<cv::Mat> images = ReadBlockImages(block, tile ? &*tile : nullptr, r.block);
  out.read_s = Since(t0);

  std::vector<Segment3> truth_local;
  SegmentSet truth;
  std::optional<orientation::VggLineAnnotations> vgg;
  if (!r.truth.empty() && std::filesystem::is_directory(r.truth)) {
    vgg = orientation::ReadVggLineAnnotations(r.truth);
  } else if (!r.truth.empty()) {
    truth = ReadSegmentsJson(r.truth);
    for (const LabelledSegment& s : truth.segments)
      truth_local.push_back({frame.ToLocal(s.segment.a), frame.ToLocal(s.segment.b)});
  }
  SubProgress sub(progress, 0.0, 0.95);
  out.result = MatchLines(block, images, r.match, r.edges, sub,
                          r.truth.empty() || vgg ? nullptr : &truth_local);
  if (tile) out.result.messages.insert(out.result.messages.begin(), tile->message);
  if (vgg) out.annotated = ScoreAgainstVgg(*vgg, block, frame, out.result, r.truth);
  if (block.surface) out.surface = LinesOnSurfaceModel(block, out.result.lines);

  if (!r.truth.empty() && !vgg) {
    std::vector<Segment3> lines, roof, extra, clutter;
    for (const Line3D& l : out.result.lines) lines.push_back(l.segment);
    // The true edge behind each entry of roof, extra and clutter.
    std::vector<size_t> roof_of, extra_of, clutter_of;
    for (size_t k = 0; k < truth.segments.size(); ++k) {
      if (IsRoofKind(truth.segments[k].kind)) {
        roof_of.push_back(k);
        roof.push_back(truth_local[k]);
      } else if (truth.segments[k].kind == sim::EdgeKindName(sim::EdgeKind::kProp)) {
        clutter_of.push_back(k);
        clutter.push_back(truth_local[k]);
      } else {
        extra_of.push_back(k);
        extra.push_back(truth_local[k]);
      }
    }
    const eval::LineScores s =
        eval::EvaluateLines(lines, roof, extra, eval::LineEvalOptions{}, nullptr, &clutter);
    if (!r.truth_edges_output.empty()) {
      // Props are no reference (they count in precision only): their
      // coverage is measured apart.
      const eval::LineScores c = eval::EvaluateLines(lines, {}, clutter, eval::LineEvalOptions{});
      std::vector<double> covered(truth.segments.size(), 0.0);
      for (size_t j = 0; j < roof_of.size(); ++j)
        covered[roof_of[j]] = s.reference_covered_each_m[j];
      for (size_t j = 0; j < extra_of.size(); ++j)
        covered[extra_of[j]] = s.reference_covered_each_m[roof.size() + j];
      for (size_t j = 0; j < clutter_of.size(); ++j)
        covered[clutter_of[j]] = c.reference_covered_each_m[j];
      const std::vector<TruthEdgeReach>& reach = out.result.truth_edges;
      for (size_t k = 0; k < truth.segments.size() && k < reach.size(); ++k) {
        const LabelledSegment& t = truth.segments[k];
        LayerFeature f;
        f.lines.push_back({output_xyz(truth_local[k].a), output_xyz(truth_local[k].b)});
        f.strings["kind"] = t.kind;
        f.integers["building"] = t.building;
        f.reals["length_m"] = truth_local[k].Length();
        f.reals["covered_m"] = covered[k];
        f.integers["views"] = reach[k].views;
        f.integers["view_pairs"] = reach[k].view_pairs;
        f.integers["pairs_along_epipolar"] = reach[k].along_epipolar;
        f.integers["stage"] = reach[k].stage;
        f.strings["stage_name"] = ReachStageName(reach[k].stage);
        f.strings["reach"] = ReachName(ReachOf(reach[k]));
        out.truth_edge_features.push_back(std::move(f));
      }
    }
    if (s.result_length_m > 0) out.precision = s.result_on_reference_m / s.result_length_m;
    if (s.reference_length_m > 0) out.completeness = s.reference_covered_m / s.reference_length_m;
    if (s.roof_edge_length_m > 0)
      out.roof_edge_completeness = s.roof_edge_covered_m / s.roof_edge_length_m;
    const std::vector<TruthEdgeReach>& reach = out.result.truth_edges;
    for (size_t k = 0; k < truth.segments.size() && k < reach.size(); ++k) {
      if (!IsRoofKind(truth.segments[k].kind)) continue;
      const double len = truth_local[k].Length();
      out.roof_edge_m += len;
      switch (ReachOf(reach[k])) {
        case Reach::kWithin:
          out.roof_reachable_m += len;
          break;
        case Reach::kFewerViews:
          out.roof_one_view_m += len;
          break;
        case Reach::kAlongEpipolar:
          out.roof_along_epipolar_m += len;
          break;
        case Reach::kOther:
          break;
      }
    }
  }

  t0 = std::chrono::steady_clock::now();
  std::vector<LayerFeature> features;
  const bool windowed = tile && tile->Windowed();
  for (const Line3D& l : out.result.lines)
    features.push_back(
        Line3DFeature(l, block, output_xyz(l.segment.a), output_xyz(l.segment.b), !windowed));
  lo.crs = !r.target_crs.empty()   ? r.target_crs
           : !r.assign_crs.empty() ? r.assign_crs
                                   : manifest.crs;
  WriteFeatureLayer(r.output, "lines3d", LayerGeometry::kLineStringZ, features, lo);
  if (!r.truth_edges_output.empty()) {
    truth_lo.crs = lo.crs;
    WriteFeatureLayer(r.truth_edges_output, "truth_edges", LayerGeometry::kLineStringZ,
                      out.truth_edge_features, truth_lo);
  }
  out.write_s = Since(t0);
  progress.Update(1.0, "done");
  return out;
}

LayerFeature Line3DFeature(const Line3D& l, const Block& block, const Eigen::Vector3d& a,
                           const Eigen::Vector3d& b, bool whole_images) {
  LayerFeature f;
  f.lines.push_back({a, b});
  f.integers["views"] = l.Views();
  f.reals["rms_px"] = l.rms_px;
  f.reals["length_m"] = l.segment.Length();
  f.strings["depth_from"] = DepthFrom(l);
  f.strings["colour_left"] = Hex(l.colour_left);
  f.strings["colour_right"] = Hex(l.colour_right);
  std::vector<std::pair<std::string, int>> observations;
  for (const auto& [v, s] : l.observations)
    observations.emplace_back(block.views[v].name, whole_images ? s : -1);
  f.strings["observations"] = FormatObservations(observations);
  return f;
}

std::string FormatMatchSummary(const MatchSummary& s) {
  std::ostringstream o;
  for (const std::string& m : s.result.messages) o << m << "\n";
  o << FormatFunnel(s.result.funnel);
  const MatchTimings& t = s.result.timings;
  char buf[400];
  std::snprintf(buf, sizeof buf,
                "Time (s): read %.2f, edges %.2f, flanking regions %.2f, candidates+chromatic+"
                "correlation %.2f, verification %.2f, assignment %.2f, 3D %.2f, write %.2f\n",
                s.read_s, t.edges_s, t.features_s, t.candidates_s, t.verify_s, t.assign_s,
                t.triangulate_s, s.write_s);
  o << buf;
  if (s.precision || s.completeness) {
    auto pct = [](const std::optional<double>& v) { return v ? 100.0 * *v : -1.0; };
    std::snprintf(buf, sizeof buf,
                  "Against the truth (10 cm, 10 deg, length-based): precision %.1f%%, "
                  "completeness %.1f%%, roof-edge completeness %.1f%%\n",
                  pct(s.precision), pct(s.completeness), pct(s.roof_edge_completeness));
    o << buf;
  }
  if (s.surface) o << FormatSurfaceAgreement(*s.surface) << "\n";
  if (s.roof_edge_m > 0) {
    const double other = std::max(
        0.0, s.roof_edge_m - s.roof_reachable_m - s.roof_along_epipolar_m - s.roof_one_view_m);
    std::snprintf(buf, sizeof buf,
                  "Roof edges within reach of a true pair: %.1f%% of %.0f m; out of reach: %.1f%% "
                  "along the epipolar lines of every pair that sees them, %.1f%% detected in fewer "
                  "than two views, %.1f%% other\n",
                  100 * s.roof_reachable_m / s.roof_edge_m, s.roof_edge_m,
                  100 * s.roof_along_epipolar_m / s.roof_edge_m,
                  100 * s.roof_one_view_m / s.roof_edge_m, 100 * other / s.roof_edge_m);
    o << buf;
  }
  if (s.annotated) {
    const eval::MatchScores& m = *s.annotated;
    auto pct = [](double a, double b) { return b > 0 ? 100.0 * a / b : 0.0; };
    std::snprintf(buf, sizeof buf,
                  "Against the annotated correspondences (2 px, 5 deg):\n"
                  "  match precision %.1f%% (%lld of %lld judged pairs, %lld of them between two "
                  "annotated rows that coincide in both views; lines: %d of %d)\n"
                  "  recall %.1f%% of annotated pairs (%lld of %lld), %.1f%% of annotated lines "
                  "(%d of %d)\n",
                  pct(m.pairs_correct, m.pairs_evaluable), m.pairs_correct, m.pairs_evaluable,
                  m.pairs_collinear_rows, m.lines_correct, m.lines_evaluable,
                  pct(m.annotated_pairs_found, m.annotated_pairs), m.annotated_pairs_found,
                  m.annotated_pairs, pct(m.annotated_lines_found, m.annotated_lines),
                  m.annotated_lines_found, m.annotated_lines);
    o << buf;
    if (m.lines_3d > 0) {
      std::snprintf(buf, sizeof buf,
                    "  3D: median distance to the annotated 3D line %.3g (%.2f%% of the scene "
                    "size %.3g), %d lines\n",
                    m.median_distance_3d, pct(m.median_distance_3d, m.scene_size), m.scene_size,
                    m.lines_3d);
      o << buf;
    }
  }
  return o.str();
}

}  // namespace roofsweep
