#include "plugin/cli/run_lib.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "algorithms/buildings/convex_polygon2.h"
#include "algorithms/buildings/footprint_completion.h"
#include "algorithms/buildings/footprint_pieces.h"
#include "algorithms/core/error.h"
#include "algorithms/core/format.h"
#include "algorithms/core/reason_kind.h"
#include "algorithms/geometry/block_overview.h"
#include "algorithms/geometry/slope.h"
#include "algorithms/matching/match_lines.h"
#include "algorithms/sweep/plane_fit.h"
#include "algorithms/sweep/sweep_half_planes.h"
#include "io/citymodel/citymodel_io.h"
#include "io/citymodel/footprint_reader.h"
#include "io/citymodel/ogr_citymodel.h"
#include "io/citymodel/output_file.h"
#include "io/citymodel/reproject.h"
#include "io/citymodel/segments_json.h"
#include "io/core/block_manifest.h"
#include "io/core/crs_identity.h"
#include "io/core/image_io.h"
#include "io/core/local_frame.h"
#include "io/orientation/block_source.h"
#include "plugin/cli/match_lib.h"
#include "plugin/cli/tile_lib.h"

namespace roofsweep {
namespace {

using Clock = std::chrono::steady_clock;

double Since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// The block's area of interest, else the bounding box of what the images
// see on the ground: footprints beyond it cannot be reconstructed and are
// not reported one by one.
std::optional<Eigen::Vector4d> BlockExtent(const Block& block) {
  if (block.aoi) return block.aoi;
  const BlockOverview overview = AnalyzeBlock(block);
  Eigen::Vector4d e(1e300, 1e300, -1e300, -1e300);
  bool any = false;
  for (const ViewFootprint& f : overview.footprints) {
    if (!f.valid) continue;
    for (const Eigen::Vector3d& p : f.outline) {
      e[0] = std::min(e[0], p.x()), e[1] = std::min(e[1], p.y());
      e[2] = std::max(e[2], p.x()), e[3] = std::max(e[3], p.y());
      any = true;
    }
  }
  return any ? std::optional<Eigen::Vector4d>(e) : std::nullopt;
}

// A roof plane hypothesis as verified, for the -planes layer.
struct PlaneTrace {
  RoofPlaneHypothesis plane;
  PlaneVerification check;
};

// Appends the planes the verification confirmed to `kept`, scored by the
// verified evidence (patch area x score); the others' reasons to `rejected`;
// with `traces`, every plane and its check.
void KeepVerified(std::vector<RoofPlaneHypothesis> planes,
                  const std::vector<PlaneVerification>& checks,
                  std::vector<RoofPlaneHypothesis>* kept, std::vector<std::string>* rejected,
                  std::vector<PlaneTrace>* traces) {
  for (size_t i = 0; i < planes.size(); ++i) {
    if (!checks[i].patch.empty()) planes[i].patch = checks[i].patch;
    if (traces) traces->push_back({planes[i], checks[i]});
    if (!checks[i].accepted) {
      rejected->push_back(planes[i].id + ": " + checks[i].reason);
      continue;
    }
    planes[i].similarity = checks[i].score;
    planes[i].score = std::abs(SignedArea(planes[i].patch)) * checks[i].score;
    planes[i].height_from_lines = !checks[i].height_confirmed;
    kept->push_back(std::move(planes[i]));
  }
}

// The -planes layer: each traced hypothesis with its patch on its plane,
// its verification figures and its fate: "built" (with the building's id),
// "rejected" (with the reason the run gives for it) or "not built" (with
// the reason its building hypothesis failed as a whole).
void WritePlaneLayer(const std::string& path, const std::vector<PlaneTrace>& traces,
                     const std::vector<RoofPlaneHypothesis>& assembled,
                     const AssemblyResult& assembly, const std::vector<std::string>& rejected,
                     const LocalFrame& frame, const std::string& crs, bool overwrite) {
  std::map<std::string, std::string> building_of, failed_with;
  std::map<std::string, int> breaks_of;
  for (const RoofPlaneHypothesis& h : assembled)
    breaks_of[h.id] = static_cast<int>(h.colour_breaks.size());
  for (size_t i = 0; i < assembled.size() && i < assembly.plane_building.size(); ++i) {
    if (!assembly.plane_building[i].empty())
      building_of[assembled[i].id] = assembly.plane_building[i];
    if (!assembly.plane_reason[i].empty()) failed_with[assembled[i].id] = assembly.plane_reason[i];
  }
  // The first reason given for each plane ("plane 7 (line 3): ...").
  std::map<std::string, std::string> reason_of;
  for (const std::string& r : rejected) {
    const size_t colon = r.find(": ");
    if (colon != std::string::npos) reason_of.emplace(r.substr(0, colon), r.substr(colon + 2));
  }
  std::vector<LayerFeature> features;
  for (const PlaneTrace& t : traces) {
    const RoofPlaneHypothesis& h = t.plane;
    if (h.patch.size() < 3 || !(std::abs(h.plane[2]) > 1e-9)) continue;
    LayerFeature f;
    Polygon3 patch;
    for (const Eigen::Vector2d& p : h.patch)
      patch.exterior.push_back(frame.ToCrs({p.x(), p.y(), PlaneZ(h.plane, p.x(), p.y())}));
    f.polygons.push_back(std::move(patch));
    f.strings["plane"] = h.id;
    const auto built = building_of.find(h.id);
    const auto why = reason_of.find(h.id);
    const auto failed = failed_with.find(h.id);
    if (!t.check.accepted) {
      f.strings["status"] = "rejected";
      f.strings["reason"] = t.check.reason;
    } else if (built != building_of.end()) {
      f.strings["status"] = "built";
      f.strings["building"] = built->second;
    } else if (why != reason_of.end()) {
      f.strings["status"] = "rejected";
      f.strings["reason"] = why->second;
    } else if (failed != failed_with.end()) {
      f.strings["status"] = "not built";
      f.strings["reason"] = failed->second;
    } else {
      // Not expected: every plane is built or has a reason.
      f.strings["status"] = "not built";
      f.strings["reason"] = "no reason recorded";
    }
    f.integers["lines"] = h.lines;
    f.integers["derived"] = h.derived;
    // Accepted on its lines where the images could not tell its height.
    f.integers["height_from_lines"] = t.check.accepted && !t.check.height_confirmed;
    f.integers["samples"] = t.check.samples;
    // Where the face changes colour across its depth (a party wall the
    // assembly may cut at); kept planes only, without footprints.
    const auto breaks = breaks_of.find(h.id);
    f.integers["colour_breaks"] = breaks != breaks_of.end() ? breaks->second : 0;
    f.reals["longest_line_m"] = h.longest_line_m;
    f.reals["slope_deg"] = SlopeDeg(h.plane.head<3>());
    f.reals["area_m2"] = std::abs(SignedArea(h.patch));
    // The evidence exists only for planes the verification could score.
    if (std::isfinite(t.check.score)) {
      f.reals["score"] = t.check.score;
      f.reals["score_below"] = t.check.score_below;
      f.reals["score_above"] = t.check.score_above;
      f.reals["below_difference"] = t.check.below_difference;
      f.reals["below_se"] = t.check.below_se;
      f.reals["above_difference"] = t.check.above_difference;
      f.reals["above_se"] = t.check.above_se;
      f.reals["tilt_difference"] = t.check.tilt_difference;
      f.reals["tilt_se"] = t.check.tilt_se;
      f.reals["offset_m"] = t.check.offset_m;
      // The horizontal plane at the ground over the same image evidence
      // (VerifyOptions::ground_alternative); absent where not tested.
      if (std::isfinite(t.check.score_ground)) f.reals["score_ground"] = t.check.score_ground;
    }
    features.push_back(std::move(f));
  }
  FeatureLayerOptions lo;
  lo.crs = crs;
  lo.overwrite = overwrite;
  lo.description =
      "roofsweep roof plane hypotheses: patch, verification score, built or why not "
      "(Baillard & Zisserman 2000, sections 4-5)";
  WriteFeatureLayer(path, "roof_planes", LayerGeometry::kMultiPolygonZ, features, lo);
}

void WriteReport(const std::string& path, const RunSummary& s) {
  nlohmann::json j;
  for (const RunStage& st : s.stages)
    j["stages"].push_back({{"stage", st.name}, {"result", st.result}, {"seconds", st.seconds}});
  j["rejected"] = s.rejected;
  j["messages"] = s.messages;
  // An existing file was refused before the work unless -overwrite.
  WriteTextFile(path, j.dump(2) + "\n", /*overwrite=*/true);
}

// Sets each building's edge_support (BuildingEdgeSupport) and drops those
// below r.min_edge_support (r.min_edge_support_unlined when no 3D line
// supports its roof), with the reason in assembled->rejected, also
// for their planes (the -planes layer tells them as not built) and their
// footprint (footprint_rejection). Returns the stage's result line.
std::string ApplyEdgeSupport(const Block& block, const std::vector<cv::Mat>& images,
                             const RunRequest& r, AssemblyResult* assembled) {
  CityModel& model = assembled->model;
  const std::vector<EdgeSupport> support = BuildingEdgeSupport(model, block, images, r.image_edges);
  std::vector<Building> kept;
  std::vector<double> fractions;
  std::map<std::string, std::string> dropped;  // building or part id -> reason
  for (size_t i = 0; i < model.buildings.size(); ++i) {
    Building& b = model.buildings[i];
    const double f = support[i].Fraction();
    if (std::isfinite(f)) {
      b.double_attributes["edge_support"] = f;
      const auto lines = b.double_attributes.find("supporting_lines");
      const bool unlined = lines != b.double_attributes.end() && lines->second == 0;
      const double min =
          unlined ? std::max(r.min_edge_support, r.min_edge_support_unlined) : r.min_edge_support;
      if (f < min) {
        // With footprints every reason is the footprint's, as the
        // assembly's are.
        const auto fp = b.string_attributes.find("footprint_id");
        const std::string reason = StrFormat(
            "roof edges on image edges %.2f < %.2f%s", f, min,
            unlined && min > r.min_edge_support ? ", and no matched line supports its roof" : "");
        const std::string why = (fp != b.string_attributes.end()
                                     ? "footprint " + fp->second + " (building " + b.id + ")"
                                     : "building " + b.id) +
                                ": " + reason;
        if (fp != b.string_attributes.end())
          assembled->footprint_rejection[fp->second] = {reason, assembled->rejected.size()};
        assembled->rejected.push_back(why);
        dropped[b.id] = why;
        for (const Building* s : b.Solids()) dropped[s->id] = why;
        continue;
      }
      fractions.push_back(f);
    }
    kept.push_back(std::move(b));
  }
  model.buildings = std::move(kept);
  for (size_t i = 0; i < assembled->plane_building.size(); ++i) {
    const auto d = dropped.find(assembled->plane_building[i]);
    if (d == dropped.end()) continue;
    assembled->plane_building[i].clear();
    if (i < assembled->plane_reason.size()) assembled->plane_reason[i] = d->second;
  }
  if (fractions.empty()) return "no roof edge seen";
  std::sort(fractions.begin(), fractions.end());
  return StrFormat("median %.0f %% of roof edges on image edges, lowest %.0f %%",
                   100 * fractions[fractions.size() / 2], 100 * fractions.front());
}

// Writes the model (block CRS coordinates) to the run's output, reprojected
// to -t_srs when given. The solids were checked in metres by the assembly;
// reprojecting to degrees afterwards keeps them closed and planar in the
// target CRS's terms.
void WriteRunOutput(CityModel model, const std::string& block_crs, const RunRequest& r) {
  model.crs = block_crs;
  if (!r.target_crs.empty()) {
    if (model.crs.empty())
      throw Error(r.block + ": the block has no CRS to reproject from (-t_srs)");
    ReprojectCityModel(model, r.target_crs);
  }
  WriteOptions wo;
  wo.format = r.format;
  wo.overwrite = r.overwrite;
  WriteCityModel(model, r.output, wo);
}

}  // namespace

RunSummary RunPipeline(const RunRequest& request, Progress& progress) {
  // A copy: the verification's thresholds follow the block's imagery once
  // the sweep has measured it (verify_follows_sweep).
  RunRequest r = request;
  if (r.output.empty())
    throw Error(std::string(r.stop_after_sweep ? "sweep" : "run") + ": no output file given (-o)");
  for (const std::string& p : {r.output, r.lines3d, r.half_planes, r.planes, r.report})
    if (!p.empty()) CheckOutputPath(p, r.overwrite);
  if (!r.stop_after_sweep) ResolveCityModelFormat(r.output, r.format);  // fail early
  RunSummary out;

  auto t0 = Clock::now();
  BlockManifest manifest = OpenBlockManifest(r.block);
  if (r.aoi) manifest.aoi = r.aoi;
  Block block = ManifestToBlock(manifest);
  const LocalFrame frame = ManifestLocalFrame(manifest);
  if (!block.ground.Known() && !r.stop_after_sweep)
    throw Error(r.block + ": the block has no ground height or DTM; walls need one");
  if (!(r.tile_buffer_m >= 0)) throw Error("run: the tile buffer must be 0 m or more");
  std::optional<TileCut> tile;
  if (block.aoi) {
    tile = CutBlockToTile(&block, r.tile_buffer_m, r.block);
    out.messages.push_back(tile->message);
  }
  if (const auto w = SurfaceModelWarning(block.ground))
    out.messages.push_back(manifest.dtm + ": " + *w);
  // Footprints are read first: a wrong file or CRS should fail in seconds,
  // not after the matching.
  std::vector<Footprint> footprints;
  const std::string footprint_path = r.footprints.empty() ? block.footprints_path : r.footprints;
  if (!footprint_path.empty() && !r.stop_after_sweep) {
    FootprintReadOptions fo;
    fo.layer = r.footprints.empty() ? block.footprints_layer : r.footprints_layer;
    fo.id_field = r.footprints_id_field;
    fo.block_crs = manifest.crs;
    fo.extent = tile ? std::optional<Eigen::Vector4d>(tile->region) : BlockExtent(block);
    footprints = ReadFootprints(footprint_path, frame, fo, &out.messages);
    if (footprints.empty() && tile) {
      // A tile of parkland: the footprints say there is nothing to build.
      out.messages.push_back(footprint_path + ": no footprint in the tile or its buffer");
      WriteRunOutput(CityModel(), manifest.crs, r);
      out.stages.push_back({"write", "0 buildings", Since(t0)});
      if (!r.report.empty()) WriteReport(r.report, out);
      progress.Update(1.0, "done");
      return out;
    }
    if (footprints.empty())
      throw Error(footprint_path +
                  ": no footprint lies where the block's images see the ground "
                  "(a different CRS or area?)");
  }
  const std::vector<cv::Mat> images = ReadBlockImages(block, tile ? &*tile : nullptr, r.block);
  out.stages.push_back({"read",
                        footprints.empty() ? StrFormat("%zu images", images.size())
                                           : StrFormat("%zu images, %zu footprints", images.size(),
                                                       footprints.size()),
                        Since(t0)});

  // Lines and matching: 0 .. 35 %; sweep: 35 .. 95 %.
  t0 = Clock::now();
  MatchResult matched;
  if (r.lines_in.empty()) {
    SubProgress match_progress(progress, 0.0, 0.35);
    matched = MatchLines(block, images, r.match, r.edges, match_progress, nullptr);
    out.messages.insert(out.messages.end(), matched.messages.begin(), matched.messages.end());
    if (block.surface)
      out.messages.push_back(FormatSurfaceAgreement(LinesOnSurfaceModel(block, matched.lines)));
    out.stages.push_back(
        {"segments + 3D lines",
         StrFormat("%lld segments, %zu 3D lines", matched.funnel.segments, matched.lines.size()),
         Since(t0)});
  } else {
    SegmentSet given = ReadSegments(r.lines_in);
    if (!given.crs.empty() && !manifest.crs.empty() &&
        !SameHorizontalCrs(given.crs, manifest.crs)) {
      const std::string from = given.crs;
      try {
        ReprojectSegments(given, manifest.crs);
      } catch (const Error& e) {
        throw Error(r.lines_in + ": " + e.what());
      }
      out.messages.push_back(r.lines_in + ": lines reprojected from " + from + " to the block's " +
                             manifest.crs);
    }
    // The views a line was matched in restrict the sweep's reference view
    // (SweepLine::views), as when `run` matches itself; names this block
    // does not have (lines of another block) drop the restriction.
    std::map<std::string, int> view_index;
    for (size_t v = 0; v < block.views.size(); ++v)
      view_index[block.views[v].name] = static_cast<int>(v);
    for (const LabelledSegment& s : given.segments) {
      Line3D l;
      l.segment = {frame.ToLocal(s.segment.a), frame.ToLocal(s.segment.b)};
      l.rms_px = s.rms_px;
      for (const auto& [name, id] : s.observations) {
        const auto it = view_index.find(name);
        if (it == view_index.end()) {
          l.observations.clear();
          break;
        }
        l.observations.emplace_back(it->second, id);
      }
      matched.lines.push_back(std::move(l));
    }
    out.stages.push_back(
        {"3D lines read",
         StrFormat("%zu 3D lines from %s", matched.lines.size(), r.lines_in.c_str()), Since(t0)});
  }
  out.lines = static_cast<int>(matched.lines.size());
  if (!r.lines3d.empty()) {
    std::vector<LayerFeature> features;
    // As `match` writes them, so that `run -lines` on this layer sweeps
    // the same lines with the same reference views.
    const bool whole_images = !tile || !tile->Windowed();
    for (const Line3D& l : matched.lines)
      features.push_back(Line3DFeature(l, block, frame.ToCrs(l.segment.a), frame.ToCrs(l.segment.b),
                                       whole_images));
    FeatureLayerOptions lo;
    lo.crs = manifest.crs;
    lo.overwrite = r.overwrite;
    WriteFeatureLayer(r.lines3d, "lines3d", LayerGeometry::kLineStringZ, features, lo);
  }

  t0 = Clock::now();
  // Lines on or near the ground (road markings, wall feet, shadows) bound
  // no roof plane: sweeping them costs half the time and yields planes the
  // assembly rejects anyway. Without a ground model everything is swept.
  std::vector<SweepLine> lines;
  int near_ground = 0;
  const double min_line_height =
      0.5 * (footprints.empty() ? r.assembly.min_height_m : r.assembly.footprint_min_height_m);
  for (const Line3D& l : matched.lines) {
    if (block.ground.Known()) {
      const Eigen::Vector3d& a = l.segment.a;
      const Eigen::Vector3d& b = l.segment.b;
      const double ha = a.z() - block.ground.HeightAt(a.x(), a.y());
      const double hb = b.z() - block.ground.HeightAt(b.x(), b.y());
      if (std::max(ha, hb) < min_line_height) {
        ++near_ground;
        continue;
      }
    }
    // A line from two views, or completed from its junctions, reprojects
    // exactly by construction: its residual measures nothing.
    const bool measured =
        l.observations.empty() ? std::isfinite(l.rms_px) : l.Views() >= 3 && !l.from_junctions;
    SweepLine s{l.segment, {}, measured ? l.rms_px : std::nan("")};
    for (const auto& [v, seg] : l.observations) s.views.push_back(v);
    lines.push_back(std::move(s));
  }
  const bool two_passes = r.lift_lines && !r.stop_after_sweep;
  // Prepared once: the second pass sweeps the same views twice more.
  std::vector<ViewTexture> textures = PrepareViewTextures(block, images, r.sweep);
  auto sweep = [&](const std::vector<SweepLine>& swept, double from, double to,
                   const std::string& stage, const std::string& extra,
                   const std::vector<HalfPlane>* previous) {
    SubProgress sweep_progress(progress, from, to);
    std::vector<HalfPlane> h =
        SweepHalfPlanes(block, textures, swept, r.sweep, sweep_progress, previous);
    out.sides = static_cast<int>(h.size());
    out.accepted = 0;
    for (const HalfPlane& x : h) out.accepted += x.accepted;
    out.stages.push_back(
        {stage,
         StrFormat("%d sides, %d accepted, candidates from Sim %.2f (%s)", out.sides, out.accepted,
                   CandidateThreshold(h, r.sweep), extra.c_str()),
         Since(t0)});
    return h;
  };
  const double sweep_to = two_passes ? 0.6 : 0.95;
  const int w0 = 2 * r.sweep.ncc_radius + 1;
  std::vector<HalfPlane> hps =
      sweep(lines, 0.35, sweep_to, "half-plane sweep",
            StrFormat("%d lines near the ground, %d x %d px window", near_ground, w0, w0), nullptr);
  // Noisy imagery: the sweep again with the wider correlation window
  // (SweepOptions::wide_ncc_radius), and every later sweep with it too.
  // The progress runs over the same range again (GDAL's line stays put
  // until it passes where it stood).
  if (WantsWiderWindow(hps, r.sweep)) {
    t0 = Clock::now();
    r.sweep.ncc_radius = r.sweep.wide_ncc_radius;
    const int w = 2 * r.sweep.ncc_radius + 1;
    hps = sweep(lines, 0.35, sweep_to, "half-plane sweep, wider window",
                StrFormat("%d x %d px on noisy images", w, w), nullptr);
  }
  if (r.verify_follows_sweep && !r.stop_after_sweep)
    r.verify.min_score = ScoreThresholdAtImageQuality(r.verify.min_score, hps, r.sweep);

  // §4 and §5: half-planes grouped into planes, every plane's patch
  // verified against all views that see it, then conflicts resolved by the
  // verified evidence (patch area x score). `final_pass`: the rejections and
  // the trace are the ones reported.
  std::vector<PlaneTrace> traces;
  std::vector<PlaneTrace>* trace = r.planes.empty() ? nullptr : &traces;
  const AssemblyOptions assembly_options = AssemblyOptionsFor(r.assembly, !footprints.empty());
  // The pieces of the planes between their lines down the fall line
  // (PiecesAcrossFallLines), each verified apart. Refuted, not merely
  // unverifiable: too few textured samples (score NaN) leave a piece to the
  // plane's evidence elsewhere. Without footprints only: with them
  // PiecesOverFootprints weighs a face house by house, and over 30 runs
  // these pieces moved no figure there beyond its noise (vertices within
  // 2 GSD -0.18 +- 0.10).
  const bool fall_line_pieces = r.fall_line_pieces && footprints.empty();
  struct RefutedPieces {
    std::vector<FallLinePiece> pieces;
    std::vector<char> refuted;
    std::vector<PlaneVerification> checks;
  };
  FallLinePieceOptions piece_options;
  piece_options.min_slope_deg = r.assembly.party_min_slope_deg;
  piece_options.max_angle_deg = r.assembly.party_max_angle_deg;
  piece_options.min_span = r.assembly.party_min_span;
  piece_options.min_depth_m = r.assembly.party_min_depth_m;
  piece_options.min_width_m = r.assembly.party_min_width_m;
  // `at`: where the progress stands meanwhile.
  auto refuted_pieces = [&](const std::vector<RoofPlaneHypothesis>& planes, double at) {
    RefutedPieces q;
    q.pieces = PiecesAcrossFallLines(planes, piece_options);
    std::vector<RoofPlaneHypothesis> hyps;
    for (const FallLinePiece& p : q.pieces) hyps.push_back(p.piece);
    SubProgress none(progress, at, at);
    q.checks = VerifyPlanes(block, images, hyps, r.verify, none);
    for (const PlaneVerification& c : q.checks)
      q.refuted.push_back(!c.accepted && std::isfinite(c.score));
    return q;
  };
  auto find_planes = [&](std::vector<SweepLine>& swept, const std::vector<HalfPlane>& sides,
                         bool final_pass, double from, double to) {
    const char* pass = two_passes ? (final_pass ? " (pass 2)" : " (pass 1)") : "";
    std::vector<std::string> rejected;
    t0 = Clock::now();
    GroupingResult grouped = GroupHalfPlanes(swept, sides, r.grouping);
    const int swept_planes = static_cast<int>(grouped.planes.size());
    int candidates = 0;
    for (const HalfPlane& h : sides) candidates += h.candidate;
    int pair_planes = 0;
    if (r.line_planes) {
      std::vector<PlaneGroup> pairs =
          PlanesFromLinePairs(swept, &grouped.planes, r.coplanar, &sides);
      pair_planes = static_cast<int>(pairs.size());
      for (PlaneGroup& g : pairs) grouped.planes.push_back(std::move(g));
    }
    const int attached = AttachCoplanarLines(swept, &grouped.planes, r.coplanar, &sides);
    const std::vector<std::string> one_line = DropWeaklySupported(&grouped.planes, r.grouping);
    rejected.insert(rejected.end(), one_line.begin(), one_line.end());
    out.planes = static_cast<int>(grouped.planes.size());
    out.stages.push_back(
        {std::string("grouping into planes") + pass,
         StrFormat("%d planes from %d candidate sides, %d from line pairs, %d lines joined, %zu "
                   "with fewer than %d lines dropped",
                   swept_planes, candidates, pair_planes, attached, one_line.size(),
                   r.grouping.min_lines),
         Since(t0)});

    t0 = Clock::now();
    std::vector<RoofPlaneHypothesis> found = ToRoofPlanes(grouped.planes, &swept);
    SubProgress verify_progress(progress, from, to);
    VerifyOptions sweep_verify = r.verify;
    sweep_verify.refine_for_texture = true;
    const std::vector<PlaneVerification> checks =
        VerifyPlanes(block, images, found, sweep_verify, verify_progress);
    const size_t n_planes = found.size();
    std::vector<RoofPlaneHypothesis> verified;
    KeepVerified(std::move(found), checks, &verified, &rejected, final_pass ? trace : nullptr);
    const size_t n_verified = verified.size();
    // A face verified as a whole may hold a part the images refute, between
    // its verges: weighed piece by piece before the conflicts, so that the
    // roof it ran over can still win there.
    int pieces_cut = 0;
    if (fall_line_pieces) {
      const RefutedPieces q = refuted_pieces(verified, to);
      for (int k : CutRefutedFallLinePieces(q.pieces, q.refuted, &verified)) {
        rejected.push_back(q.pieces[k].piece.id + ": " + q.checks[k].reason);
        if (final_pass && trace) trace->push_back({q.pieces[k].piece, q.checks[k]});
        ++pieces_cut;
      }
    }
    // A plane the assembly refuses whatever the others are (too low, too
    // steep) goes before the conflicts, where it could push out a plane the
    // assembly would keep. Short lines are not such a property where a
    // coplanar neighbour can still merge with the plane (a flat roof found
    // as two planes of short lines): the merge's longest line decides.
    // Every plane spared from the line rule first: the merge partners are
    // looked for among the planes that are no roof for no other reason.
    const std::vector<char> all(verified.size(), 1);
    std::vector<std::string> refused =
        DropRefusedRoofs(&verified, block.ground, assembly_options, &all);
    const std::vector<char> may_merge =
        r.merge_coplanar ? NearCoplanarNeighbours(verified, r.merge) : std::vector<char>();
    const std::vector<std::string> too_short =
        DropRefusedRoofs(&verified, block.ground, assembly_options, &may_merge);
    refused.insert(refused.end(), too_short.begin(), too_short.end());
    // So does a plane mostly outside every footprint.
    const std::vector<std::string> outside =
        DropOutsideFootprints(&verified, footprints, assembly_options);
    refused.insert(refused.end(), outside.begin(), outside.end());
    rejected.insert(rejected.end(), refused.begin(), refused.end());
    const std::vector<std::string> settled = SettleVerifiedPlanes(&verified, r.grouping);
    rejected.insert(rejected.end(), settled.begin(), settled.end());
    out.stages.push_back(
        {std::string("verification") + pass,
         StrFormat("%zu of %zu planes confirmed (score >= %.2f)%s, %zu of them no roof (too "
                   "low, too steep%s), %zu left after conflicts",
                   n_verified, n_planes, r.verify.min_score,
                   fall_line_pieces
                       ? StrFormat(", %d pieces between their verges refuted", pieces_cut).c_str()
                       : "",
                   refused.size(), footprints.empty() ? "" : ", off the footprints",
                   verified.size()),
         Since(t0)});
    if (final_pass) out.rejected.insert(out.rejected.end(), rejected.begin(), rejected.end());
    return verified;
  };

  std::vector<RoofPlaneHypothesis> roof_planes;
  // The views' image segments, for the lifts and the eave search: those
  // matching found, or found again when the lines were read from a file.
  std::vector<Segments2D> image_segments;
  auto view_segments = [&]() -> const std::vector<Segments2D>& {
    if (image_segments.empty())
      image_segments = r.lines_in.empty() ? std::move(matched.segments)
                                          : ExtractViewSegments(images, r.match, r.edges);
    return image_segments;
  };
  if (two_passes) {
    roof_planes = find_planes(lines, hps, false, 0.6, 0.62);
    t0 = Clock::now();
    const std::vector<Segments2D>& segments = view_segments();
    std::vector<std::vector<bool>> used(segments.size());
    for (size_t v = 0; v < segments.size(); ++v) used[v].assign(segments[v].size(), false);
    std::vector<Segment3> known;
    // Lines read from a file name segments of the whole images; in a tile's
    // windows those ids name other segments.
    const bool ids_apply = r.lines_in.empty() || !tile || !tile->Windowed();
    for (const Line3D& l : matched.lines) {
      known.push_back(l.segment);
      if (ids_apply)
        for (const auto& [v, id] : l.observations)
          if (v >= 0 && v < static_cast<int>(used.size()) && id >= 0 &&
              id < static_cast<int>(used[v].size()))
            used[v][id] = true;
    }
    const std::vector<LiftedLine> lifts =
        LiftSegmentsOntoPlanes(block, segments, used, roof_planes, known, r.lift);
    auto to_sweep = [](const LiftedLine& l) {
      SweepLine s{l.segment, {}, std::nan("")};
      for (const auto& [v, id] : l.observations) s.views.push_back(v);
      return s;
    };
    std::vector<SweepLine> probe;
    for (const LiftedLine& l : lifts) probe.push_back(to_sweep(l));
    SubProgress probe_progress(progress, 0.62, 0.65);
    const std::vector<LiftedLine> borders =
        KeepBorderLifts(lifts, SweepHalfPlanes(block, textures, probe, r.sweep, probe_progress),
                        roof_planes, r.lift);
    for (const LiftedLine& l : borders) lines.push_back(to_sweep(l));
    out.stages.push_back({"segments lifted onto planes",
                          StrFormat("%zu lifted onto %zu planes, %zu of them border lines",
                                    lifts.size(), roof_planes.size(), borders.size()),
                          Since(t0)});
    size_t n_level = 0;
    // Without footprints only: with them the roof models over bare
    // footprints reach the roofs no line places, and over 30 paired runs
    // the level lines moved plane quality -0.29 +- 0.26 there (5 up / 10
    // down) against +0.12 +- 0.21 without (building quality +1.51 +- 0.45).
    if (r.level_lines && footprints.empty()) {
      t0 = Clock::now();
      // A lifted segment lies on a plane already: its depth is known.
      for (const LiftedLine& l : lifts)
        if (!l.observations.empty()) used[l.observations[0].first][l.observations[0].second] = true;
      for (const LiftedLine& l : borders) known.push_back(l.segment);
      // Where the block gives no ground, the lowest lines stand for it.
      double ground_z = 0;
      {
        std::vector<double> z;
        for (const SweepLine& l : lines) z.push_back(std::min(l.segment.a.z(), l.segment.b.z()));
        if (!z.empty()) {
          std::nth_element(z.begin(), z.begin() + z.size() / 20, z.end());
          ground_z = z[z.size() / 20];
        }
      }
      SubProgress level_progress(progress, 0.65, 0.72);
      LevelLineStats ls;
      const std::vector<LevelLine> level =
          SweepLevelLines(block, textures, segments, used, roof_planes, known, ground_z,
                          CandidateThreshold(hps, r.sweep), r.sweep, r.level, level_progress, &ls);
      // The reference view is the segment's own: its image line is exact
      // only there.
      for (const LevelLine& l : level) lines.push_back({l.segment, {l.view}, std::nan(""), true});
      n_level = level.size();
      out.stages.push_back(
          {"level lines swept",
           StrFormat(
               "%d segments no view fixes, %d swept, %d with a height that stands out, %zu placed",
               ls.candidates, ls.swept, ls.peaked, level.size()),
           Since(t0)});
    }
    t0 = Clock::now();
    // Only the lines whose bands a lifted line reaches are swept again.
    hps = sweep(lines, r.level_lines && footprints.empty() ? 0.72 : 0.65, 0.95,
                "half-plane sweep (pass 2)",
                StrFormat("%zu lines lifted, %zu level", borders.size(), n_level), &hps);
  }

  // The sweeps are done; what follows reads the images themselves.
  std::vector<ViewTexture>().swap(textures);

  const std::string half_plane_path = r.stop_after_sweep ? r.output : r.half_planes;
  if (!half_plane_path.empty()) {
    t0 = Clock::now();
    std::vector<LayerFeature> features;
    for (const HalfPlane& h : hps) {
      if (h.reference_view < 0) continue;
      LayerFeature f;
      // The strip the sweep saw, lifted onto its best plane.
      Polygon3 strip;
      for (const Eigen::Vector2d& p : HalfPlanePatch(lines[h.line], h, 0.5)) {
        const double z = -(h.plane[0] * p.x() + h.plane[1] * p.y() + h.plane[3]) / h.plane[2];
        strip.exterior.push_back(frame.ToCrs({p.x(), p.y(), std::isfinite(z) ? z : 0.0}));
      }
      if (strip.exterior.size() < 3) continue;
      f.polygons.push_back(std::move(strip));
      f.integers["line"] = h.line;
      f.integers["side"] = h.side;
      f.integers["accepted"] = h.accepted;
      // The looser test that lets the side propose a plane (SweepOptions).
      f.integers["candidate"] = h.candidate;
      f.integers["points"] = h.points;
      f.integers["views"] = h.views;
      f.reals["theta_deg"] = h.theta_deg;
      f.reals["slope_deg"] = std::acos(std::clamp(h.plane[2], -1.0, 1.0)) * 180 / M_PI;
      f.reals["similarity"] = h.similarity;
      f.reals["curvature"] = h.curvature;
      f.reals["peak_ratio"] = h.peak_ratio;
      f.reals["extent_m"] = h.extent_m;
      f.strings["reason"] = h.reason;
      f.strings["reference_view"] = block.views[h.reference_view].name;
      features.push_back(std::move(f));
    }
    FeatureLayerOptions lo;
    lo.driver = r.stop_after_sweep ? r.format : "";
    lo.crs = manifest.crs;
    lo.overwrite = r.overwrite;
    lo.description = "roofsweep half-planes (Baillard & Zisserman 2000, section 3)";
    WriteFeatureLayer(half_plane_path, "half_planes", LayerGeometry::kMultiPolygonZ, features, lo);
    if (r.stop_after_sweep)
      out.stages.push_back({"write", StrFormat("%zu half-planes", features.size()), Since(t0)});
  }
  if (r.stop_after_sweep) {
    if (!r.report.empty()) WriteReport(r.report, out);
    progress.Update(1.0, "done");
    return out;
  }

  roof_planes = find_planes(lines, hps, true, 0.95, 0.99);

  // With footprints: a plane that spans buildings is weighed over each
  // footprint apart, and cut back where the images refute it there (a face
  // running on over a neighbour's roof). Before the completions, so that
  // they can roof what the cut leaves bare.
  if (!footprints.empty() && r.footprint_pieces) {
    t0 = Clock::now();
    FootprintPieceOptions po;
    po.min_piece_m2 = r.assembly.footprint_min_piece_m2;  // the pieces the assembly would build
    const std::vector<FootprintPiece> pieces = PiecesOverFootprints(roof_planes, footprints, po);
    std::vector<RoofPlaneHypothesis> hyps;
    for (const FootprintPiece& q : pieces) hyps.push_back(q.piece);
    SubProgress none(progress, 0.99, 0.99);
    const std::vector<PlaneVerification> checks = VerifyPlanes(block, images, hyps, r.verify, none);
    // Refuted, not merely unverifiable: too few textured samples (score
    // NaN) leave the piece to the plane's evidence elsewhere.
    std::vector<char> refuted(pieces.size());
    for (size_t k = 0; k < pieces.size(); ++k)
      refuted[k] = !checks[k].accepted && std::isfinite(checks[k].score);
    const std::vector<int> cut = CutRefutedPieces(pieces, refuted, footprints, &roof_planes, po);
    for (int k : cut) {
      out.rejected.push_back(hyps[k].id + ": " + checks[k].reason);
      if (trace) trace->push_back({hyps[k], checks[k]});
    }
    out.stages.push_back({"planes over several footprints",
                          StrFormat("%zu pieces verified, %zu cut", pieces.size(), cut.size()),
                          Since(t0)});
  }

  // Every completion step below proposes planes that are verified like
  // the sweep's own, then settled in the conflicts with those kept so far;
  // returns how many the verification confirmed. With `kept_new`, the
  // conflicts are settled on a copy and only the proposals that stay are
  // taken from it (how many: *kept_new): the planes kept so far are not
  // decided again.
  // `review` may overturn verdicts before they are applied.
  auto add_verified = [&](std::vector<RoofPlaneHypothesis> proposals,
                          const VerifyOptions* verify = nullptr, size_t* kept_new = nullptr,
                          const std::function<void(std::vector<PlaneVerification>*)>& review = {}) {
    SubProgress none(progress, 0.99, 0.99);
    std::vector<PlaneVerification> checks =
        VerifyPlanes(block, images, proposals, verify ? *verify : r.verify, none);
    if (review) review(&checks);
    std::set<std::string> new_ids;
    std::vector<RoofPlaneHypothesis> trial;
    if (kept_new) {
      for (size_t k = 0; k < proposals.size(); ++k)
        if (checks[k].accepted) new_ids.insert(proposals[k].id);
      trial = roof_planes;
    }
    std::vector<RoofPlaneHypothesis>& into = kept_new ? trial : roof_planes;
    const size_t before = into.size();
    KeepVerified(std::move(proposals), checks, &into, &out.rejected, trace);
    const size_t confirmed = into.size() - before;
    for (const std::string& why : ResolveConflicts(&into, r.grouping))
      if (!kept_new || new_ids.count(why.substr(0, why.find(": ")))) out.rejected.push_back(why);
    if (kept_new) {
      *kept_new = 0;
      for (RoofPlaneHypothesis& q : trial)
        if (new_ids.count(q.id)) roof_planes.push_back(std::move(q)), ++*kept_new;
    }
    return confirmed;
  };

  // Patches that run past the eave or verge bounding their lines, cut
  // back before the eave search and the mirror take them as they are.
  if (r.border_clip) {
    t0 = Clock::now();
    const int cut = ClipFacesAtBorderLines(&roof_planes, r.eaves);
    out.stages.push_back({"faces cut at their border lines",
                          StrFormat("%d of %zu patches cut", cut, roof_planes.size()), Since(t0)});
  }

  // Faces cut short of their eaves, grown to them before the symmetry
  // completion mirrors them.
  if (r.eave_search) {
    t0 = Clock::now();
    const std::vector<FaceEave> eaves = FindEaves(block, view_segments(), roof_planes, r.eaves);
    const int grown = ExtendFacesToEaves(eaves, &roof_planes, r.eaves);
    out.stages.push_back({"faces grown to their eaves",
                          StrFormat("%zu eaves found below %zu planes, %d patches grown",
                                    eaves.size(), roof_planes.size(), grown),
                          Since(t0)});
  }

  // Completion by symmetry: the face beyond each ridge the sweep found
  // from one side only, verified like the others; derived, so it yields
  // in conflicts to every plane found directly.
  if (r.mirror_faces) {
    t0 = Clock::now();
    std::vector<RoofPlaneHypothesis> mirrored = MirroredFaces(roof_planes, r.mirror);
    const size_t proposed = mirrored.size();
    VerifyOptions at_ridge = r.verify;
    at_ridge.height_test = !r.mirror.height_from_ridge;
    const size_t confirmed = add_verified(std::move(mirrored), &at_ridge);
    out.stages.push_back(
        {"mirrored faces",
         StrFormat("%zu faces beyond a ridge proposed, %zu confirmed", proposed, confirmed),
         Since(t0)});
  }

  // Completion by footprints: planes of neighbouring footprints (terraced
  // houses) proposed over each footprint, verified like the others, and
  // kept where they conflict with no plane found directly; repeated while
  // it confirms new planes, so that a row is completed from any house the
  // sweep found.
  if (!footprints.empty()) {
    t0 = Clock::now();
    std::set<std::string> tried;
    int proposed = 0, confirmed = 0;
    for (int round = 0; round < 20; ++round) {
      std::vector<RoofPlaneHypothesis> extra;
      for (RoofPlaneHypothesis& q : PlanesFromNeighbourFootprints(roof_planes, footprints))
        if (tried.insert(q.id).second) extra.push_back(std::move(q));
      if (extra.empty()) break;
      proposed += static_cast<int>(extra.size());
      const int now = static_cast<int>(add_verified(std::move(extra)));
      confirmed += now;
      if (now == 0) break;
    }
    out.stages.push_back(
        {"footprint completion",
         StrFormat("%d planes of neighbours proposed, %d confirmed", proposed, confirmed),
         Since(t0)});
  }

  // Faces seen over part of their footprint grow along it where the
  // images confirm the strip beyond the patch; the plane, its lines and its
  // score stay as they are (the strips are no evidence in conflicts).
  if (!footprints.empty() && r.footprint_growth) {
    t0 = Clock::now();
    std::vector<PatchExtension> ext = ExtensionsAlongFootprints(roof_planes, footprints, r.growth);
    std::vector<RoofPlaneHypothesis> strips;
    for (const PatchExtension& e : ext) strips.push_back(e.strip);
    SubProgress none(progress, 0.99, 0.99);
    const std::vector<PlaneVerification> checks =
        VerifyPlanes(block, images, strips, r.verify, none);
    std::vector<std::vector<Eigen::Vector2d>> extra(roof_planes.size());
    size_t confirmed = 0;
    for (size_t k = 0; k < ext.size(); ++k) {
      if (!checks[k].accepted) continue;
      const auto& patch = checks[k].patch.empty() ? strips[k].patch : checks[k].patch;
      extra[ext[k].plane].insert(extra[ext[k].plane].end(), patch.begin(), patch.end());
      ++confirmed;
    }
    for (size_t i = 0; i < roof_planes.size(); ++i) {
      if (extra[i].empty()) continue;
      extra[i].insert(extra[i].end(), roof_planes[i].patch.begin(), roof_planes[i].patch.end());
      roof_planes[i].patch = ConvexHull(std::move(extra[i]));
    }
    out.stages.push_back({"faces grown along footprints",
                          StrFormat("%zu strips proposed, %zu confirmed", ext.size(), confirmed),
                          Since(t0)});
  }

  // The hip end missing at one end of a ridge, from the one found at the
  // other; after the growth along footprints, which takes the long faces to
  // the footprint's ends and so gives the ridge's length. The conflicts are
  // settled on a copy, and only the new ends are taken from it: settled
  // again, the patches just grown along the footprints conflict anew, and
  // on `hard-1` a face went that way whenever this stage ran, with nothing
  // proposed.
  if (r.hip_ends) {
    t0 = Clock::now();
    std::vector<RoofPlaneHypothesis> ends = MirroredHipEnds(roof_planes, r.hip_end);
    const size_t proposed = ends.size();
    size_t confirmed = 0, kept = 0;
    if (!ends.empty()) confirmed = add_verified(std::move(ends), nullptr, &kept);
    out.stages.push_back({"mirrored hip ends",
                          StrFormat("%zu hip ends proposed at the other end of a ridge, %zu "
                                    "confirmed, %zu kept in the conflicts",
                                    proposed, confirmed, kept),
                          Since(t0)});
  }

  // With footprints, the faces missing on one side of a symmetric
  // footprint from their mirror images on the other (a mansard's steep
  // lower faces and shallow upper ends); after the mirrored faces and hip
  // ends, which have their own ridge to go by. Their height is the mirrored
  // face's (RunRequest::footprint_mirror_min_margin). The conflicts are
  // settled on a copy and only the new faces taken from it, as for the hip
  // ends.
  if (!footprints.empty() && r.footprint_mirror) {
    t0 = Clock::now();
    FootprintMirrorOptions mo = r.footprint_mirror_options;
    mo.leave_one_face =
        r.footprint_flat_roofs && r.roof_models_over_footprints && r.roofs_beyond_ridges;
    std::vector<RoofPlaneHypothesis> faces =
        FacesMirroredAcrossFootprints(roof_planes, footprints, mo);
    const size_t proposed = faces.size();
    size_t confirmed = 0, kept = 0;
    VerifyOptions from_mirror = r.verify;
    from_mirror.min_margin = r.footprint_mirror_min_margin;
    if (!faces.empty()) confirmed = add_verified(std::move(faces), &from_mirror, &kept);
    out.stages.push_back({"faces mirrored across footprints",
                          StrFormat("%zu proposed across a footprint's axis, %zu confirmed, %zu "
                                    "kept in the conflicts",
                                    proposed, confirmed, kept),
                          Since(t0)});
  }

  // One face fitted as two planes a few degrees apart: the merged plane
  // replaces both where the images confirm it about as well as the weaker
  // of the two. Two planes in a concave crease that it fits clearly worse
  // over one part than that part's own plane are two surfaces: only the
  // one that fits the images better stays.
  if (r.merge_coplanar) {
    t0 = Clock::now();
    const std::vector<PlaneMerge> merges = NearCoplanarMerges(roof_planes, r.merge);
    std::vector<RoofPlaneHypothesis> proposals;
    for (const PlaneMerge& m : merges) proposals.push_back(m.merged);
    SubProgress none(progress, 0.99, 0.99);
    const std::vector<PlaneVerification> checks =
        VerifyPlanes(block, images, proposals, r.verify, none);
    // A pair in a concave crease: the merged plane over each part's own
    // patch (NearCoplanarMergeOptions::concave_parts).
    std::vector<RoofPlaneHypothesis> on_parts;
    for (const PlaneMerge& m : merges) {
      if (!m.concave) continue;
      for (int part : {m.a, m.b}) {
        RoofPlaneHypothesis h = m.merged;
        h.patch = roof_planes[part].patch;
        on_parts.push_back(std::move(h));
      }
    }
    const std::vector<PlaneVerification> part_checks =
        VerifyPlanes(block, images, on_parts, r.verify, none);
    // A merged plane is verified as a whole, like the sweep's: where a piece
    // of it between its verges is refuted, the two stay apart (the parts of
    // a face cut at a refuted piece before the conflicts would join again
    // across it).
    std::vector<char> piece_refuted(proposals.size(), 0);
    if (fall_line_pieces) {
      const RefutedPieces q = refuted_pieces(proposals, 0.99);
      for (size_t k = 0; k < q.pieces.size(); ++k)
        if (q.refuted[k]) piece_refuted[q.pieces[k].plane] = 1;
    }
    std::vector<char> merged_away(roof_planes.size(), 0);
    std::vector<RoofPlaneHypothesis> merged;
    int creases = 0;
    size_t part_check = 0;
    for (size_t k = 0; k < merges.size(); ++k) {
      const RoofPlaneHypothesis &a = roof_planes[merges[k].a], &b = roof_planes[merges[k].b];
      bool parts_hold = true;
      if (merges[k].concave) {
        for (const RoofPlaneHypothesis* p : {&a, &b}) {
          // NaN (too few textured samples) does not refute.
          const double s = part_checks[part_check++].score;
          parts_hold = parts_hold && !(s < p->similarity - r.merge.min_score_loss);
        }
      }
      if (!checks[k].accepted || piece_refuted[k] ||
          checks[k].score < std::min(a.similarity, b.similarity) - r.merge.min_score_loss)
        continue;
      if (!parts_hold) {
        // Not one face, and the assembly's lower envelope cannot roof both:
        // it would put each plane over the other's part. The images decide
        // which one stays.
        const bool drop_a = a.similarity < b.similarity;
        const RoofPlaneHypothesis &loser = drop_a ? a : b, &winner = drop_a ? b : a;
        merged_away[drop_a ? merges[k].a : merges[k].b] = 1;
        out.rejected.push_back(
            StrFormat("%s: meets a plane that fits the images better in a concave crease, "
                      "without a step (%.2f against %.2f for %s)",
                      loser.id.c_str(), loser.similarity, winner.similarity, winner.id.c_str()));
        ++creases;
        continue;
      }
      RoofPlaneHypothesis m = std::move(proposals[k]);
      if (!checks[k].patch.empty()) m.patch = checks[k].patch;
      m.similarity = checks[k].score;
      m.score = std::abs(SignedArea(m.patch)) * checks[k].score;
      merged_away[merges[k].a] = merged_away[merges[k].b] = 1;
      for (const RoofPlaneHypothesis* p : {&a, &b})
        out.rejected.push_back(p->id + ": merged into one plane (" + m.id + ")");
      if (trace) trace->push_back({m, checks[k]});
      merged.push_back(std::move(m));
    }
    const size_t n_merged = merged.size();
    std::vector<RoofPlaneHypothesis> kept;
    for (size_t i = 0; i < roof_planes.size(); ++i)
      if (!merged_away[i]) kept.push_back(std::move(roof_planes[i]));
    for (RoofPlaneHypothesis& m : merged) kept.push_back(std::move(m));
    roof_planes = std::move(kept);
    out.stages.push_back({"near-coplanar planes merged",
                          StrFormat("%zu pairs proposed, %zu merged, %d apart in a concave "
                                    "crease",
                                    merges.size(), n_merged, creases),
                          Since(t0)});
  }

  // Footprints that still carry no plane (garages, sheds and roofs whose
  // edges gave too few lines for the sweep): a roof model over each,
  // verified face by face like any plane.
  if (!footprints.empty() && r.footprint_flat_roofs) {
    t0 = Clock::now();
    BareFootprintRoofOptions bo;
    bo.models = r.roof_models_over_footprints;
    bo.beyond_ridges = r.roofs_beyond_ridges;
    bo.model = r.roof_models;
    bo.min_gain = r.roof_model_min_gain;
    bo.min_height_m = r.assembly.footprint_min_height_m;
    // The faces are verified like any plane, but for the height margin.
    VerifyOptions model_verify = r.verify;
    model_verify.min_margin = r.roof_model_min_margin;
    std::vector<Segment3> segments;
    for (const Line3D& l : matched.lines) segments.push_back(l.segment);
    int tried = 0, beyond = 0, with_model = 0;
    std::vector<int> model_of;
    std::vector<RoofPlaneHypothesis> roofs = RoofsOverBareFootprints(
        block, images, roof_planes, footprints, segments, bo, r.verify, &tried, &beyond, &model_of);
    const size_t proposed = roofs.size();
    const size_t confirmed = add_verified(
        std::move(roofs), &model_verify, nullptr, [&](std::vector<PlaneVerification>* checks) {
          if (r.roof_models_whole) with_model = JudgeModelsWhole(model_of, model_verify, checks);
        });
    out.stages.push_back(
        {"roofs over bare footprints",
         StrFormat("%d of %zu footprints without a plane, %d beyond the ridge of "
                   "their one face: %zu faces proposed, %zu confirmed (%d with "
                   "their model)",
                   tried, footprints.size(), beyond, proposed, confirmed, with_model),
         Since(t0)});
  }

  if (r.drop_eave_planes) {
    t0 = Clock::now();
    const std::vector<std::string> why = FlatPlanesBeyondEaves(roof_planes, r.eave_planes);
    std::vector<RoofPlaneHypothesis> kept;
    size_t dropped = 0;
    for (size_t i = 0; i < roof_planes.size(); ++i) {
      if (why[i].empty()) {
        kept.push_back(std::move(roof_planes[i]));
      } else {
        out.rejected.push_back(roof_planes[i].id + ": " + why[i]);
        ++dropped;
      }
    }
    roof_planes = std::move(kept);
    out.stages.push_back(
        {"flat planes beyond eaves", StrFormat("%zu dropped", dropped), Since(t0)});
  }

  if (footprints.empty() && r.colour_breaks && r.assembly.split_at_party_lines) {
    t0 = Clock::now();
    const auto breaks = FindColourBreaks(block, images, roof_planes, r.colour_break);
    size_t n_breaks = 0, n_faces = 0;
    for (size_t i = 0; i < roof_planes.size(); ++i) {
      roof_planes[i].colour_breaks = breaks[i];
      n_breaks += breaks[i].size();
      n_faces += !breaks[i].empty();
    }
    out.stages.push_back(
        {"colour breaks",
         StrFormat("%zu on %zu of %zu roof faces", n_breaks, n_faces, roof_planes.size()),
         Since(t0)});
  }

  // Faces found from a hip run on past the corner of the eaves where the
  // hip ends; cut there once the conflicts are settled (CutFacesAtHipFeet).
  if (r.border_clip) {
    t0 = Clock::now();
    const int cut = CutFacesAtHipFeet(&roof_planes, r.eaves);
    out.stages.push_back({"faces cut at the feet of their hips",
                          StrFormat("%d of %zu patches cut", cut, roof_planes.size()), Since(t0)});
  }

  t0 = Clock::now();
  AssemblyResult assembled = AssembleBuildings(roof_planes, block.ground, r.assembly, footprints);
  const double assembly_seconds = Since(t0);
  t0 = Clock::now();
  const std::string support_result = ApplyEdgeSupport(block, images, r, &assembled);
  const RunStage support_stage{"edge support", support_result, Since(t0)};
  std::optional<RunStage> lod1_stage;
  if (!footprints.empty() && r.lod1_fallback) {
    t0 = Clock::now();
    std::vector<Segment3> segments;
    for (const Line3D& l : matched.lines) segments.push_back(l.segment);
    const Lod1Counts n = AddLod1Blocks(footprints, block.ground, block.max_building_height,
                                       segments, r.lod1, &assembled);
    lod1_stage = RunStage{
        "LoD1 blocks",
        StrFormat("%d of %d footprints without a roof", n.blocks, n.footprints_without), Since(t0)};
  }
  out.rejected.insert(out.rejected.end(), assembled.rejected.begin(), assembled.rejected.end());
  std::optional<RunStage> tile_stage;
  if (manifest.aoi) {
    const size_t before = assembled.model.buildings.size();
    const std::vector<std::string> left =
        KeepTileBuildings(*manifest.aoi, frame, footprints, &assembled);
    out.rejected.insert(out.rejected.end(), left.begin(), left.end());
    tile_stage = RunStage{
        "tile",
        StrFormat("%zu of %zu buildings in the tile, ids prefixed %s_",
                  assembled.model.buildings.size(), before, TileTag(*manifest.aoi).c_str()),
        0.0};
  }
  out.buildings = static_cast<int>(assembled.model.buildings.size());
  int lod2_solids = 0;
  for (const Building& b : assembled.model.buildings) {
    const int n = static_cast<int>(b.Solids().size());
    out.solids += n;
    if (b.lod == 1)
      ++out.lod1_buildings;
    else
      lod2_solids += n;
  }
  const int lod2_buildings = out.buildings - out.lod1_buildings;
  if (trace)
    WritePlaneLayer(r.planes, traces, roof_planes, assembled, out.rejected, frame, manifest.crs,
                    r.overwrite);
  out.stages.push_back(
      {"LoD2 buildings",
       StrFormat("%d of %d hypotheses, %d planes used", lod2_solids, assembled.hypotheses,
                 assembled.planes_used) +
           (lod2_solids != lod2_buildings
                ? StrFormat(footprints.empty()
                                ? ", %d buildings (the solids of one adjacent group are its parts)"
                                : ", %d buildings (the solids over one footprint are its parts)",
                            lod2_buildings)
                : std::string()) +
           (assembled.party_cuts > 0 ? StrFormat(", %d cut at party walls", assembled.party_cuts)
                                     : std::string()),
       assembly_seconds});
  out.stages.push_back(support_stage);
  if (lod1_stage) out.stages.push_back(*lod1_stage);
  if (tile_stage) out.stages.push_back(*tile_stage);

  t0 = Clock::now();
  CityModel model = std::move(assembled.model);
  model.TransformVertices([&](const Eigen::Vector3d& v) { return frame.ToCrs(v); });
  WriteRunOutput(std::move(model), manifest.crs, r);
  out.stages.push_back({"write",
                        out.lod1_buildings > 0 ? StrFormat("%d buildings, %d of them LoD1",
                                                           out.buildings, out.lod1_buildings)
                                               : StrFormat("%d buildings", out.buildings),
                        Since(t0)});
  if (!r.report.empty()) WriteReport(r.report, out);
  progress.Update(1.0, "done");
  return out;
}

std::string FormatRunSummary(const RunSummary& s) {
  std::ostringstream o;
  for (const std::string& m : s.messages) o << m << "\n";
  o << StrFormat("%-22s %-44s %9s\n", "stage", "result", "time (s)");
  double total = 0;
  for (const RunStage& st : s.stages) {
    o << StrFormat("%-22s %-44s %9.2f\n", st.name.c_str(), st.result.c_str(), st.seconds);
    total += st.seconds;
  }
  o << StrFormat("%-22s %-44s %9.2f\n", "total", "", total);
  if (!s.rejected.empty()) {
    std::map<std::string, int> kinds;
    for (const std::string& r : s.rejected) ++kinds[ReasonKind(r)];
    o << "Not built (" << s.rejected.size() << "; -report FILE lists each):\n";
    for (const auto& [k, n] : kinds) o << StrFormat("  %5d  %s\n", n, k.c_str());
  }
  return o.str();
}

}  // namespace roofsweep
