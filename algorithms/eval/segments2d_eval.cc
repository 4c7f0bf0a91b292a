#include "algorithms/eval/segments2d_eval.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "algorithms/edges/segment_index.h"

namespace roofsweep {
namespace eval {
namespace {

using V2 = Eigen::Vector2d;
using V3 = Eigen::Vector3d;

double PointSegmentDistance(const V2& q, const V2& a, const V2& b) {
  const V2 ab = b - a;
  const double l2 = ab.squaredNorm();
  const double t = l2 > 0 ? std::clamp((q - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
  return (a + t * ab - q).norm();
}

// True when a segment of `index` (over `segments`) passes within the
// distance of q with a direction within the angle of unit direction t.
bool Matches(const SegmentIndex& index, const Segments2D& segments, const V2& q, const V2& t,
             const Segment2DEvalOptions& o) {
  const double cos_max = std::cos(o.max_angle_deg * M_PI / 180.0);
  for (int id : index.NearPoint(q, o.max_distance_px)) {
    const Segment2D& s = segments[static_cast<size_t>(id)];
    const V2 d = s.p1 - s.p0;
    const double len = d.norm();
    if (len <= 0) continue;
    if (std::abs(d.dot(t)) / len < cos_max) continue;
    if (PointSegmentDistance(q, s.p0, s.p1) <= o.max_distance_px) return true;
  }
  return false;
}

bool Inside(const V2& p, const Camera& c, double border) {
  return p.x() >= border && p.y() >= border && p.x() <= c.width - border &&
         p.y() <= c.height - border;
}

// A sample of a projected true edge: pixel, unit image direction, depth.
struct EdgeSample {
  V2 pixel;
  V2 direction;
  double depth;
};

// Samples about every `step` px along the projection of a->b (sampled in
// 3D, so lens distortion bends the path as it should). Points behind the
// camera are skipped.
std::vector<EdgeSample> SampleEdge(const Camera& camera, const Pose& pose, const V3& a, const V3& b,
                                   double step) {
  std::vector<EdgeSample> out;
  const auto pa = Project(camera, pose, a), pb = Project(camera, pose, b);
  double approx = 0;
  if (pa && pb) {
    approx = (*pb - *pa).norm();
  } else {
    // One end behind the camera: sample densely enough for the visible part.
    approx = std::max(camera.width, camera.height) * 4.0;
  }
  const int n = std::max(1, static_cast<int>(std::ceil(approx / step)));
  const double dt = 0.25 / n;
  for (int i = 0; i < n; ++i) {
    const double t = (i + 0.5) / n;
    const V3 x = a + t * (b - a);
    const auto p = Project(camera, pose, x);
    const auto p0 = Project(camera, pose, a + std::max(0.0, t - dt) * (b - a));
    const auto p1 = Project(camera, pose, a + std::min(1.0, t + dt) * (b - a));
    if (!p || !p0 || !p1) continue;
    const V2 d = *p1 - *p0;
    if (d.norm() <= 0) continue;
    out.push_back({*p, d.normalized(), pose.ToCamera(x).z()});
  }
  return out;
}

}  // namespace

VisibilityFn DepthMapVisibility(const cv::Mat& depth, double tolerance_m, double tolerance_rel) {
  return [depth, tolerance_m, tolerance_rel](const V2& pixel, double z) {
    const int x = static_cast<int>(std::floor(pixel.x()));
    const int y = static_cast<int>(std::floor(pixel.y()));
    if (x < 0 || y < 0 || x >= depth.cols || y >= depth.rows) return false;
    const float d = depth.at<float>(y, x);
    if (!std::isfinite(d)) return false;
    return std::abs(d - z) <= std::max(tolerance_m, tolerance_rel * z);
  };
}

Segment2DScores EvaluateSegments2D(const Camera& camera, const Pose& pose,
                                   const std::vector<sim::TrueEdge>& truth,
                                   const VisibilityFn& visible, const Segments2D& detected,
                                   const Segment2DEvalOptions& o) {
  Segment2DScores out;
  out.per_edge.resize(truth.size());
  out.segments = static_cast<int>(detected.size());
  const SegmentIndex detected_index(detected);

  // Projected true edges as short straight pieces (every edge, visible or
  // not), for precision.
  Segments2D pieces;
  for (size_t e = 0; e < truth.size(); ++e) {
    const std::vector<EdgeSample> s =
        SampleEdge(camera, pose, truth[e].a, truth[e].b, 4.0 * o.sample_step_px);
    // Pieces between sample points, extended by half a step at the ends.
    for (size_t i = 0; i + 1 < s.size(); ++i) {
      Segment2D p;
      p.p0 = s[i].pixel;
      p.p1 = s[i + 1].pixel;
      if (i == 0) p.p0 -= s[i].direction * 2.0 * o.sample_step_px;
      if (i + 2 == s.size()) p.p1 += s[i + 1].direction * 2.0 * o.sample_step_px;
      pieces.push_back(p);
    }
    if (s.size() == 1) {
      Segment2D p;
      p.p0 = s[0].pixel - s[0].direction * 2.0 * o.sample_step_px;
      p.p1 = s[0].pixel + s[0].direction * 2.0 * o.sample_step_px;
      pieces.push_back(p);
    }
  }
  const SegmentIndex truth_index(pieces);

  // Recall.
  for (size_t e = 0; e < truth.size(); ++e) {
    const sim::TrueEdge& edge = truth[e];
    std::vector<EdgeSample> s = SampleEdge(camera, pose, edge.a, edge.b, o.sample_step_px);
    s.erase(
        std::remove_if(s.begin(), s.end(),
                       [&](const EdgeSample& x) { return !Inside(x.pixel, camera, o.border_px); }),
        s.end());
    if (s.size() < 2) continue;
    const double step =
        s.size() > 1 ? (s.back().pixel - s.front().pixel).norm() / (s.size() - 1) : 0;
    // Length inside the image, along the (possibly bent) path.
    double inside_len = 0;
    for (size_t i = 0; i + 1 < s.size(); ++i) inside_len += (s[i + 1].pixel - s[i].pixel).norm();
    if (inside_len + step < o.min_edge_length_px) continue;
    const double w = inside_len / (s.size() - 1);  // length per sample
    LengthScore& score = out.per_edge[e];
    LengthScore interior;
    // Ends of the whole projected edge (not of its part inside the image).
    const auto end_a = Project(camera, pose, edge.a), end_b = Project(camera, pose, edge.b);
    for (const EdgeSample& x : s) {
      const V2 n(x.direction.y(), -x.direction.x());
      const bool vis = visible(x.pixel, x.depth) ||
                       visible(x.pixel + o.probe_offset_px * n, x.depth) ||
                       visible(x.pixel - o.probe_offset_px * n, x.depth);
      if (!vis) continue;
      score.length_px += w;
      const bool covered = Matches(detected_index, detected, x.pixel, x.direction, o);
      if (covered) score.covered_px += w;
      const bool near_end = (end_a && (x.pixel - *end_a).norm() < o.end_margin_px) ||
                            (end_b && (x.pixel - *end_b).norm() < o.end_margin_px);
      if (!near_end) {
        interior.length_px += w;
        if (covered) interior.covered_px += w;
      }
    }
    LengthScore& k = out.per_kind[edge.kind];
    k.length_px += score.length_px;
    k.covered_px += score.covered_px;
    LengthScore& ki = out.per_kind_interior[edge.kind];
    ki.length_px += interior.length_px;
    ki.covered_px += interior.covered_px;
    if (sim::IsRoofEdge(edge.kind)) {
      out.roof.length_px += score.length_px;
      out.roof.covered_px += score.covered_px;
      out.roof_interior.length_px += interior.length_px;
      out.roof_interior.covered_px += interior.covered_px;
    }
  }

  // Precision.
  out.per_segment.resize(detected.size());
  for (size_t j = 0; j < detected.size(); ++j) {
    const Segment2D& seg = detected[j];
    const double len = seg.Length();
    if (!(len > 0)) continue;
    const V2 t = (seg.p1 - seg.p0) / len;
    const int n = std::max(1, static_cast<int>(std::ceil(len / o.sample_step_px)));
    const double w = len / n;
    for (int i = 0; i < n; ++i) {
      const V2 q = seg.p0 + ((i + 0.5) / n) * (seg.p1 - seg.p0);
      out.detected_px += w;
      out.per_segment[j].length_px += w;
      if (Matches(truth_index, pieces, q, t, o)) {
        out.detected_on_truth_px += w;
        out.per_segment[j].covered_px += w;
      }
    }
  }
  return out;
}

}  // namespace eval
}  // namespace roofsweep
