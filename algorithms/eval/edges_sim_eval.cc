// rs_edges_sim_eval: measures the 2D segment detectors against the
// simulator's ground truth (issue 4). Simulates the `realistic` preset for
// a few seeds, runs ExtractSegments with the max, Di Zenzo and grey methods
// (and max without the segments marked as texture, as matching takes them)
// and OpenCV's LSD on every view, scores them with EvaluateSegments2D
// (visibility from the renderer's depth map) and prints one table.
//
//   rs_edges_sim_eval [--preset realistic] [--seeds 1,2,3] [--size PX] [--strips N]
//                     [--views N] [--methods max-tex,max-tex+2x,...]
//
// A plain program, not a test: it takes minutes, and its figures are
// reported, not asserted.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <opencv2/imgproc.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "algorithms/core/progress.h"
#include "algorithms/edges/extract_segments.h"
#include "algorithms/eval/segments2d_eval.h"
#include "algorithms/simulate/presets.h"
#include "algorithms/simulate/renderer.h"

namespace roofsweep {
namespace {

using sim::EdgeKind;

struct Totals {
  eval::LengthScore roof;
  std::map<EdgeKind, eval::LengthScore> kinds, kinds_interior;
  eval::LengthScore roof_interior;  // without 5 px at either end of each edge
  // Outline (eave, verge) of the roofs coloured to match the lawn's
  // luminance, and ridges/hips/valleys/breaks of roofs whose faces all share
  // one material (only the shading separates the faces).
  eval::LengthScore isoluminant_outline, isoluminant_inner, uniform_inner;
  double detected = 0, on_truth = 0;
  // Detected length on no true edge, by what the faces on either side of
  // the segment's midpoint (3 px away) are: a tree or prop on either side;
  // the same face on both (texture, shadow, material border inside a face);
  // two different faces (an edge of the scene missed by the tolerances).
  double false_tree_prop = 0, false_in_face = 0, false_between_faces = 0;
  long segments = 0;
  int images = 0;
  double ms = 0;
};

void Add(eval::LengthScore& a, const eval::LengthScore& b) {
  a.length_px += b.length_px;
  a.covered_px += b.covered_px;
}

bool IsInner(EdgeKind k) {
  return k == EdgeKind::kRidge || k == EdgeKind::kHip || k == EdgeKind::kValley ||
         k == EdgeKind::kBreak;
}

// OpenCV's LSD on the grey image; its coordinates put the origin at the
// centre of the top-left pixel, roofsweep's at the corner: +0.5.
Segments2D Lsd(const cv::Mat& rgb8, double min_length) {
  cv::Mat grey;
  cv::cvtColor(rgb8, grey, cv::COLOR_RGB2GRAY);
  cv::Ptr<cv::LineSegmentDetector> lsd = cv::createLineSegmentDetector(cv::LSD_REFINE_STD);
  std::vector<cv::Vec4f> lines;
  lsd->detect(grey, lines);
  Segments2D out;
  for (const cv::Vec4f& l : lines) {
    Segment2D s;
    s.p0 = Eigen::Vector2d(l[0] + 0.5, l[1] + 0.5);
    s.p1 = Eigen::Vector2d(l[2] + 0.5, l[3] + 0.5);
    s.method = GradientMethod::kGrey;
    if (s.Length() >= min_length) out.push_back(s);
  }
  return out;
}

std::vector<int> ParseList(const std::string& s) {
  std::vector<int> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ',')) out.push_back(std::atoi(item.c_str()));
  return out;
}

double Pct(const eval::LengthScore& s) { return s.length_px > 0 ? 100.0 * s.Ratio() : -1; }

void PrintCell(double pct) {
  if (pct < 0)
    std::printf(" %7s", "-");
  else
    std::printf(" %6.1f%%", pct);
}

