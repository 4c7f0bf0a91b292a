#include "algorithms/sweep/eave_search.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <tuple>
#include <utility>

#include "algorithms/buildings/convex_polygon2.h"
#include "algorithms/edges/segment_index.h"
#include "algorithms/geometry/view.h"
#include "algorithms/sweep/plane_fit.h"

namespace roofsweep {
namespace {

constexpr double kDegToRad = M_PI / 180.0;
// Bins along the eave in which views are counted: finer than any eave
// length that matters, coarse enough to stay cheap.
constexpr double kBinM = 0.1;

std::optional<Eigen::Vector3d> OntoPlane(const Camera& cam, const Pose& pose,
                                         const Eigen::Vector2d& px, const Eigen::Vector4d& plane,
                                         double min_incidence) {
  return IntersectPlane(BackProject(cam, pose, px), plane, min_incidence);
}

// A segment of one view lifted onto the plane: its position down the fall
// line and its span along the level direction (clipped to the patch's).
struct Lift {
  double s = 0, u0 = 0, u1 = 0;
  int view = -1;
};

// Down the fall line of a sloped face (min_slope_deg or more) with a
// patch; none for a flat one, which has no eave to tell.
std::optional<Eigen::Vector2d> DownTheFallLine(const RoofPlaneHypothesis& p, double min_slope_deg) {
  const Eigen::Vector3d n = p.plane.head<3>();
  if (p.patch.size() < 3 || !(n.z() > 1e-3) ||
      std::acos(std::clamp(n.z(), -1.0, 1.0)) < min_slope_deg * kDegToRad)
    return std::nullopt;
  return Eigen::Vector2d(n.head<2>().normalized());
}

// True when a line of at least min_length_m lies along `end`, the
// outermost position of the face's lines in direction e: both of its ends
// within level_line_m of it (the eave below the lines, a verge beside them).
bool LineAlongEnd(const RoofPlaneHypothesis& p, const Eigen::Vector2d& e, double end,
                  const EaveSearchOptions& o) {
  for (const auto& l : p.lines_xy)
    if ((l[1] - l[0]).norm() >= o.min_length_m && e.dot(l[0]) >= end - o.level_line_m &&
        e.dot(l[1]) >= end - o.level_line_m)
      return true;
  return false;
}

// The lowest point of a face's lines down the fall line g: its position
// s, the point, and the line's other end seen from it (up the face).
struct LowestEnd {
  double s = -1e300;
  Eigen::Vector2d foot = Eigen::Vector2d::Zero(), up = Eigen::Vector2d::Zero();
};
std::optional<LowestEnd> LowestLineEnd(const RoofPlaneHypothesis& p, const Eigen::Vector2d& g) {
  std::optional<LowestEnd> low;
  for (const auto& l : p.lines_xy)
    for (int k = 0; k < 2; ++k)
      if (!low || g.dot(l[k]) > low->s) low = LowestEnd{g.dot(l[k]), l[k], l[1 - k] - l[k]};
  return low;
}

std::optional<FaceEave> SearchFace(const Block& block, const std::vector<Segments2D>& segments,
                                   const std::vector<SegmentIndex>& index,
                                   const RoofPlaneHypothesis& p, const EaveSearchOptions& o) {
  const std::optional<Eigen::Vector2d> fall = DownTheFallLine(p, o.min_slope_deg);
  if (!fall) return std::nullopt;
  const Eigen::Vector2d g = *fall;         // down the fall line
  const Eigen::Vector2d t(-g.y(), g.x());  // level along the face
  double u_min = 1e300, u_max = -1e300;
  for (const Eigen::Vector2d& q : p.patch) {
    u_min = std::min(u_min, t.dot(q));
    u_max = std::max(u_max, t.dot(q));
  }
  // From the lowest point of its lines: a patch may reach past them (the
  // sweep's band, the hull of a stray line) and over the ground.
  const std::optional<LowestEnd> lowest = LowestLineEnd(p, g);
  if (!lowest) return std::nullopt;
  const double s_low = lowest->s;
  // That point must be the lower end of a verge or a hip, where an eave
  // begins: a line down the face, of some length.
  const Eigen::Vector2d down = lowest->up;
  if (down.norm() < o.min_edge_m || std::abs(g.dot(down)) < o.min_edge_cos * down.norm())
    return std::nullopt;
  // A face whose lowest line is level already has its eave: beyond it lie
  // the gutter's shadow, the facade and the ground, whose edges a view
  // along them places anywhere down the fall line.
  if (LineAlongEnd(p, g, s_low, o)) return std::nullopt;
  const double s_from = s_low + o.search_from_m, s_to = s_low + o.search_to_m;
  const double extent = u_max - u_min;
  if (extent < o.min_length_m) return std::nullopt;
  const double tan_max = std::tan(o.max_angle_deg * kDegToRad);

  std::vector<Lift> lifts;
  for (size_t v = 0; v < block.views.size() && v < segments.size(); ++v) {
    const View& view = block.views[v];
    const Camera& cam = block.CameraOf(view);
    Eigen::Vector2d lo(1e300, 1e300), hi(-1e300, -1e300);
    bool seen = true;
    for (double s : {s_from, s_to})
      for (double u : {u_min, u_max}) {
        const Eigen::Vector2d q = s * g + u * t;
        const auto px = Project(cam, view.pose, {q.x(), q.y(), PlaneZ(p.plane, q.x(), q.y())});
        if (!px) {
          seen = false;
          break;
        }
        lo = lo.cwiseMin(*px);
        hi = hi.cwiseMax(*px);
      }
    if (!seen || hi.x() < 0 || hi.y() < 0 || lo.x() > cam.width || lo.y() > cam.height) continue;
    for (int id : index[v].InBox(lo, hi)) {
      const Segment2D& sg = segments[v][id];
      if (sg.texture || sg.Length() < o.min_segment_px) continue;
      const auto A = OntoPlane(cam, view.pose, sg.p0, p.plane, o.min_incidence);
      const auto B = OntoPlane(cam, view.pose, sg.p1, p.plane, o.min_incidence);
      if (!A || !B) continue;
      const Eigen::Vector2d a = A->head<2>(), b = B->head<2>();
      const double ua = t.dot(a), ub = t.dot(b), sa = g.dot(a), sb = g.dot(b);
      if (std::abs(sa - sb) > tan_max * std::abs(ua - ub)) continue;
      const double s = 0.5 * (sa + sb);
      if (s < s_from || s > s_to) continue;
      const double u0 = std::max(std::min(ua, ub), u_min), u1 = std::min(std::max(ua, ub), u_max);
      if (u1 <= u0) continue;
      lifts.push_back({s, u0, u1, static_cast<int>(v)});
    }
  }
  if (lifts.empty()) return std::nullopt;
  std::sort(lifts.begin(), lifts.end(), [](const Lift& x, const Lift& y) {
    return std::tie(x.s, x.view, x.u0, x.u1) < std::tie(y.s, y.view, y.u0, y.u1);
  });

  // Every lift's position is a candidate; the one held longest by
  // min_views views wins, the outermost of equals (tile courses and shadow
  // lines lie inside the face, the eave at its edge).
  const int bins = std::max(1, static_cast<int>(std::ceil(extent / kBinM)));
  const int nv = static_cast<int>(block.views.size());
  std::vector<char> mark(static_cast<size_t>(bins) * nv);
  struct Best {
    double held = 0, s = 0;
    int first = -1, last = -1, views = 0;
    size_t from = 0, to = 0;  // the lifts taken: [from, to)
  } best;
  size_t lo = 0;
  for (size_t c = 0; c < lifts.size(); ++c) {
    const double sc = lifts[c].s;
    while (lifts[lo].s < sc - o.position_tolerance_m) ++lo;
    size_t hi = c;
    while (hi < lifts.size() && lifts[hi].s <= sc + o.position_tolerance_m) ++hi;
    std::fill(mark.begin(), mark.end(), 0);
    std::vector<char> view_used(static_cast<size_t>(nv), 0);
    for (size_t k = lo; k < hi; ++k) {
      const Lift& l = lifts[k];
      const int b0 = std::max(0, static_cast<int>(std::ceil((l.u0 - u_min) / kBinM - 0.5)));
      const int b1 = std::min(bins - 1, static_cast<int>(std::floor((l.u1 - u_min) / kBinM - 0.5)));
      for (int b = b0; b <= b1; ++b) mark[static_cast<size_t>(b) * nv + l.view] = 1;
      view_used[static_cast<size_t>(l.view)] = 1;
    }
    int held = 0, first = -1, last = -1;
    for (int b = 0; b < bins; ++b) {
      int k = 0;
      for (int v = 0; v < nv; ++v) k += mark[static_cast<size_t>(b) * nv + v];
      if (k < o.min_views) continue;
      ++held;
      if (first < 0) first = b;
      last = b;
    }
    const double held_m = held * kBinM;
    // Ties go to the outer position: the candidates come in order of s.
    if (held_m > 0 && held_m >= best.held) {
      best.held = held_m;
      best.first = first;
      best.last = last;
      best.from = lo;
      best.to = hi;
      best.views = static_cast<int>(std::count(view_used.begin(), view_used.end(), 1));
    }
  }
  if (best.first < 0 || best.held < o.min_length_m || best.held < o.min_fraction * extent)
    return std::nullopt;
  // The position: the lifts' mean, weighted by length.
  double sum = 0, weight = 0;
  for (size_t k = best.from; k < best.to; ++k) {
    const double w = lifts[k].u1 - lifts[k].u0;
    sum += w * lifts[k].s;
    weight += w;
  }
  best.s = sum / weight;
  FaceEave e;
  e.a = best.s * g + (u_min + best.first * kBinM) * t;
  e.b = best.s * g + (u_min + std::min(extent, (best.last + 1) * kBinM)) * t;
  e.beyond_lines_m = best.s - s_low;
  e.held_m = best.held;
  e.views = best.views;
  return e;
}

double Area(const Ring2& r) { return r.size() < 3 ? 0.0 : std::abs(SignedArea(r)); }

// True when clip_min_line_ends lines of min_length_m or more that run
// along direction e (within 45 deg of it) have their outer end within
// level_line_m of `end`.
bool LinesEndAt(const RoofPlaneHypothesis& p, const Eigen::Vector2d& e, double end,
                const EaveSearchOptions& o) {
  if (o.clip_min_line_ends <= 0) return false;
  int n = 0;
  for (const auto& l : p.lines_xy) {
    const Eigen::Vector2d d = l[1] - l[0];
    if (d.norm() < o.min_length_m || std::abs(e.dot(d.normalized())) < std::sqrt(0.5)) continue;
    if (std::max(e.dot(l[0]), e.dot(l[1])) >= end - o.level_line_m) ++n;
  }
  return n >= o.clip_min_line_ends;
}

// Cuts `clipped` clip_beyond_m past the outermost point of the face's
// lines in direction e, if the lines span min_depth_m that way and a line
// of min_length_m lies along that point or, with at_line_ends (flat faces),
// clip_min_line_ends of them end there (LinesEndAt).
void CutPastEndLine(const RoofPlaneHypothesis& p, const Eigen::Vector2d& e, double min_depth_m,
                    bool at_line_ends, const EaveSearchOptions& o, Ring2* clipped) {
  double end = -1e300, start = 1e300;
  for (const auto& l : p.lines_xy)
    for (const Eigen::Vector2d& q : l) {
      end = std::max(end, e.dot(q));
      start = std::min(start, e.dot(q));
    }
  if (end - start >= min_depth_m &&
      (LineAlongEnd(p, e, end, o) || (at_line_ends && LinesEndAt(p, e, end, o))))
    *clipped = ClipHalfPlane(*clipped, e.x(), e.y(), -(end + o.clip_beyond_m));
}

// The directions a face is cut in. A sloped face: down the fall line (the
// eave, when the lines span clip_min_depth_m that way: a ridge alone, or
// with a chimney's edge beside it, does not tell whether the face hangs
// from it or rises from it) and both ways along the level (the verges; a
// verge is itself as deep as min_length_m). A flat face has no fall line:
// each of its lines of min_length_m or more gives two directions, across
// it both ways, each with the depth rule (a lone edge does not tell on
// which side its roof lies).
std::vector<std::pair<Eigen::Vector2d, double>> CutDirections(
    const RoofPlaneHypothesis& p, const std::optional<Eigen::Vector2d>& fall,
    const EaveSearchOptions& o) {
  if (fall) {
    const Eigen::Vector2d g = *fall;         // down the fall line
    const Eigen::Vector2d t(-g.y(), g.x());  // level along the face
    return {{g, o.clip_min_depth_m}, {t, 0.0}, {-t, 0.0}};
  }
  std::vector<std::pair<Eigen::Vector2d, double>> out;
  for (const auto& l : p.lines_xy) {
    const Eigen::Vector2d d = l[1] - l[0];
    if (d.norm() < o.min_length_m) continue;
    const Eigen::Vector2d n = Eigen::Vector2d(-d.y(), d.x()).normalized();
    out.emplace_back(n, o.clip_min_depth_m);
    out.emplace_back(-n, o.clip_min_depth_m);
  }
  return out;
}

// The position down the fall line g where face p is cut at the foot of
// its hip, where another face's eave ends (EaveSearchOptions::hip_corner_m),
// if there is one.
std::optional<double> HipCornerCut(const RoofPlaneHypothesis& p, const Eigen::Vector2d& g,
                                   const std::vector<RoofPlaneHypothesis>& planes,
                                   const EaveSearchOptions& o) {
  if (!(o.hip_corner_m > 0)) return std::nullopt;
  const std::optional<LowestEnd> low = LowestLineEnd(p, g);
  if (!low || low->up.norm() < o.min_edge_m) return std::nullopt;
  const double s_low = low->s;
  const Eigen::Vector2d foot = low->foot, up = low->up;
  const double c = -g.dot(up) / up.norm();
  if (c < o.hip_min_cos || c > o.hip_max_cos) return std::nullopt;
  const double z = PlaneZ(p.plane, foot.x(), foot.y());
  for (const RoofPlaneHypothesis& q : planes) {
    if (&q == &p) continue;
    const std::optional<Eigen::Vector2d> fall_q = DownTheFallLine(q, o.min_slope_deg);
    if (!fall_q || fall_q->dot(g) > std::cos(30 * kDegToRad)) continue;
    const Eigen::Vector2d gq = *fall_q;
    const std::optional<LowestEnd> q_lowest = LowestLineEnd(q, gq);
    if (!q_lowest) continue;
    const double q_low = q_lowest->s;
    for (const auto& l : q.lines_xy) {
      const Eigen::Vector2d d = l[1] - l[0];
      const double len = d.norm();
      if (len < o.min_length_m ||
          std::abs(gq.dot(d)) > std::sin(o.max_angle_deg * kDegToRad) * len ||
          std::min(gq.dot(l[0]), gq.dot(l[1])) < q_low - o.level_line_m)
        continue;
      for (int k = 0; k < 2; ++k) {
        const Eigen::Vector2d back = l[1 - k] - l[k];
        if ((l[k] - foot).norm() <= o.hip_corner_m && -g.dot(back) >= std::sqrt(0.5) * len &&
            std::abs(PlaneZ(q.plane, l[k].x(), l[k].y()) - z) <= o.hip_corner_dz_m)
          return s_low;
      }
    }
  }
  return std::nullopt;
}

}  // namespace

std::vector<FaceEave> FindEaves(const Block& block, const std::vector<Segments2D>& segments,
                                const std::vector<RoofPlaneHypothesis>& planes,
                                const EaveSearchOptions& o) {
  std::vector<SegmentIndex> index;
  index.reserve(segments.size());
  for (const Segments2D& s : segments) index.emplace_back(s);
  std::vector<std::optional<FaceEave>> found(planes.size());
  tbb::parallel_for(size_t{0}, planes.size(), [&](size_t i) {
    found[i] = SearchFace(block, segments, index, planes[i], o);
    if (found[i]) found[i]->plane = static_cast<int>(i);
  });
  std::vector<FaceEave> out;
  for (const auto& f : found)
    if (f) out.push_back(*f);
  return out;
}

int ExtendFacesToEaves(const std::vector<FaceEave>& eaves, std::vector<RoofPlaneHypothesis>* planes,
                       const EaveSearchOptions& o, std::vector<std::string>* log) {
  int grown = 0;
  char buf[240];
  for (const FaceEave& e : eaves) {
    RoofPlaneHypothesis& p = (*planes)[static_cast<size_t>(e.plane)];
    std::vector<Eigen::Vector2d> pts = p.patch;
    pts.push_back(e.a);
    pts.push_back(e.b);
    Ring2 grown_patch = ConvexHull(std::move(pts));
    const double added = Area(grown_patch) - Area(p.patch);
    if (!(added > 1e-3)) continue;
    double taken = 0;
    for (size_t j = 0; j < planes->size(); ++j) {
      if (static_cast<int>(j) == e.plane) continue;
      const Ring2& q = (*planes)[j].patch;
      if (q.size() < 3) continue;
      taken += Area(IntersectConvex(grown_patch, q)) - Area(IntersectConvex(p.patch, q));
    }
    if (taken > o.max_overlap_fraction * added) {
      std::snprintf(buf, sizeof buf,
                    "%s: eave %.1f m down the fall line left out: %.0f %% of the %.1f m2 it "
                    "adds lies under other planes",
                    p.id.c_str(), e.beyond_lines_m, 100 * taken / added, added);
      if (log) log->push_back(buf);
      continue;
    }
    std::snprintf(buf, sizeof buf,
                  "%s: patch grown to its eave %.1f m down the fall line (%d views over %.1f m), "
                  "+%.1f m2",
                  p.id.c_str(), e.beyond_lines_m, e.views, e.held_m, added);
    if (log) log->push_back(buf);
    p.patch = std::move(grown_patch);
    ++grown;
  }
  return grown;
}

int ClipFacesAtBorderLines(std::vector<RoofPlaneHypothesis>* planes, const EaveSearchOptions& o,
                           std::vector<std::string>* log) {
  int cut = 0;
  char buf[200];
  for (RoofPlaneHypothesis& p : *planes) {
    if (p.lines_xy.empty() || p.patch.size() < 3) continue;
    const std::optional<Eigen::Vector2d> fall = DownTheFallLine(p, o.min_slope_deg);
    const bool flat = p.plane.z() >= std::cos(o.flat_max_slope_deg * kDegToRad);
    if (!fall && !(o.clip_flat && flat)) continue;
    Ring2 clipped = p.patch;
    for (const auto& [e, min_depth_m] : CutDirections(p, fall, o))
      CutPastEndLine(p, e, min_depth_m, /*at_line_ends=*/!fall, o, &clipped);
    const double removed = Area(p.patch) - Area(clipped);
    if (clipped.size() < 3 || !(removed > 1e-3)) continue;
    std::snprintf(buf, sizeof buf, "%s: %spatch cut by %.1f m2 to its border lines", p.id.c_str(),
                  fall ? "" : "flat ", removed);
    if (log) log->push_back(buf);
    p.patch = std::move(clipped);
    ++cut;
  }
  return cut;
}

int CutFacesAtHipFeet(std::vector<RoofPlaneHypothesis>* planes, const EaveSearchOptions& o,
                      std::vector<std::string>* log) {
  // Decided on the patches as they come, then applied: a cut face's
  // neighbours are judged by the same planes and lines either way.
  // Per plane: down its fall line, and the position of the cut there.
  std::vector<std::optional<std::pair<Eigen::Vector2d, double>>> at(planes->size());
  for (size_t i = 0; i < planes->size(); ++i) {
    const RoofPlaneHypothesis& p = (*planes)[i];
    if (const auto fall = DownTheFallLine(p, o.min_slope_deg))
      if (const auto s = HipCornerCut(p, *fall, *planes, o)) at[i] = std::make_pair(*fall, *s);
  }
  int cut = 0;
  char buf[200];
  for (size_t i = 0; i < planes->size(); ++i) {
    if (!at[i]) continue;
    RoofPlaneHypothesis& p = (*planes)[i];
    const auto& [g, s] = *at[i];
    Ring2 clipped = ClipHalfPlane(p.patch, g.x(), g.y(), -(s + o.clip_beyond_m));
    const double removed = Area(p.patch) - Area(clipped);
    if (clipped.size() < 3 || !(removed > 1e-3)) continue;
    std::snprintf(buf, sizeof buf, "%s: patch cut by %.1f m2 at the foot of its hip", p.id.c_str(),
                  removed);
    if (log) log->push_back(buf);
    p.patch = std::move(clipped);
    ++cut;
  }
  return cut;
}

}  // namespace roofsweep
