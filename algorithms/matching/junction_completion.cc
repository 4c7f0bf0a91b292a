#include "algorithms/matching/junction_completion.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <set>

#include "algorithms/matching/epipolar.h"
#include "algorithms/matching/line_triangulation.h"
#include "algorithms/matching/view_support.h"

namespace roofsweep {
namespace {

constexpr double kDeg = M_PI / 180.0;

struct Hypothesis {
  int view = -1, segment = -1;
  Segment3 line;
  ViewSupport support;
  bool ok = false;
  bool horizontal = false;  // one junction and the horizontal assumption
};

// The junction of one end `e` (ideal pixels) of a segment with the
// interpretation plane `plane` (unit normal): the anchoring 3D line's
// piercing point, or empty.
std::optional<Eigen::Vector3d> Junction(const ViewFeatures& v, const Eigen::Vector4d& plane,
                                        const Eigen::Vector2d& e, const std::vector<Line3D>& lines,
                                        const std::vector<int>& near, const MatchOptions& o,
                                        int* anchor) {
  const double sin_min = std::sin(o.junction_min_angle * kDeg);
  double best = o.junction_px;
  std::optional<Eigen::Vector3d> out;
  for (int id : near) {
    const Segment3& L = lines[id].segment;
    const Eigen::Vector3d d = L.b - L.a;
    const double len = d.norm();
    if (!(len > 0)) continue;
    const double den = plane.head<3>().dot(d);
    // Too flat an intersection leaves the junction's depth uncertain.
    if (std::abs(den) < sin_min * len) continue;
    const double t = -(plane.head<3>().dot(L.a) + plane.w()) / den;
    const double gap = t < 0 ? -t * len : t > 1 ? (t - 1) * len : std::min(t, 1 - t) * len;
    if (gap > o.junction_gap_m) continue;
    const Eigen::Vector3d X = L.a + t * d;
    const auto x = ProjectIdeal(v, X);
    if (!x) continue;
    const double dist = (*x - e).norm();
    if (dist <= best) {
      best = dist;
      out = X;
      *anchor = id;
    }
  }
  return out;
}

}  // namespace

JunctionCompletion CompleteAtJunctions(const std::vector<ViewFeatures>& views,
                                       const std::vector<Line3D>& lines,
                                       const std::optional<SceneHeights>& z_range,
                                       const MatchOptions& o) {
  JunctionCompletion out;
  const int nv = static_cast<int>(views.size());
  std::set<std::pair<int, int>> used;
  for (const Line3D& l : lines)
    for (const auto& k : l.observations) used.insert(k);

  // The 3D lines as seen in each view, indexed for the end queries.
  std::vector<std::unique_ptr<SegmentIndex>> index(nv);
  std::vector<std::vector<int>> line_of(nv);
  tbb::parallel_for(0, nv, [&](int v) {
    Segments2D projected;
    for (size_t id = 0; id < lines.size(); ++id) {
      const auto a = ProjectIdeal(views[v], lines[id].segment.a),
                 b = ProjectIdeal(views[v], lines[id].segment.b);
      if (!a || !b) continue;
      Segment2D s;
      s.p0 = *a;
      s.p1 = *b;
      projected.push_back(s);
      line_of[v].push_back(static_cast<int>(id));
    }
    index[v] = std::make_unique<SegmentIndex>(projected);
  });

  std::vector<Hypothesis> hyps;
  for (int v = 0; v < nv; ++v)
    for (size_t s = 0; s < views[v].ideal.size(); ++s)
      if (views[v].ideal[s].Length() >= o.min_length && !used.count({v, static_cast<int>(s)}))
        hyps.push_back({v, static_cast<int>(s), {}, {}, false, false});

  // An anchor's projection may stop short of the corner by up to
  // junction_gap_m; 50 px covers a metre down to 2 cm GSD.
  const double reach = o.junction_px + 50.0;
  std::vector<char> candidate(hyps.size(), 0);
  tbb::parallel_for(size_t{0}, hyps.size(), [&](size_t n) {
    Hypothesis& h = hyps[n];
    const ViewFeatures& v = views[h.view];
    const Segment2D& s = v.ideal[h.segment];
    Eigen::Vector4d plane = BackProjectLine(v, s.p0, s.p1);
    plane /= plane.head<3>().norm();
    int anchor[2] = {-1, -1};
    std::optional<Eigen::Vector3d> X[2];
    for (int end = 0; end < 2; ++end) {
      const Eigen::Vector2d& e = end == 0 ? s.p0 : s.p1;
      std::vector<int> near;
      for (int k : index[h.view]->NearPoint(e, reach)) near.push_back(line_of[h.view][k]);
      X[end] = Junction(v, plane, e, lines, near, o, &anchor[end]);
    }
    if (o.junction_horizontal && X[0].has_value() != X[1].has_value()) {
      const int known = X[0] ? 0 : 1;
      const Eigen::Vector4d level(0, 0, 1, -X[known]->z());
      X[1 - known] = IntersectPlane(RayThrough(v, known == 0 ? s.p1 : s.p0), level);
      h.horizontal = true;
    }
    if (!X[0] || !X[1] || anchor[0] == anchor[1]) return;
    candidate[n] = 1;
    h.line.a = *X[0];
    h.line.b = *X[1];
    if (h.line.Length() < o.junction_min_length_m) return;
    if (z_range)
      for (const Eigen::Vector3d* p : {&h.line.a, &h.line.b})
        if (!z_range->Contains(*p)) return;
    h.support = SupportInViews(views, h.line, {h.view}, o);
    if (!h.support.Accepted(o)) return;
    // The corners themselves must be seen again: in some other view a
    // supporting segment ends at both projected junctions. Along the
    // epipolar lines this is the only test of the junctions' depth (a wrong
    // anchor moves them along the segment).
    for (const auto& [k, sup] : h.support.segments) {
      const auto a = ProjectIdeal(views[k], h.line.a), b = ProjectIdeal(views[k], h.line.b);
      if (!a || !b) continue;
      const double len = (*b - *a).norm();
      const Eigen::Vector2d d = (*b - *a) / len;
      const Segment2D& t = views[k].ideal[sup];
      const double u0 = (t.p0 - *a).dot(d), u1 = (t.p1 - *a).dot(d);
      if (std::abs(std::min(u0, u1)) <= o.junction_px &&
          std::abs(std::max(u0, u1) - len) <= o.junction_px) {
        h.ok = true;
        break;
      }
    }
  });
  for (size_t n = 0; n < hyps.size(); ++n) {
    out.candidates += candidate[n];
    out.verified += hyps[n].ok;
  }

  // Greedy one-to-one: best supported first, then longest in the image.
  std::vector<size_t> order;
  for (size_t n = 0; n < hyps.size(); ++n)
    if (hyps[n].ok) order.push_back(n);
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    const Hypothesis &A = hyps[a], &B = hyps[b];
    if (A.support.supporting != B.support.supporting)
      return A.support.supporting > B.support.supporting;
    return views[A.view].ideal[A.segment].Length() > views[B.view].ideal[B.segment].Length();
  });
  for (size_t n : order) {
    const Hypothesis& h = hyps[n];
    if (used.count({h.view, h.segment})) continue;
    std::vector<std::pair<int, int>> keys = {{h.view, h.segment}};
    for (const auto& k : h.support.segments)
      if (!used.count(k)) keys.push_back(k);
    if (keys.size() < 2 || static_cast<int>(keys.size()) < o.min_views) continue;
    // The junctions fix the depth; the observations check it.
    double ss = 0;
    for (const auto& [v, s] : keys) {
      const LineObservation obs{views[v].P, views[v].ideal[s].p0, views[v].ideal[s].p1};
      ss += LineResidual(obs, h.line.a, h.line.b).squaredNorm();
    }
    const double rms = std::sqrt(ss / (2.0 * keys.size()));
    if (!(rms <= o.max_residual)) continue;
    Line3D line;
    line.segment = h.line;
    line.rms_px = rms;
    line.observations = keys;
    line.from_junctions = true;
    line.horizontal_assumed = h.horizontal;
    out.horizontal += h.horizontal;
    line.colour_left = views[h.view].segments[h.segment].colour_left;
    line.colour_right = views[h.view].segments[h.segment].colour_right;
    for (const auto& k : keys) used.insert(k);
    out.lines.push_back(std::move(line));
  }
  return out;
}

}  // namespace roofsweep