int Main(int argc, char** argv) {
  std::vector<int> seeds = {1, 2, 3};
  int size = 0, strips = 0, views = 0;
  std::string preset = "realistic", only;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i], v = argv[i + 1];
    if (a == "--seeds")
      seeds = ParseList(v);
    else if (a == "--preset")
      preset = v;
    else if (a == "--size")
      size = std::atoi(v.c_str());
    else if (a == "--strips")
      strips = std::atoi(v.c_str());
    else if (a == "--views")
      views = std::atoi(v.c_str());
    else if (a == "--methods")
      only = v;
    else {
      std::fprintf(stderr, "unknown option %s\n", a.c_str());
      return 2;
    }
  }
  // "+2x": with the coarse-scale fusion (EdgeOptions::coarse_fusion).
  std::vector<std::string> methods = {"max",     "max-tex", "max+2x", "max-tex+2x",
                                      "dizenzo", "grey",    "lsd"};
  if (!only.empty()) {
    const std::vector<std::string> known = methods;
    methods.clear();
    for (size_t from = 0; from <= only.size();) {
      const size_t comma = std::min(only.find(',', from), only.size());
      const std::string m = only.substr(from, comma - from);
      if (std::find(known.begin(), known.end(), m) == known.end()) {
        std::fprintf(stderr, "unknown method '%s' in --methods\n", m.c_str());
        return 2;
      }
      methods.push_back(m);
      from = comma + 1;
    }
  }
  std::map<std::string, Totals> totals;
  std::set<EdgeKind> seen_kinds;
  double isoluminant_buildings = 0, buildings = 0;
  for (int seed : seeds) {
    sim::SimulationOptions o = sim::SimulationPreset(preset);
    o.seed = static_cast<uint64_t>(seed);
    if (size > 0) o.cameras.image_width = o.cameras.image_height = size;
    if (strips > 0) o.cameras.strips = strips;
    if (views > 0) o.cameras.images_per_strip = views;
    NullProgress np;
    const auto t0 = std::chrono::steady_clock::now();
    const sim::SimulationResult r = sim::Simulate(o, np);
    const double sim_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const sim::Renderer renderer(r.scene, o.render);

    // Building subsets from the materials (the truth has no colours).
    const size_t nb = r.scene.city.buildings.size();
    std::vector<bool> isoluminant(nb, false), uniform(nb, false);
    for (size_t b = 0; b < nb; ++b) {
      std::set<int> roof_mats;
      const auto& surfaces = r.scene.city.buildings[b].surfaces;
      for (size_t s = 0; s < surfaces.size(); ++s) {
        if (surfaces[s].type != SurfaceType::kRoof) continue;
        const int m = r.scene.surface_materials[b][s];
        roof_mats.insert(m);
        if (r.scene.materials[static_cast<size_t>(m)].name.find("isoluminant") != std::string::npos)
          isoluminant[b] = true;
      }
      uniform[b] = roof_mats.size() == 1;
      isoluminant_buildings += isoluminant[b];
    }
    buildings += nb;
    std::fprintf(
        stderr,
        "seed %d: %zu buildings (%d isoluminant), %zu views of %d x %d, %zu true "
        "edges, simulated in %.1f s\n",
        seed, nb, static_cast<int>(std::count(isoluminant.begin(), isoluminant.end(), true)),
        r.views.size(), o.cameras.image_width, o.cameras.image_height, r.truth.edges.size(), sim_s);

    for (size_t v = 0; v < r.views.size(); ++v) {
      const sim::SimulatedView& view = r.views[v];
      const sim::GeometryMaps maps = renderer.RenderGeometry(view.camera, view.pose);
      const eval::VisibilityFn visible = eval::DepthMapVisibility(maps.depth);
      cv::Mat image;
      r.images[v].convertTo(image, CV_32FC3, 1.0 / 255.0);
      for (const std::string& m : methods) {
        const auto t1 = std::chrono::steady_clock::now();
        Segments2D segments;
        if (m == "lsd") {
          segments = Lsd(r.images[v], 15.0);
        } else {
          EdgeOptions eo;
          eo.method = m.rfind("max", 0) == 0 ? GradientMethod::kMax
                      : m == "dizenzo"       ? GradientMethod::kDiZenzo
                                             : GradientMethod::kGrey;
          eo.coarse_fusion = m.find("+2x") != std::string::npos;
          segments = ExtractSegments(image, eo);
          // What matching takes (MatchOptions::match_texture).
          if (m.rfind("max-tex", 0) == 0)
            segments.erase(std::remove_if(segments.begin(), segments.end(),
                                          [](const Segment2D& g) { return g.texture; }),
                           segments.end());
        }
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t1)
                .count();
        const eval::Segment2DScores s =
            eval::EvaluateSegments2D(view.camera, view.pose, r.truth.edges, visible, segments);
        Totals& t = totals[m];
        Add(t.roof, s.roof);
        Add(t.roof_interior, s.roof_interior);
        for (const auto& [k, score] : s.per_kind_interior) Add(t.kinds_interior[k], score);
        for (const auto& [k, score] : s.per_kind) {
          Add(t.kinds[k], score);
          seen_kinds.insert(k);
        }
        for (size_t e = 0; e < r.truth.edges.size(); ++e) {
          const sim::TrueEdge& edge = r.truth.edges[e];
          if (edge.building < 0) continue;
          const size_t b = static_cast<size_t>(edge.building);
          const bool outline = edge.kind == EdgeKind::kEave || edge.kind == EdgeKind::kVerge;
          if (isoluminant[b] && outline) Add(t.isoluminant_outline, s.per_edge[e]);
          if (isoluminant[b] && IsInner(edge.kind)) Add(t.isoluminant_inner, s.per_edge[e]);
          if (uniform[b] && IsInner(edge.kind)) Add(t.uniform_inner, s.per_edge[e]);
        }
        for (size_t j = 0; j < segments.size(); ++j) {
          const double miss = s.per_segment[j].length_px - s.per_segment[j].covered_px;
          if (miss <= 0) continue;
          const Segment2D& seg = segments[j];
          auto face_at = [&](const Eigen::Vector2d& p) {
            const int x = static_cast<int>(std::floor(p.x())),
                      y = static_cast<int>(std::floor(p.y()));
            if (x < 0 || y < 0 || x >= maps.face.cols || y >= maps.face.rows) return -1;
            return maps.face.at<int>(y, x);
          };
          const int fl = face_at(seg.Midpoint() + 3.0 * seg.LeftNormal());
          const int fr = face_at(seg.Midpoint() - 3.0 * seg.LeftNormal());
          auto tree_or_prop = [&](int f) {
            if (f < 0) return false;
            const sim::FaceKind k = renderer.faces()[static_cast<size_t>(f)].kind;
            return k == sim::FaceKind::kTreeCrown || k == sim::FaceKind::kTreeTrunk ||
                   k == sim::FaceKind::kProp;
          };
          if (tree_or_prop(fl) || tree_or_prop(fr)) {
            t.false_tree_prop += miss;
          } else if (fl == fr) {
            t.false_in_face += miss;
          } else {
            t.false_between_faces += miss;
          }
        }
        t.detected += s.detected_px;
        t.on_truth += s.detected_on_truth_px;
        t.segments += s.segments;
        t.images += 1;
        t.ms += ms;
      }
    }
  }

  std::printf("\n%s preset, seeds", preset.c_str());
  for (int s : seeds) std::printf(" %d", s);
  std::printf(
      "; %d images per method; tolerance 1.5 px / 5 deg; true edges >= 15 px, visible "
      "(depth map)\n\n",
      totals[methods[0]].images);
  std::printf("%-8s %7s %7s %7s %7s %8s", "method", "recall", "prec.", "seg/img", "ms/img",
              "iso-out");
  std::printf(" %7s %7s", "iso-in", "unif-in");
  for (EdgeKind k : seen_kinds) std::printf(" %7.7s", sim::EdgeKindName(k));
  std::printf("\n");
  for (const std::string& m : methods) {
    const Totals& t = totals[m];
    std::printf("%-8s", m.c_str());
    PrintCell(Pct(t.roof));
    PrintCell(t.detected > 0 ? 100.0 * t.on_truth / t.detected : -1);
    std::printf(" %7.0f %7.1f ", static_cast<double>(t.segments) / t.images, t.ms / t.images);
    PrintCell(Pct(t.isoluminant_outline));
    PrintCell(Pct(t.isoluminant_inner));
    PrintCell(Pct(t.uniform_inner));
    for (EdgeKind k : seen_kinds) PrintCell(Pct(t.kinds.at(k)));
    std::printf("\n");
  }
  std::printf("\nthe same without 5 px at either end of each edge (junctions, corners):\n");
  std::printf("%-8s %7s", "method", "recall");
  for (EdgeKind k : seen_kinds) std::printf(" %7.7s", sim::EdgeKindName(k));
  std::printf("\n");
  for (const std::string& m : methods) {
    const Totals& tm = totals[m];
    std::printf("%-8s", m.c_str());
    PrintCell(Pct(tm.roof_interior));
    for (EdgeKind k : seen_kinds) {
      const auto it = tm.kinds_interior.find(k);
      PrintCell(it == tm.kinds_interior.end() ? -1 : Pct(it->second));
    }
    std::printf("\n");
  }
  std::printf(
      "\ndetected length on no true edge, share of all detected length, by the faces "
      "3 px either side of the segment midpoint:\n%-8s %10s %10s %10s\n",
      "method", "tree/prop", "same face", "two faces");
  for (const std::string& m : methods) {
    const Totals& tm = totals[m];
    const double d = std::max(tm.detected, 1e-9);
    std::printf("%-8s %9.1f%% %9.1f%% %9.1f%%\n", m.c_str(), 100 * tm.false_tree_prop / d,
                100 * tm.false_in_face / d, 100 * tm.false_between_faces / d);
  }
  const Totals& t = totals[methods[0]];
  std::printf(
      "\nvisible evaluated length (px): roof %.0f, iso-out %.0f, iso-in %.0f, unif-in %.0f;",
      t.roof.length_px, t.isoluminant_outline.length_px, t.isoluminant_inner.length_px,
      t.uniform_inner.length_px);
  for (EdgeKind k : seen_kinds)
    std::printf(" %s %.0f", sim::EdgeKindName(k), t.kinds.at(k).length_px);
  std::printf("\nbuildings %.0f, isoluminant %.0f\n", buildings, isoluminant_buildings);
  std::printf(
      "iso-out: eaves+verges of isoluminant roofs; iso-in / unif-in: ridges, hips, "
      "valleys, breaks of isoluminant roofs / of roofs with one material on all faces\n");
  return 0;
}

}  // namespace
}  // namespace roofsweep

int main(int argc, char** argv) { return roofsweep::Main(argc, argv); }
