#include "algorithms/sweep/lift_lines.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <tuple>

#include "algorithms/buildings/convex_polygon2.h"
#include "algorithms/edges/segment_index.h"
#include "algorithms/geometry/view.h"
#include "algorithms/sweep/plane_fit.h"

namespace roofsweep {
namespace {

constexpr double kDegToRad = M_PI / 180.0;

std::optional<Eigen::Vector3d> OntoPlane(const Camera& cam, const Pose& pose,
                                         const Eigen::Vector2d& px, const Eigen::Vector4d& plane,
                                         double min_incidence) {
  return IntersectPlane(BackProject(cam, pose, px), plane, min_incidence);
}

// The part [t0, t1] of the plan segment a-b inside the convex ring (CCW);
// t0 >= t1 when none.
std::pair<double, double> InsideSpan(const Ring2& ring, const Eigen::Vector2d& a,
                                     const Eigen::Vector2d& b) {
  double t0 = 0, t1 = 1;
  const Eigen::Vector2d d = b - a;
  for (size_t i = 0; i < ring.size(); ++i) {
    const Eigen::Vector2d& p = ring[i];
    const Eigen::Vector2d& q = ring[(i + 1) % ring.size()];
    const Eigen::Vector2d e = q - p;
    // Inside: cross(e, x - p) >= 0.
    const double f0 = e.x() * (a.y() - p.y()) - e.y() * (a.x() - p.x());
    const double fd = e.x() * d.y() - e.y() * d.x();
    if (std::abs(fd) < 1e-12) {
      if (f0 < 0) return {1, 0};
      continue;
    }
    const double t = -f0 / fd;
    if (fd > 0)
      t0 = std::max(t0, t);
    else
      t1 = std::min(t1, t);
    if (t0 >= t1) return {1, 0};
  }
  return {t0, t1};
}

// Views that confirm a lift: all its observations but the lifted one.
size_t Confirmations(const LiftedLine& l) { return l.observations.size() - 1; }

// How much of the projection p-q detected segments of a view cover, as
// a fraction of its length, and the longest such segment (-1 when none).
double Coverage(const Segments2D& segs, const std::vector<bool>& used, const SegmentIndex& index,
                const Eigen::Vector2d& p, const Eigen::Vector2d& q, const LiftOptions& o,
                int* best) {
  *best = -1;
  const double len = (q - p).norm();
  if (len < 1) return 0;
  const Eigen::Vector2d d = (q - p) / len;
  const Eigen::Vector2d n(-d.y(), d.x());
  Segment2D query;
  query.p0 = p;
  query.p1 = q;
  std::vector<std::pair<double, double>> spans;
  double best_len = 0;
  const double cos_max = std::cos(o.confirm_angle_deg * kDegToRad);
  for (int id : index.Near(query, o.confirm_distance_px)) {
    if (used[id]) continue;
    const Segment2D& s = segs[id];
    if (std::abs(s.Direction().dot(d)) < cos_max) continue;
    if (std::abs((s.p0 - p).dot(n)) > o.confirm_distance_px ||
        std::abs((s.p1 - p).dot(n)) > o.confirm_distance_px)
      continue;
    double u0 = (s.p0 - p).dot(d), u1 = (s.p1 - p).dot(d);
    if (u0 > u1) std::swap(u0, u1);
    u0 = std::max(u0, 0.0);
    u1 = std::min(u1, len);
    if (u1 <= u0) continue;
    spans.emplace_back(u0, u1);
    if (u1 - u0 > best_len) {
      best_len = u1 - u0;
      *best = id;
    }
  }
  std::sort(spans.begin(), spans.end());
  double covered = 0, reach = 0;
  for (const auto& [u0, u1] : spans) {
    const double from = std::max(u0, reach);
    if (u1 > from) covered += u1 - from;
    reach = std::max(reach, u1);
  }
  return covered / len;
}

// True when the shorter of a and b lies within the distance of the other's
// line, at a small angle, and they overlap along it.
bool Duplicate(const Segment3& a, const Segment3& b, const LiftOptions& o) {
  const Segment3& lo = a.Length() < b.Length() ? a : b;
  const Segment3& hi = a.Length() < b.Length() ? b : a;
  const Eigen::Vector3d d = hi.Direction();
  if (d.isZero() || std::abs(d.dot(lo.Direction())) < std::cos(o.duplicate_angle_deg * kDegToRad))
    return false;
  auto off = [&](const Eigen::Vector3d& x) {
    const Eigen::Vector3d r = x - hi.a;
    return (r - r.dot(d) * d).norm();
  };
  if (off(lo.a) > o.duplicate_distance_m || off(lo.b) > o.duplicate_distance_m) return false;
  double u0 = (lo.a - hi.a).dot(d), u1 = (lo.b - hi.a).dot(d);
  if (u0 > u1) std::swap(u0, u1);
  return u1 > 0 && u0 < hi.Length();
}

}  // namespace

std::vector<LiftedLine> LiftSegmentsOntoPlanes(const Block& block,
                                               const std::vector<Segments2D>& segments,
                                               const std::vector<std::vector<bool>>& used,
                                               const std::vector<RoofPlaneHypothesis>& planes,
                                               const std::vector<Segment3>& known,
                                               const LiftOptions& o) {
  const int nv = static_cast<int>(block.views.size());
  if (static_cast<int>(segments.size()) != nv || static_cast<int>(used.size()) != nv) return {};
  std::vector<SegmentIndex> index;
  index.reserve(nv);
  for (int v = 0; v < nv; ++v) index.emplace_back(segments[v]);

  // Candidates per (plane, view), gathered in parallel and concatenated in
  // that order so the result does not depend on the thread count.
  const int np = static_cast<int>(planes.size());
  std::vector<std::vector<LiftedLine>> found(static_cast<size_t>(np) * nv);
  tbb::parallel_for(0, np * nv, [&](int job) {
    const int pi = job / nv, v = job % nv;
    const RoofPlaneHypothesis& plane = planes[pi];
    if (plane.patch.size() < 3 || std::abs(plane.plane[2]) < 1e-6) return;
    const Ring2 grown = GrowConvex(plane.patch, o.patch_margin_m);
    const View& view = block.views[v];
    const Camera& cam = block.CameraOf(view);
    Eigen::Vector2d lo(1e300, 1e300), hi(-1e300, -1e300);
    for (const Eigen::Vector2d& p : grown) {
      const auto q = Project(cam, view.pose, {p.x(), p.y(), PlaneZ(plane.plane, p.x(), p.y())});
      if (!q) return;
      lo = lo.cwiseMin(*q);
      hi = hi.cwiseMax(*q);
    }
    if (hi.x() < 0 || hi.y() < 0 || lo.x() > cam.width || lo.y() > cam.height) return;
    for (int id : index[v].InBox(lo, hi)) {
      if (used[v][id]) continue;
      const Segment2D& s = segments[v][id];
      const auto a0 = OntoPlane(cam, view.pose, s.p0, plane.plane, o.min_incidence);
      const auto b0 = OntoPlane(cam, view.pose, s.p1, plane.plane, o.min_incidence);
      if (!a0 || !b0) continue;
      // The plane gives the depth only where it is: the part of a segment
      // beyond the grown patch (an eave that runs on along a row of
      // neighbours) is left to those neighbours' planes.
      const auto [t0, t1] = InsideSpan(grown, a0->head<2>(), b0->head<2>());
      if (t1 <= t0) continue;
      const Eigen::Vector3d a = *a0 + t0 * (*b0 - *a0), b = *a0 + t1 * (*b0 - *a0);
      if ((b - a).norm() < o.min_length_m) continue;
      LiftedLine c;
      c.segment = {a, b};
      c.plane = pi;
      c.observations.emplace_back(v, id);
      for (int w = 0; w < nv; ++w) {
        if (w == v) continue;
        const Camera& cw = block.CameraOf(block.views[w]);
        const auto pa = Project(cw, block.views[w].pose, a);
        const auto pb = Project(cw, block.views[w].pose, b);
        if (!pa || !pb || !cw.Contains(*pa) || !cw.Contains(*pb)) continue;
        int best = -1;
        if (Coverage(segments[w], used[w], index[w], *pa, *pb, o, &best) >= o.confirm_coverage) {
          c.observations.emplace_back(w, best);
          // Does w fix the depth? The epipolar line of w through the
          // segment's middle in v, against the segment.
          const Eigen::Vector3d mid = 0.5 * (a + b);
          const Eigen::Vector3d base = (block.views[w].pose.C - view.pose.C).normalized();
          const auto m0 = Project(cam, view.pose, mid);
          const auto m1 = Project(cam, view.pose, mid + base);
          if (m0 && m1 && (*m1 - *m0).norm() > 1e-9) {
            const double along = std::abs((*m1 - *m0).normalized().dot(s.Direction()));
            if (along < std::cos(o.fixing_angle_deg * kDegToRad)) ++c.fixing;
          }
        }
      }
      if (Confirmations(c) > 0 && c.fixing >= o.min_fixing) found[job].push_back(std::move(c));
    }
  });

  std::vector<LiftedLine> all;
  for (auto& f : found)
    for (LiftedLine& c : f) all.push_back(std::move(c));
  std::stable_sort(all.begin(), all.end(), [](const LiftedLine& x, const LiftedLine& y) {
    if (Confirmations(x) != Confirmations(y)) return Confirmations(x) > Confirmations(y);
    return x.segment.Length() > y.segment.Length();
  });
  std::vector<std::vector<bool>> taken(nv);
  for (int v = 0; v < nv; ++v) taken[v].assign(segments[v].size(), false);
  std::vector<LiftedLine> out;
  for (LiftedLine& c : all) {
    const auto [v, id] = c.observations.front();
    if (taken[v][id]) continue;
    bool dup = false;
    for (const Segment3& k : known) dup = dup || Duplicate(k, c.segment, o);
    for (const LiftedLine& l : out) dup = dup || Duplicate(l.segment, c.segment, o);
    if (dup) continue;
    for (const auto& [w, s] : c.observations) taken[w][s] = true;
    out.push_back(std::move(c));
  }
  return out;
}

std::vector<LiftedLine> KeepBorderLifts(const std::vector<LiftedLine>& lifted,
                                        const std::vector<HalfPlane>& sides,
                                        const std::vector<RoofPlaneHypothesis>& planes,
                                        const LiftOptions& o) {
  std::vector<LiftedLine> kept;
  if (sides.size() != 2 * lifted.size()) return kept;
  const double cos_max = std::cos(o.border_angle_deg * kDegToRad);
  for (size_t i = 0; i < lifted.size(); ++i) {
    const LiftedLine& l = lifted[i];
    const RoofPlaneHypothesis& p = planes.at(static_cast<size_t>(l.plane));
    if (p.patch.empty()) continue;
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    for (const Eigen::Vector2d& q : p.patch) centre += q;
    centre /= static_cast<double>(p.patch.size());
    const int toward = SideOf(l.segment, centre);
    if (toward == 0) continue;
    bool inner = false, outer = false;
    for (const HalfPlane* h : {&sides[2 * i], &sides[2 * i + 1]}) {
      const bool on =
          h->candidate && std::abs(h->plane.head<3>().dot(p.plane.head<3>())) >= cos_max;
      (h->side == toward ? inner : outer) = on;
    }
    if (inner && !outer) kept.push_back(l);
  }
  return kept;
}

}  // namespace roofsweep
