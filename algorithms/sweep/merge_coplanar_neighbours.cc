#include "algorithms/sweep/merge_coplanar_neighbours.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "algorithms/buildings/convex_polygon2.h"
#include "algorithms/buildings/polygon2.h"
#include "algorithms/sweep/plane_fit.h"

namespace roofsweep {

namespace {

// The candidate pairs (i < j) of NearCoplanarMerges: normals within
// max_angle_deg, patches within max_gap_m, and a step of at most max_step_m
// where they meet.
std::vector<std::pair<int, int>> CandidatePairs(const std::vector<RoofPlaneHypothesis>& planes,
                                                const NearCoplanarMergeOptions& o) {
  const double cos_max = std::cos(o.max_angle_deg * M_PI / 180);
  const int n = static_cast<int>(planes.size());
  std::vector<Eigen::Vector4d> bounds(n);
  for (int i = 0; i < n; ++i) bounds[i] = RingBounds(planes[i].patch);
  const Eigen::Vector4d gap(-o.max_gap_m, -o.max_gap_m, o.max_gap_m, o.max_gap_m);
  std::vector<std::pair<int, int>> out;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      const RoofPlaneHypothesis &a = planes[i], &b = planes[j];
      if (!BoundsMeet(bounds[i] + gap, bounds[j])) continue;
      if (a.plane.head<3>().dot(b.plane.head<3>()) < cos_max) continue;
      if (ConvexDistance(a.patch, b.patch) > o.max_gap_m) continue;
      double step = -1;
      for (int pass = 0; pass < 2; ++pass) {
        const RoofPlaneHypothesis &p = pass ? b : a, &q = pass ? a : b;
        const Ring2 near = GrowConvex(q.patch, o.meet_m);
        for (const auto& v : p.patch)
          if (InsideConvex(near, v))
            step = std::max(
                step, std::abs(PlaneZ(p.plane, v.x(), v.y()) - PlaneZ(q.plane, v.x(), v.y())));
      }
      if (step >= 0 && step <= o.max_step_m) out.push_back({i, j});
    }
  return out;
}

}  // namespace

std::vector<char> NearCoplanarNeighbours(const std::vector<RoofPlaneHypothesis>& planes,
                                         const NearCoplanarMergeOptions& o) {
  std::vector<char> has(planes.size(), 0);
  for (const auto& [i, j] : CandidatePairs(planes, o)) has[i] = has[j] = 1;
  return has;
}

std::vector<PlaneMerge> NearCoplanarMerges(const std::vector<RoofPlaneHypothesis>& planes,
                                           const NearCoplanarMergeOptions& o) {
  const int n = static_cast<int>(planes.size());
  struct Pair {
    double score;
    int i, j;
  };
  std::vector<Pair> pairs;
  for (const auto& [i, j] : CandidatePairs(planes, o))
    pairs.push_back({planes[i].score + planes[j].score, i, j});
  std::sort(pairs.begin(), pairs.end(), [](const Pair& x, const Pair& y) {
    if (x.score != y.score) return x.score > y.score;
    return x.i != y.i ? x.i < y.i : x.j < y.j;
  });
  std::vector<char> used(n, 0);
  std::vector<PlaneMerge> out;
  for (const Pair& pr : pairs) {
    if (used[pr.i] || used[pr.j]) continue;
    used[pr.i] = used[pr.j] = 1;
    const RoofPlaneHypothesis &a = planes[pr.i], &b = planes[pr.j];
    std::vector<WeightedPoint> pts;
    for (const RoofPlaneHypothesis* h : {&a, &b}) {
      const Eigen::Vector4d bb = RingBounds(h->patch);
      for (double x = bb[0]; x <= bb[2]; x += o.sample_spacing_m)
        for (double y = bb[1]; y <= bb[3]; y += o.sample_spacing_m)
          if (InsideConvex(h->patch, {x, y})) pts.push_back({{x, y, PlaneZ(h->plane, x, y)}, 1.0});
    }
    PlaneMerge m;
    m.a = pr.i;
    m.b = pr.j;
    m.merged = a.score >= b.score ? a : b;
    RoofPlaneHypothesis& h = m.merged;
    h.plane = FitPlane(pts, h.plane);
    std::vector<Eigen::Vector2d> all = a.patch;
    all.insert(all.end(), b.patch.begin(), b.patch.end());
    h.patch = ConvexHull(std::move(all));
    h.lines = a.lines + b.lines;
    h.longest_line_m = std::max(a.longest_line_m, b.longest_line_m);
    h.lines_xy = a.lines_xy;
    h.lines_xy.insert(h.lines_xy.end(), b.lines_xy.begin(), b.lines_xy.end());
    h.colour_breaks = a.colour_breaks;
    h.colour_breaks.insert(h.colour_breaks.end(), b.colour_breaks.begin(), b.colour_breaks.end());
    const int rl = a.reprojection_lines + b.reprojection_lines;
    h.reprojection_lines = rl;
    h.reprojection_rms_px =
        rl > 0 ? std::sqrt((a.reprojection_lines * a.reprojection_rms_px * a.reprojection_rms_px +
                            b.reprojection_lines * b.reprojection_rms_px * b.reprojection_rms_px) /
                           rl)
               : 0;
    h.derived = a.derived && b.derived;
    h.height_from_lines = a.height_from_lines && b.height_from_lines;
    h.id = a.id + " merged with " + b.id;
    m.concave = o.concave_parts && ConcaveCrease(a, b);
    out.push_back(std::move(m));
  }
  return out;
}

bool ConcaveCrease(const RoofPlaneHypothesis& a, const RoofPlaneHypothesis& b) {
  const double area_a = SignedArea(a.patch), area_b = SignedArea(b.patch);
  if (a.patch.size() < 3 || b.patch.size() < 3 || area_a == 0 || area_b == 0) return false;
  const Eigen::Vector2d ca = FirstMoment(a.patch) / area_a, cb = FirstMoment(b.patch) / area_b;
  return PlaneZ(b.plane, ca.x(), ca.y()) < PlaneZ(a.plane, ca.x(), ca.y()) &&
         PlaneZ(a.plane, cb.x(), cb.y()) < PlaneZ(b.plane, cb.x(), cb.y());
}

}  // namespace roofsweep
