#include "plugin/cli/simulate_lib.h"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

#include "algorithms/core/error.h"
#include "algorithms/geometry/rotation.h"
#include "io/citymodel/citymodel_io.h"
#include "io/citymodel/ogr_citymodel.h"
#include "io/citymodel/segments_json.h"
#include "io/citymodel/visibility_json.h"
#include "io/core/block_manifest.h"
#include "io/core/image_io.h"
#include "io/core/local_frame.h"
#include "io/orientation/block_source.h"

namespace fs = std::filesystem;

namespace roofsweep {
namespace {

// Removes a half-written output folder unless the run completed.
class TempFolder {
 public:
  explicit TempFolder(const std::string& final_dir) {
    const fs::path target = fs::absolute(final_dir);
    path_ = (target.parent_path() /
             ("." + target.filename().string() + ".tmp" + std::to_string(::getpid())))
                .string();
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempFolder() {
    std::error_code ec;
    if (!committed_) fs::remove_all(path_, ec);
  }
  const std::string& path() const { return path_; }
  void CommitTo(const std::string& final_dir) {
    std::error_code ec;
    fs::remove_all(final_dir, ec);
    fs::rename(path_, final_dir);
    committed_ = true;
  }

 private:
  std::string path_;
  bool committed_ = false;
};

void CheckOutputFolder(const std::string& dir, bool overwrite) {
  if (dir.empty()) throw Error("simulate: no output folder given (-o DIR)");
  const fs::path p = fs::absolute(dir);
  if (!fs::is_directory(p.parent_path())) {
    throw Error(dir + ": the folder it would be created in does not exist");
  }
  if (fs::exists(p) && !overwrite) {
    throw Error(dir + ": already exists; use -overwrite to replace it");
  }
}

void WriteText(const std::string& path, const std::string& text) {
  std::ofstream f(path);
  f << text;
  if (!f) throw Error(path + ": cannot write");
}

std::string CameraYaml(const Camera& c) {
  // orthority's interior parameters: focal length and sensor size in the same
  // unit (mm), principal point as an offset from the image centre in units
  // of the larger image side (see io/orientation/orthority_yaml.cc).
  const double px_mm = c.pixel_size_mm > 0 ? c.pixel_size_mm : 0.0046;
  const double s = std::max(c.width, c.height);
  char buf[1024];
  std::snprintf(buf, sizeof buf,
                "%s:\n    type: %s\n    im_size: [%d, %d]\n    focal_len: [%.12g, %.12g]\n"
                "    sensor_size: [%.12g, %.12g]\n    cx: %.15g\n    cy: %.15g\n",
                c.id.c_str(), c.HasDistortion() ? "brown" : "pinhole", c.width, c.height,
                c.fx * px_mm, c.fy * px_mm, c.width * px_mm, c.height * px_mm,
                (c.cx - c.width / 2.0) / s, (c.cy - c.height / 2.0) / s);
  std::string out = buf;
  if (c.HasDistortion()) {
    std::snprintf(buf, sizeof buf,
                  "    k1: %.15g\n    k2: %.15g\n    k3: %.15g\n    p1: %.15g\n    p2: %.15g\n",
                  c.k1, c.k2, c.k3, c.p1, c.p2);
    out += buf;
  }
  return out;
}

// The simulated terrain as a DTM in the block's CRS: 1 m cells over the
// ground every view sees, nadir or oblique, with a margin.
void WriteTerrainDtm(const sim::SimulationResult& sim, const LocalFrame& frame,
                     const std::string& crs, const std::string& path) {
  const sim::GroundLayout& g = sim.scene.ground;
  Eigen::Vector4d box = sim.scene.area;
  for (const sim::SimulatedView& v : sim.views) {
    const Eigen::Vector3d& C = v.pose.C;
    // Oblique views look up to about their height away from below them.
    const double reach = 1.2 * std::max(0.0, C.z() - g.HeightAt(C.head<2>()));
    const Eigen::Vector2d r = Eigen::Vector2d::Constant(reach);
    box.head<2>() = box.head<2>().cwiseMin(C.head<2>() - r).eval();
    box.tail<2>() = box.tail<2>().cwiseMax(C.head<2>() + r).eval();
  }
  Eigen::Vector2d lo(std::numeric_limits<double>::infinity(),
                     std::numeric_limits<double>::infinity());
  Eigen::Vector2d hi = -lo;
  for (double x : {box(0), box(2)})
    for (double y : {box(1), box(3)}) {
      const Eigen::Vector2d p = frame.ToCrs(Eigen::Vector3d(x, y, g.HeightAt({x, y}))).head<2>();
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  const double cell = 1.0;
  lo = (lo.array() / cell).floor().matrix() * cell;
  hi = (hi.array() / cell).ceil().matrix() * cell;
  const int cols = static_cast<int>(std::lround((hi.x() - lo.x()) / cell));
  const int rows = static_cast<int>(std::lround((hi.y() - lo.y()) / cell));
  cv::Mat z(rows, cols, CV_32FC1);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      const Eigen::Vector2d e(lo.x() + (c + 0.5) * cell, hi.y() - (r + 0.5) * cell);
      // The terrain under this cell centre, found at the origin's height:
      // the local vertical leans against the CRS's by 8e-5 rad 500 m out,
      // so the height is off by slope x lean x height difference, under a
      // millimetre (0.8 mm at most against an exact fixed point, measured
      // on a 1 km DTM at 10 %).
      const Eigen::Vector3d l = frame.ToLocal(Eigen::Vector3d(e.x(), e.y(), frame.OriginCrs().z()));
      z.at<float>(r, c) = static_cast<float>(
          frame.ToCrs(Eigen::Vector3d(l.x(), l.y(), g.HeightAt(l.head<2>()))).z());
    }
  WriteHeightRaster(path, z, {lo.x(), cell, 0, hi.y(), 0, -cell}, crs);
}

}  // namespace

SimulateSummary RunSimulate(const SimulateRequest& r, Progress& progress) {
  CheckOutputFolder(r.output_dir, r.overwrite);
  sim::SimulationOptions o = sim::SimulationPreset(r.preset);
  o.seed = r.seed;
  if (r.strips > 0) o.cameras.strips = r.strips;
  if (r.images_per_strip > 0) o.cameras.images_per_strip = r.images_per_strip;
  if (r.image_size > 0) o.cameras.image_width = o.cameras.image_height = r.image_size;
  if (r.gsd > 0) o.cameras.gsd = r.gsd;
  if (r.buildings >= 0) o.scene.building_count = r.buildings;
  if (r.obliques) o.cameras.obliques = true;
  if (r.forward_overlap >= 0) {
    // Below a half, part of each image lies in no neighbour: a strip no
    // longer sees all its ground in stereo. Near 1 the baseline vanishes.
    if (!(r.forward_overlap >= 0.5 && r.forward_overlap < 0.95))
      throw Error("simulate: the forward overlap must be 50..95 %");
    o.cameras.forward_overlap = r.forward_overlap;
  }
  if (r.side_overlap >= 0) {
    if (!(r.side_overlap < 0.95)) throw Error("simulate: the side overlap must be 0..95 %");
    o.cameras.side_overlap = r.side_overlap;
  }
  if (!std::isfinite(r.terrain_slope_percent) || !std::isfinite(r.terrain_aspect_deg) ||
      r.terrain_slope_percent < 0 || r.terrain_slope_percent > 50)
    throw Error("simulate: the terrain slope must be 0..50 %");
  if (r.terrain_slope_percent > 0) {
    if (!r.citygml.empty())
      throw Error("simulate: a terrain slope needs a generated town, not -citygml");
    const double a = r.terrain_aspect_deg * M_PI / 180, s = r.terrain_slope_percent / 100;
    // The ground falls towards the aspect, so it rises the other way.
    o.scene.ground_slope = -s * Eigen::Vector2d(std::sin(a), std::cos(a));
  }
  if (!std::isfinite(r.terrain_relief_m) || r.terrain_relief_m < 0 || r.terrain_relief_m > 50)
    throw Error("simulate: the terrain relief must be 0..50 m");
  if (r.terrain_relief_m > 0) {
    if (!r.citygml.empty())
      throw Error("simulate: a terrain relief needs a generated town, not -citygml");
    o.scene.terrain_relief_m = r.terrain_relief_m;
  }
  std::string ext = r.image_format.empty() ? (r.preset == "easy" ? "png" : "jpg") : r.image_format;
  if (ext == "jpeg") ext = "jpg";
  if (ext != "jpg" && ext != "tif" && ext != "png") {
    throw Error("simulate: image format '" + ext + "' is not one of jpg, tif, png");
  }

  // A real model is rendered in its own CRS at its own place: the local
  // frame's origin is the model's plan centre at its lowest point.
  std::string crs = r.crs;
  Eigen::Vector3d origin = r.origin;
  CityModel input;
  if (!r.citygml.empty()) {
    input = ReadCityModel(r.citygml);
    // The renderer and the ground truth take each building as one set of
    // surfaces, as eval compares them.
    MergeBuildingParts(&input);
    if (r.aoi) {
      const Eigen::Vector4d w = *r.aoi;
      std::vector<Building> kept;
      for (Building& b : input.buildings) {
        Eigen::Vector2d c = Eigen::Vector2d::Zero();
        int n = 0;
        for (const Surface& s : b.surfaces)
          for (const Polygon3& p : s.polygons)
            for (const auto& v : p.exterior) c += v.head<2>(), ++n;
        if (n == 0) continue;
        c /= n;
        if (c.x() >= w(0) && c.x() <= w(2) && c.y() >= w(1) && c.y() <= w(3)) {
          kept.push_back(std::move(b));
        }
      }
      input.buildings = std::move(kept);
    }
    if (input.buildings.empty()) {
      throw Error(r.citygml + ": no buildings to simulate" + (r.aoi ? " inside -aoi" : ""));
    }
    if (!input.crs.empty()) crs = input.crs;
    const auto b = input.Bounds();
    origin = Eigen::Vector3d((b(0) + b(3)) / 2, (b(1) + b(4)) / 2, b(2));
  }
  const LocalFrame frame(crs, origin);
  if (!r.citygml.empty()) {
    input.TransformVertices([&](const Eigen::Vector3d& v) { return frame.ToLocal(v); });
    input.crs.clear();
  }

  TempFolder tmp(r.output_dir);
  const auto t0 = std::chrono::steady_clock::now();
  SubProgress render(progress, 0.0, 0.8);
  const sim::SimulationResult sim = sim::Simulate(o, render, r.citygml.empty() ? nullptr : &input);
  if (sim.truth.city.buildings.empty() && r.citygml.empty() && o.scene.building_count > 0) {
    // The generator places a building only where two views see all of it.
    throw Error(
        "simulate: no building fits inside two views; use larger images (-size), a "
        "coarser -gsd or more -views");
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  const std::string dir = tmp.path();
  fs::create_directories(dir + "/images");
  fs::create_directories(dir + "/orientation");
  std::string opk = "imageName X Y Z Omega Phi Kappa\n";
  for (size_t i = 0; i < sim.views.size(); ++i) {
    const sim::SimulatedView& v = sim.views[i];
    WriteImage(dir + "/images/" + v.name + "." + ext, sim.images[i], r.jpeg_quality);
    const Eigen::Vector3d pos = frame.ToCrs(v.pose.C);
    // Camera-to-grid rotation: camera-to-ENU, then ENU back to grid axes.
    const Eigen::Matrix3d r_grid = frame.GridToLocal(pos).transpose() * CvToPatb(v.pose.R);
    const Eigen::Vector3d a = RotationToOpk(r_grid);
    char line[256];
    std::snprintf(line, sizeof line, "%s %.6f %.6f %.6f %.10f %.10f %.10f\n", v.name.c_str(),
                  pos.x(), pos.y(), pos.z(), a(0), a(1), a(2));
    opk += line;
    ReportOrCancel(progress, 0.8 + 0.15 * (i + 1) / sim.views.size());
  }
  WriteText(dir + "/orientation/opk.txt", opk);
  // One camera: the layout gives every view the same interior orientation.
  Camera cam = sim.views.front().camera;
  cam.id = "simulated";
  WriteText(dir + "/orientation/camera.yaml", CameraYaml(cam));

  ImportOptions io;
  io.crs = crs;
  io.camera_file = dir + "/orientation/camera.yaml";
  io.image_dir = dir + "/images";
  if (sim.scene.ground.slope.isZero() && sim.scene.ground.Planar()) {
    io.ground_height = frame.ToCrs(Eigen::Vector3d(0, 0, sim.scene.ground.z)).z();
  } else {
    WriteTerrainDtm(sim, frame, crs, dir + "/dtm.tif");
    io.dtm = dir + "/dtm.tif";
  }
  BlockManifest manifest = ImportBlock("opk", {dir + "/orientation/opk.txt"}, io);
  WriteManifest(manifest, dir + "/block.json", false);

  CityModel truth = sim.truth.city;
  truth.TransformVertices([&](const Eigen::Vector3d& v) { return frame.ToCrs(v); });
  truth.crs = crs;
  WriteCityModel(truth, dir + "/groundtruth.gml");

  // The true footprints (each building's ground surfaces), the input `run`
  // takes as building footprints; not referenced from block.json, so the
  // default evaluation stays without them.
  std::vector<LayerFeature> footprints;
  for (const Building& b : truth.buildings) {
    LayerFeature f;
    for (const Surface& sf : b.surfaces)
      if (sf.type == SurfaceType::kGround)
        f.polygons.insert(f.polygons.end(), sf.polygons.begin(), sf.polygons.end());
    if (f.polygons.empty()) continue;
    f.strings["id"] = b.id;
    footprints.push_back(std::move(f));
  }
  FeatureLayerOptions fo;
  fo.crs = crs;
  fo.description = "simulated building footprints (the true ground surfaces)";
  WriteFeatureLayer(dir + "/footprints.gpkg", "footprints", LayerGeometry::kMultiPolygonZ,
                    footprints, fo);

  SegmentSet edges;
  edges.crs = crs;
  for (const sim::TrueEdge& e : sim.truth.edges) {
    LabelledSegment s;
    s.segment = {frame.ToCrs(e.a), frame.ToCrs(e.b)};
    s.kind = sim::EdgeKindName(e.kind);
    s.building = e.building;  // rms_px stays NaN: a true edge has no residual
    edges.segments.push_back(std::move(s));
  }
  WriteSegmentsJson(edges, dir + "/groundtruth_edges.json", false);

  // What each view sees of each true roof polygon, for `eval`'s
  // completeness over the roofs the images show (ScoreSeenPlanes).
  RoofVisibilityFile vis;
  vis.crs = crs;
  for (const sim::SimulatedView& v : sim.views) vis.views.push_back(v.name);
  for (const sim::RoofPolygonVisibility& p : sim.roof_visibility)
    vis.polygons.push_back({truth.buildings[p.building].id, frame.ToCrs(p.centroid), p.seen});
  WriteRoofVisibilityJson(vis, dir + "/groundtruth_visibility.json", false);

  SimulateSummary s;
  s.views = static_cast<int>(sim.views.size());
  s.buildings = static_cast<int>(truth.buildings.size());
  s.roof_planes = static_cast<int>(sim.truth.roof_planes.size());
  s.edges = static_cast<int>(edges.segments.size());
  s.gsd_m = o.cameras.gsd;
  s.seconds_render = seconds;

  nlohmann::json meta = {
      {"preset", r.preset},
      {"seed", r.seed},
      {"citygml", r.citygml.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.citygml)},
      {"crs", crs},
      {"origin", {origin.x(), origin.y(), origin.z()}},
      {"views", s.views},
      {"image_size", {cam.width, cam.height}},
      {"gsd_m", s.gsd_m},
      {"forward_overlap", o.cameras.forward_overlap},
      {"side_overlap", o.cameras.side_overlap},
      {"buildings", s.buildings},
      {"roof_planes", s.roof_planes},
      {"edges", s.edges},
      {"image_format", ext},
      {"jpeg_quality", ext == "jpg" ? r.jpeg_quality : 0},
      {"terrain_slope_percent", r.terrain_slope_percent},
      {"terrain_aspect_deg", r.terrain_aspect_deg},
      {"terrain_relief_m", r.terrain_relief_m}};
  WriteText(dir + "/simulation.json", meta.dump(2) + "\n");
  tmp.CommitTo(r.output_dir);
  ReportOrCancel(progress, 1.0);
  return s;
}

}  // namespace roofsweep
