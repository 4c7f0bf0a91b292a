// Judges the half-plane sweep alone on a simulated block: the true 3D roof
// edges are the input lines, and each line side's result is compared with
// the true roof face attached there (if any).
//
//   rs_sweep_sim_eval [preset=realistic] [seed=1] [image cache folder] [option=value...]
//
// Prints acceptance and the angle error (median, 90th percentile) per roof
// material pattern and overall.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "algorithms/simulate/presets.h"
#include "algorithms/simulate/scene_truth.h"
#include "algorithms/sweep/half_plane_family.h"
#include "algorithms/sweep/sweep_half_planes.h"

using namespace roofsweep;

namespace {

double Percentile(std::vector<double> v, double q) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  return v[static_cast<size_t>(std::min<double>(v.size() - 1, std::floor(q * v.size())))];
}

struct Tally {
  int sides = 0, accepted = 0;
  std::vector<double> errors;      // accepted sides, |theta - truth| deg
  std::vector<double> all_errors;  // every swept side with a face
  std::vector<double> sims, curvatures;
};

}  // namespace

int main(int argc, char** argv) {
  const std::string preset = argc > 1 ? argv[1] : "realistic";
  sim::SimulationOptions so = sim::SimulationPreset(preset);
  if (argc > 2) so.seed = std::stoull(argv[2]);
  // Folder for the rendered images (a development cache, not a format).
  const std::string cache = argc > 3 ? argv[3] : "";
  NullProgress progress;
  auto t0 = std::chrono::steady_clock::now();
  // Simulate() without the rendering, so that the images can come from a
  // cache (rendering the realistic block takes minutes).
  sim::SimulationResult r;
  sim::SceneOptions scene_options = so.scene;
  {
    const Eigen::Vector2d cover = sim::FlightCoverage(so.cameras);
    scene_options.extent_x = cover.x();
    scene_options.extent_y = cover.y();
    const Eigen::Vector4d area(-cover.x() / 2, -cover.y() / 2, cover.x() / 2, cover.y() / 2);
    scene_options.visibility_views.clear();
    for (const sim::SimulatedView& v :
         sim::LayoutCameras(area, scene_options.ground_z, so.cameras, so.seed))
      scene_options.visibility_views.push_back({v.camera, v.pose});
  }
  r.scene = sim::GenerateScene(scene_options, so.seed);
  r.truth = sim::TruthOf(r.scene);
  r.views = sim::LayoutCameras(r.scene.area, r.scene.ground.z, so.cameras, so.seed);
  {
    std::unique_ptr<sim::Renderer> renderer;
    for (size_t i = 0; i < r.views.size(); ++i) {
      const std::string path = cache.empty()
                                   ? std::string()
                                   : cache + "/" + preset + "_" + std::to_string(so.seed) + "_" +
                                         std::to_string(i) + ".png";
      cv::Mat image;
      if (!path.empty() && std::ifstream(path).good()) {
        image = cv::imread(path, cv::IMREAD_COLOR);
        if (!image.empty()) cv::cvtColor(image, image, cv::COLOR_BGR2RGB);
      }
      if (image.empty()) {
        if (!renderer) renderer = std::make_unique<sim::Renderer>(r.scene, so.render);
        image = renderer->Render(r.views[i], static_cast<int>(i), so.seed);
        if (!path.empty()) {
          cv::Mat bgr;
          cv::cvtColor(image, bgr, cv::COLOR_RGB2BGR);
          cv::imwrite(path, bgr);
        }
      }
      r.images.push_back(image);
    }
  }
  auto t1 = std::chrono::steady_clock::now();

  Block block;
  block.source = "simulated " + preset;
  std::vector<cv::Mat> images;
  for (size_t i = 0; i < r.views.size(); ++i) {
    block.cameras.push_back(r.views[i].camera);
    View v;
    v.name = r.views[i].name;
    v.camera = static_cast<int>(i);
    v.pose = r.views[i].pose;
    block.views.push_back(v);
    cv::Mat f;
    r.images[i].convertTo(f, CV_32FC3, 1.0 / 255.0);
    images.push_back(f);
  }
  std::vector<SweepLine> lines;
  std::vector<const sim::TrueEdge*> edges;
  for (const sim::TrueEdge& e : r.truth.edges) {
    if (!sim::IsRoofEdge(e.kind)) continue;
    lines.push_back({Segment3{e.a, e.b}, {}});
    edges.push_back(&e);
  }
  // Option overrides: name=value after the positional arguments.
  SweepOptions options;
  for (int i = 4; i < argc; ++i) {
    const std::string arg = argv[i];
    const size_t eq = arg.find('=');
    if (eq == std::string::npos) continue;
    const std::string key = arg.substr(0, eq);
    const double value = std::stod(arg.substr(eq + 1));
    if (key == "ncc_radius")
      options.ncc_radius = static_cast<int>(value);
    else if (key == "band_width_px")
      options.band_width_px = value;
    else if (key == "min_similarity")
      options.min_similarity = value;
    else if (key == "min_curvature")
      options.min_curvature = value;
    else if (key == "min_views")
      options.min_views = static_cast<int>(value);
    else if (key == "max_points")
      options.max_points = static_cast<int>(value);
    else if (key == "poi_canny_low")
      options.poi_canny_low = value;
    else if (key == "poi_canny_high")
      options.poi_canny_high = value;
    else if (key == "outlier_min_score")
      options.outlier_min_score = value;
    else if (key == "valid_view_ratio")
      options.valid_view_ratio = value;
    else if (key == "coarse_step_deg")
      options.coarse_step_deg = value;
    else {
      std::fprintf(stderr, "unknown option %s\n", key.c_str());
      return 2;
    }
  }
  const std::vector<HalfPlane> result = SweepHalfPlanes(block, images, lines, options, progress);
  auto t2 = std::chrono::steady_clock::now();

  std::map<std::string, Tally> by_pattern;
  Tally all, free_sides;
  std::map<std::string, int> reasons;
  int unseen = 0;
  for (const HalfPlane& h : result) {
    if (h.reference_view < 0) {
      ++unseen;
      continue;
    }
    const sim::TrueEdge& e = *edges[h.line];
    const auto family = HalfPlaneFamily::Make(lines[h.line].segment, h.side);
    if (!family) continue;
    // The true face on this side: a roof plane of the building containing
    // the edge and covering a point 0.3 m into the side.
    const sim::RoofPlane* face = nullptr;
    double truth = 0;
    for (const sim::RoofPlane& rp : r.truth.roof_planes) {
      if (rp.building != e.building) continue;
      const Eigen::Vector3d n = rp.plane.head<3>();
      if (std::abs(n.dot(e.a) + rp.plane(3)) > 0.05 || std::abs(n.dot(e.b) + rp.plane(3)) > 0.05)
        continue;
      const double theta = family->AngleOfNormal(n);
      const Eigen::Vector3d p = family->line().At(0.5) + 0.3 * family->Direction(theta);
      if (!rp.polygon.ContainsXY(p.head<2>())) continue;
      face = &rp;
      truth = theta * 180 / M_PI;
      break;
    }
    if (!face) {
      ++free_sides.sides;
      free_sides.accepted += h.accepted;
      continue;
    }
    const int m = r.scene.surface_materials.at(face->building).at(face->surface);
    const std::string pattern = sim::PatternName(r.scene.materials.at(m).pattern);
    for (Tally* t : {&by_pattern[pattern], &all}) {
      ++t->sides;
      if (h.accepted) {
        ++t->accepted;
        t->errors.push_back(std::abs(h.theta_deg - truth));
      }
      if (!h.profile.empty()) {
        t->all_errors.push_back(std::abs(h.theta_deg - truth));
        t->sims.push_back(h.similarity);
        t->curvatures.push_back(h.curvature);
      }
    }
    if (!h.accepted) ++reasons[h.reason.substr(0, h.reason.find_first_of("(0123456789"))];
  }
  std::printf("preset %s seed %llu: %zu views, %zu roof edges, simulate %.1f s, sweep %.1f s\n",
              preset.c_str(), static_cast<unsigned long long>(so.seed), block.views.size(),
              lines.size(), std::chrono::duration<double>(t1 - t0).count(),
              std::chrono::duration<double>(t2 - t1).count());
  std::printf("%-14s %6s %9s %11s %11s %8s | swept: %10s %8s %8s %8s\n", "face pattern", "sides",
              "accepted", "median err", "p90 err", "<=2 deg", "median err", "<=2 deg", "med sim",
              "med Sim''");
  auto row = [](const std::string& name, const Tally& t) {
    const double within =
        t.errors.empty() ? 0.0 : std::count_if(t.errors.begin(), t.errors.end(), [](double e) {
                                   return e <= 2.0;
                                 }) / static_cast<double>(t.errors.size());
    const double within_all = t.all_errors.empty()
                                  ? 0.0
                                  : std::count_if(t.all_errors.begin(), t.all_errors.end(),
                                                  [](double e) { return e <= 2.0; }) /
                                        static_cast<double>(t.all_errors.size());
    std::printf("%-14s %6d %8.1f%% %10.2f° %10.2f° %7.1f%% | %9.2f° %7.1f%% %8.3f %8.1f\n",
                name.c_str(), t.sides, t.sides ? 100.0 * t.accepted / t.sides : 0.0,
                Percentile(t.errors, 0.5), Percentile(t.errors, 0.9), 100 * within,
                Percentile(t.all_errors, 0.5), 100 * within_all, Percentile(t.sims, 0.5),
                Percentile(t.curvatures, 0.5));
  };
  for (const auto& [name, t] : by_pattern) row(name, t);
  row("all faces", all);
  std::printf("sides without a roof face: %d, accepted %d (%.1f%%); sides seen by no view: %d\n",
              free_sides.sides, free_sides.accepted,
              free_sides.sides ? 100.0 * free_sides.accepted / free_sides.sides : 0.0, unseen);
  std::printf("rejections on sides with a face:\n");
  for (const auto& [reason, n] : reasons) std::printf("  %5d  %s\n", n, reason.c_str());
  return 0;
}
