#include "algorithms/sweep/plane_grouping.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <string>

#include "algorithms/buildings/convex_polygon2.h"
#include "algorithms/buildings/polygon2.h"
#include "algorithms/core/format.h"
#include "algorithms/sweep/half_plane_family.h"
#include "algorithms/sweep/plane_fit.h"

namespace roofsweep {
namespace {

constexpr double kDeg = M_PI / 180.0;

double Reliability(const HalfPlane& h) {
  // Both of the paper's indicators: a high, sharp maximum; half-planes
  // passing the paper's own test come first.
  return (h.accepted ? 1.0 : 0.0) + h.similarity * std::min(1.0, -h.curvature / 8.0);
}

// Area of the convex ring on either side of the plan line a x + b y + c = 0:
// {a x + b y + c <= 0, > 0}.
std::pair<double, double> SideAreas(const Ring2& ring, double a, double b, double c) {
  return {std::abs(SignedArea(ClipHalfPlane(ring, a, b, c))),
          std::abs(SignedArea(ClipHalfPlane(ring, -a, -b, -c)))};
}

// Parameter interval [t0, t1] of the plan line p + t u inside the convex
// ring; empty (t0 > t1) when it misses it.
std::pair<double, double> LineInterval(const Ring2& ring, const Eigen::Vector2d& p,
                                       const Eigen::Vector2d& u) {
  double t0 = -1e300, t1 = 1e300;
  const double area = SignedArea(ring);
  for (size_t k = 0; k < ring.size(); ++k) {
    const Eigen::Vector2d& a = ring[k];
    const Eigen::Vector2d& b = ring[(k + 1) % ring.size()];
    // Inside: left of every edge of a counter-clockwise ring.
    Eigen::Vector2d nrm(-(b - a).y(), (b - a).x());
    if (area < 0) nrm = -nrm;
    const double den = nrm.dot(u), num = nrm.dot(a - p);
    if (std::abs(den) < 1e-12) {
      if (num > 0) return {1, 0};  // parallel and outside this edge
      continue;
    }
    const double t = num / den;
    if (den > 0)
      t0 = std::max(t0, t);
    else
      t1 = std::min(t1, t);
  }
  return {t0, t1};
}

// The plan-view line x + t d where planes p and q meet, when each patch
// lies on its own side of it with at most max_across of its area on the
// other's: the two are faces that border each other there (a ridge, a
// valley, a hip) rather than rivals for the same roof. Nothing when the
// planes are within min_angle_deg or meet in a nearly vertical line.
struct MeetLine {
  Eigen::Vector2d x, d;
  double plan_to_3d = 1;  // 3D length per plan length along the line
  // The first patch lies mostly where a x + b y + c < 0, with (a, b) = d
  // turned left and the line through x (the second on the other side).
  bool first_on_negative = false;
};
std::optional<MeetLine> BorderBetween(const Eigen::Vector4d& p_plane, const Ring2& p_patch,
                                      const Eigen::Vector4d& q_plane, const Ring2& q_patch,
                                      double min_angle_deg, double max_across) {
  if (p_patch.size() < 3 || q_patch.size() < 3) return std::nullopt;
  const Eigen::Vector3d np = p_plane.head<3>(), nq = q_plane.head<3>();
  const Eigen::Vector3d u = np.cross(nq);
  if (u.norm() < std::sin(min_angle_deg * kDeg)) return std::nullopt;
  // A point on both planes (n . X = -d for each).
  const Eigen::Vector3d x0 =
      (-p_plane[3] * nq.cross(u) - q_plane[3] * u.cross(np)) / u.squaredNorm();
  const Eigen::Vector2d dir = u.head<2>();
  if (dir.norm() < 0.1 * u.norm()) return std::nullopt;  // a nearly vertical intersection
  const Eigen::Vector2d d = dir.normalized(), x = x0.head<2>();
  // The plan line a x + b y + c = 0 through x along d.
  const double a = -d.y(), b = d.x(), c = -(a * x.x() + b * x.y());
  const auto [p_neg, p_pos] = SideAreas(p_patch, a, b, c);
  const auto [q_neg, q_pos] = SideAreas(q_patch, a, b, c);
  const double pa = p_neg + p_pos, qa = q_neg + q_pos;
  if (pa <= 0 || qa <= 0) return std::nullopt;
  const bool p_on_neg = p_neg >= p_pos, q_on_neg = q_neg >= q_pos;
  if (p_on_neg == q_on_neg) return std::nullopt;  // both on one side: no border between them
  if (std::min(p_neg, p_pos) > max_across * pa || std::min(q_neg, q_pos) > max_across * qa)
    return std::nullopt;
  return MeetLine{x, d, u.norm() / dir.norm(), p_on_neg};
}

// True when one of `lines` (plan view) runs along the meet line: both ends
// within max_offset of it, at least min_length long.
bool LineAlong(const MeetLine& m, const std::vector<std::array<Eigen::Vector2d, 2>>& lines,
               double max_offset, double min_length) {
  const Eigen::Vector2d across(-m.d.y(), m.d.x());
  for (const auto& l : lines)
    if ((l[1] - l[0]).norm() >= min_length && std::abs(across.dot(l[0] - m.x)) <= max_offset &&
        std::abs(across.dot(l[1] - m.x)) <= max_offset)
      return true;
  return false;
}

// The class a plane competes in: found planes whose height the images
// confirmed, then found planes placed by their lines, then derived ones.
int ConflictClass(const RoofPlaneHypothesis& p) { return 2 * p.derived + p.height_from_lines; }

// True when the patches of p and q overlap by more than max_overlap of the
// smaller one and the two are not faces that meet (see GroupingOptions);
// `overlap` is that fraction.
bool InConflict(const RoofPlaneHypothesis& p, const RoofPlaneHypothesis& q,
                const GroupingOptions& o, double* overlap) {
  const Ring2 inter = IntersectConvex(p.patch, q.patch);
  if (inter.empty()) return false;
  const double f =
      std::abs(SignedArea(inter)) /
      std::max(1e-9, std::min(std::abs(SignedArea(p.patch)), std::abs(SignedArea(q.patch))));
  if (f <= o.max_overlap) return false;
  // Two faces whose patches spill over the line where they meet (both
  // faces of a gable past its ridge) overlap without competing, when a 3D
  // line of each runs along that line: the border was seen.
  if (o.conflict_meet_max_across > 0 && f <= o.conflict_meet_max_overlap) {
    const auto meet = BorderBetween(p.plane, p.patch, q.plane, q.patch, o.virtual_min_angle_deg,
                                    o.conflict_meet_max_across);
    if (meet &&
        LineAlong(*meet, p.lines_xy, o.conflict_meet_line_offset_m, o.virtual_min_length_m) &&
        LineAlong(*meet, q.lines_xy, o.conflict_meet_line_offset_m, o.virtual_min_length_m))
      return false;
  }
  *overlap = f;
  return true;
}

// q's patch cut back to its own side of the convex crease where it meets p
// (GroupingOptions::conflict_cut_at_crease); empty when they do not meet so.
Ring2 CutAtConvexCrease(const RoofPlaneHypothesis& q, const RoofPlaneHypothesis& p, double overlap,
                        const GroupingOptions& o) {
  // A derived face has no supporting lines of its own; the lines it
  // carries in plan were moved from the face it was derived from (a hip
  // end mirrored along its ridge) and tell a face from a fragment as well.
  int lines = q.lines;
  double longest = q.longest_line_m;
  if (q.derived) {
    lines = std::max(lines, static_cast<int>(q.lines_xy.size()));
    for (const auto& l : q.lines_xy) longest = std::max(longest, (l[1] - l[0]).norm());
  }
  if (!o.conflict_cut_at_crease || overlap > o.conflict_meet_max_overlap ||
      lines < o.conflict_cut_min_lines || longest < o.conflict_replace_min_line_m)
    return {};
  const auto meet = BorderBetween(q.plane, q.patch, p.plane, p.patch, o.virtual_min_angle_deg,
                                  o.conflict_meet_max_across);
  if (!meet) return {};
  // Plan distance from the meet line, a x + b y + c; q keeps the side it
  // mostly lies on, where the distance has the sign `side`.
  const double a = -meet->d.y(), b = meet->d.x(), c = -(a * meet->x.x() + b * meet->x.y());
  const double side = meet->first_on_negative ? -1.0 : 1.0;
  Ring2 cut = ClipHalfPlane(q.patch, -side * a, -side * b, -side * c);
  if (cut.size() < 3 || std::abs(SignedArea(cut)) <= 0) return {};
  auto on_side = [&](const std::vector<std::array<Eigen::Vector2d, 2>>& lines, double s) {
    for (const auto& l : lines)
      for (const Eigen::Vector2d& x : l)
        if (s * (a * x.x() + b * x.y() + c) < -o.conflict_meet_line_offset_m) return false;
    return true;
  };
  if (!on_side(q.lines_xy, side) || !on_side(p.lines_xy, -side)) return {};
  // Convex: over q's side p runs above q (beyond a ridge or a hip each
  // face rises on; in a valley it would fall below).
  const Eigen::Vector2d m = FirstMoment(cut) / SignedArea(cut);
  if (!(PlaneZ(p.plane, m.x(), m.y()) > PlaneZ(q.plane, m.x(), m.y()))) return {};
  return cut;
}

// True when a supporting line of q runs inside p's patch at least step_m
// above or below p's plane (both heights from the planes: a line lies
// within the grouping's tolerance of its own plane). Sampled at its ends,
// quarters and middle, as a hip rises from a border to the ridge.
bool LineOffPlane(const RoofPlaneHypothesis& q, const RoofPlaneHypothesis& p, double step_m) {
  if (!(std::abs(p.plane[2]) > 1e-6 && std::abs(q.plane[2]) > 1e-6)) return false;
  for (const auto& l : q.lines_xy)
    for (int i = 0; i <= 4; ++i) {
      const Eigen::Vector2d x = l[0] + 0.25 * i * (l[1] - l[0]);
      if (InsideConvex(p.patch, x) &&
          std::abs(PlaneZ(q.plane, x.x(), x.y()) - PlaneZ(p.plane, x.x(), x.y())) >= step_m)
        return true;
    }
  return false;
}

// True when the patch of q lies in p's plane: normals within
// max_angle_deg, and p within max_distance_m of q at the centre of q's
// patch (the grouping's tolerances for a half-plane joining a plane).
bool CoplanarWith(const RoofPlaneHypothesis& p, const RoofPlaneHypothesis& q,
                  const GroupingOptions& o) {
  if (!(std::abs(p.plane[2]) > 1e-6 && std::abs(q.plane[2]) > 1e-6) || q.patch.empty())
    return false;
  if (std::abs(p.plane.head<3>().normalized().dot(q.plane.head<3>().normalized())) <
      std::cos(o.max_angle_deg * kDeg))
    return false;
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& x : q.patch) c += x;
  c /= static_cast<double>(q.patch.size());
  return std::abs(PlaneZ(p.plane, c.x(), c.y()) - PlaneZ(q.plane, c.x(), c.y())) <=
         o.max_distance_m;
}

// How deep inside the convex patch the lines reach: the largest distance
// from the patch's border of a point of theirs inside it (ends, quarters,
// middle); 0 when none is inside.
double LineDepthInside(const Ring2& patch,
                       const std::vector<std::array<Eigen::Vector2d, 2>>& lines) {
  double depth = 0;
  for (const auto& l : lines)
    for (int i = 0; i <= 4; ++i) {
      const Eigen::Vector2d x = l[0] + 0.25 * i * (l[1] - l[0]);
      if (!InsideConvex(patch, x)) continue;
      double d = std::numeric_limits<double>::infinity();
      for (size_t k = 0; k < patch.size(); ++k)
        d = std::min(d, PointSegmentDistance(x, patch[k], patch[(k + 1) % patch.size()]));
      depth = std::max(depth, d);
    }
  return depth;
}

// A kept plane cut across its fall line (GroupingOptions::
// conflict_cut_across_fall): the pieces where across . x < lo and > hi.
struct FallCut {
  std::string plane;  // its id
  Eigen::Vector2d across = Eigen::Vector2d::Zero();
  double lo = 0, hi = 0;
  std::vector<std::string> faces;  // the ids of the faces that cut it
  std::string reason;
};

// The cut of p[big] at the sides of the faces' hull, when they cross its
// patch along its fall line and leave a piece wide enough beside them.
std::optional<FallCut> CutAcrossFall(const std::vector<RoofPlaneHypothesis>& p, int big,
                                     const std::vector<int>& faces, const GroupingOptions& o) {
  const RoofPlaneHypothesis& b = p[big];
  if (b.patch.size() < 3 || !(std::abs(b.plane[2]) > 1e-6)) return std::nullopt;
  // Along the plane's fall line, as party walls run; on a flat plane along
  // the steepest face's (a shed roof's verges between flat roofs).
  // |n_xy| = sin(slope) for a unit normal.
  const double min_xy = std::sin(o.conflict_cut_min_slope_deg * kDeg);
  Eigen::Vector2d g = b.plane.head<2>();
  for (int q : faces)
    if (g.norm() < min_xy && p[q].plane.head<2>().norm() > g.norm()) g = p[q].plane.head<2>();
  if (g.norm() < min_xy) return std::nullopt;
  const Eigen::Vector2d fall = g.normalized(), across(-fall.y(), fall.x());
  std::vector<Eigen::Vector2d> pts;
  double sum = 0;
  bool line_off = false;
  for (int q : faces) {
    pts.insert(pts.end(), p[q].patch.begin(), p[q].patch.end());
    sum += p[q].score;
    line_off = line_off || (o.conflict_replace_min_step_m > 0 &&
                            LineOffPlane(p[q], b, o.conflict_replace_min_step_m));
  }
  const Ring2 hull = IntersectConvex(ConvexHull(std::move(pts)), b.patch);
  if (hull.size() < 3) return std::nullopt;
  const auto [s_lo, s_hi] = ConvexExtent(hull, across);
  const auto [f_lo, f_hi] = ConvexExtent(hull, fall);
  const auto [a_lo, a_hi] = ConvexExtent(b.patch, across);
  const auto [c_lo, c_hi] = ConvexChord(b.patch, across, fall, 0.5 * (s_lo + s_hi));
  // A house's width at least: a sliver of one face fitted twice holds a
  // line off it too.
  if (s_hi - s_lo < o.conflict_cut_min_width_m) return std::nullopt;
  if (!(f_hi - f_lo >= o.conflict_cut_min_span * (c_hi - c_lo))) return std::nullopt;
  if (s_lo - a_lo < o.conflict_cut_min_width_m && a_hi - s_hi < o.conflict_cut_min_width_m)
    return std::nullopt;
  const double cut_area = std::abs(SignedArea(ConvexSlab(b.patch, across, s_lo, s_hi)));
  // The faces roof most of what is cut away, not a sliver of it.
  double covered = 0;
  for (int q : faces) covered += std::abs(SignedArea(IntersectConvex(p[q].patch, b.patch)));
  if (covered < o.conflict_cut_min_cover * cut_area) return std::nullopt;
  if (!line_off && !(sum > b.similarity * cut_area)) return std::nullopt;
  std::string names;
  FallCut cut{b.id, across, s_lo, s_hi, {}, ""};
  for (int q : faces) {
    names += (names.empty() ? "" : ", ") + p[q].id;
    cut.faces.push_back(p[q].id);
  }
  cut.reason = StrFormat("%s: cut across its fall line where %zu plane(s) %s: %s", b.id.c_str(),
                         faces.size(), line_off ? "hold a line off it" : "fit the images better",
                         names.c_str());
  return cut;
}

}  // namespace

bool VirtualLine(const PlaneGroup& p, const PlaneGroup& q, const GroupingOptions& o) {
  const auto line = BorderBetween(p.plane, p.patch, q.plane, q.patch, o.virtual_min_angle_deg,
                                  o.virtual_max_across);
  if (!line) return false;
  const auto [a0, a1] = LineInterval(GrowConvex(p.patch, o.max_gap_m), line->x, line->d);
  const auto [b0, b1] = LineInterval(GrowConvex(q.patch, o.max_gap_m), line->x, line->d);
  const double plan_length = std::min(a1, b1) - std::max(a0, b0);
  // Plan length to 3D length along the (possibly inclined) intersection.
  return plan_length * line->plan_to_3d >= o.virtual_min_length_m;
}

std::vector<Eigen::Vector2d> HalfPlanePatch(const SweepLine& line, const HalfPlane& h,
                                            double min_extent_m) {
  // The sweep's own evidence when it has enough of it: a strip would run
  // past the eaves along a hip or over a neighbour's roof.
  if (h.support.size() >= 3 && h.extent_m >= min_extent_m) return h.support;
  const auto family = HalfPlaneFamily::Make(line.segment, h.side);
  if (!family) return {};
  const Eigen::Vector3d w = family->Direction(h.theta_deg * kDeg);
  const double reach = std::max(h.extent_m, min_extent_m);
  const Eigen::Vector3d a = line.segment.a, b = line.segment.b;
  const Eigen::Vector3d a2 = a + reach * w, b2 = b + reach * w;
  return ConvexHull({a.head<2>(), b.head<2>(), a2.head<2>(), b2.head<2>()});
}

GroupingResult GroupHalfPlanes(const std::vector<SweepLine>& lines,
                               const std::vector<HalfPlane>& hps, const GroupingOptions& o) {
  std::vector<int> order;
  for (size_t i = 0; i < hps.size(); ++i)
    if (hps[i].candidate && hps[i].line >= 0 && hps[i].line < static_cast<int>(lines.size()))
      order.push_back(static_cast<int>(i));
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return Reliability(hps[a]) > Reliability(hps[b]); });

  struct Work {
    PlaneGroup g;
    std::vector<WeightedPoint> pts;
    std::vector<Eigen::Vector2d> corners;
    double sim_sum = 0;
  };
  std::vector<Work> work;
  const double cos_max = std::cos(o.max_angle_deg * kDeg);
  for (int i : order) {
    const HalfPlane& h = hps[i];
    const SweepLine& line = lines[h.line];
    const std::vector<Eigen::Vector2d> rect = HalfPlanePatch(line, h, o.min_extent_m);
    if (rect.size() < 3) continue;
    const auto family = HalfPlaneFamily::Make(line.segment, h.side);
    const Eigen::Vector3d w = family->Direction(h.theta_deg * kDeg);
    const double reach = std::max(h.extent_m, o.min_extent_m);
    int best = -1;
    double best_cos = cos_max;
    for (size_t k = 0; k < work.size(); ++k) {
      const PlaneGroup& g = work[k].g;
      const double c = g.plane.head<3>().dot(h.plane.head<3>());
      if (c < best_cos) continue;
      if (PlaneDistance(g.plane, line.segment.a) > o.max_distance_m ||
          PlaneDistance(g.plane, line.segment.b) > o.max_distance_m)
        continue;
      if (ConvexDistance(g.patch, rect) > o.max_gap_m) continue;
      best = static_cast<int>(k);
      best_cos = c;
    }
    if (best < 0) {
      work.push_back({});
      best = static_cast<int>(work.size()) - 1;
      work[best].g.plane = h.plane;
    }
    Work& wk = work[best];
    wk.g.half_planes.push_back(i);
    if (std::find(wk.g.lines.begin(), wk.g.lines.end(), h.line) == wk.g.lines.end())
      wk.g.lines.push_back(h.line);
    wk.g.longest_line_m = std::max(wk.g.longest_line_m, line.segment.Length());
    // The lines are measurements; the far edge of the strip only keeps the
    // fit from degenerating when all lines are parallel and coplanar.
    wk.pts.push_back({line.segment.a, 1.0});
    wk.pts.push_back({line.segment.b, 1.0});
    wk.pts.push_back({line.segment.a + reach * w, 0.25});
    wk.pts.push_back({line.segment.b + reach * w, 0.25});
    wk.g.plane = FitPlane(wk.pts, wk.g.plane);
    wk.corners.insert(wk.corners.end(), rect.begin(), rect.end());
    wk.g.patch = ConvexHull(wk.corners);
    wk.sim_sum += h.similarity;
    wk.g.similarity = wk.sim_sum / wk.g.half_planes.size();
    wk.g.score += std::abs(SignedArea(rect)) * h.similarity;
  }

  GroupingResult out;
  for (Work& w : work) out.planes.push_back(std::move(w.g));
  return out;
}

namespace {

// ResolveConflicts once; with `cuts`, the kept planes to cut across their
// fall line (conflict_cut_across_fall), named by their ids.
std::vector<std::string> ResolveConflictsOnce(std::vector<RoofPlaneHypothesis>* planes,
                                              const GroupingOptions& o,
                                              std::vector<FallCut>* cuts) {
  std::vector<RoofPlaneHypothesis>& p = *planes;
  const int n = static_cast<int>(p.size());
  std::vector<int> by_score(n);
  std::iota(by_score.begin(), by_score.end(), 0);
  std::stable_sort(by_score.begin(), by_score.end(), [&](int a, int b) {
    if (ConflictClass(p[a]) != ConflictClass(p[b]))
      return ConflictClass(p[a]) < ConflictClass(p[b]);
    return p[a].score > p[b].score;
  });
  // Only neighbours can conflict: boxes first (a city tile holds thousands
  // of planes).
  std::vector<Eigen::Vector4d> box(n);
  for (int i = 0; i < n; ++i) box[i] = RingBounds(p[i].patch);
  // Pairs that meet in a convex crease, the weaker cut back to its side
  // (conflict_cut_at_crease): the assembly's envelope meets them there.
  std::set<std::pair<int, int>> creases;
  auto conflict = [&](int a, int b, double* f) {
    return BoundsMeet(box[a], box[b]) && !creases.count({std::min(a, b), std::max(a, b)}) &&
           InConflict(p[a], p[b], o, f);
  };

  std::vector<char> in(n, 0);
  std::vector<std::string> reason(n);
  // A plane the several faces replaced goes for good, and the conflicts
  // are settled again without it: the planes it had pushed out are decided
  // anew (see conflict_redecide).
  std::vector<char> replaced(n, 0), promoted(n, 0);
  std::vector<Ring2> whole_patch(n);
  for (int k = 0; k < n; ++k) whole_patch[k] = p[k].patch;

  // The greedy pass (§5), strongest first; a plane meeting a stronger one
  // in a convex crease is cut back to its side (conflict_cut_at_crease).
  auto decide_in_order = [&]() {
    std::fill(in.begin(), in.end(), 0);
    creases.clear();
    for (int k = 0; k < n; ++k) {
      p[k].patch = whole_patch[k];
      if (!replaced[k]) reason[k].clear();
    }
    // The faces that replaced a plane are decided first: they won against
    // it, and a plane it had pushed out must not now push them out.
    std::vector<int> order;
    for (int pass = 0; pass < 2; ++pass)
      for (int k : by_score)
        if (!replaced[k] && promoted[k] == (pass == 0)) order.push_back(k);
    for (int k : order) {
      int with = -1;
      double overlap = 0;
      // A hipped end can meet a face at each of its two hips.
      std::vector<std::pair<int, int>> met;
      for (int cuts = 0;; ++cuts) {
        with = -1;
        for (int j : order) {
          if (j == k) break;  // only stronger planes were decided
          if (in[j] && conflict(k, j, &overlap)) {
            with = j;
            break;
          }
        }
        if (with < 0 || cuts == 2) break;
        Ring2 cut = CutAtConvexCrease(p[k], p[with], overlap, o);
        if (cut.empty()) break;
        p[k].patch = std::move(cut);
        met.emplace_back(std::min(k, with), std::max(k, with));
        creases.insert(met.back());
      }
      if (with < 0) {
        in[k] = 1;
        continue;
      }
      p[k].patch = whole_patch[k];
      for (const auto& pair : met) creases.erase(pair);
      reason[k] = StrFormat("%s: overlaps the stronger %s by %.0f %% in plan view", p[k].id.c_str(),
                            p[with].id.c_str(), 100 * overlap);
    }
  };

  auto admit_derived = [&]() {
    // A derived face against small found planes (see
    // GroupingOptions::derived_displaces_fraction): it takes their place when
    // every kept plane it conflicts with is found and that small, or a
    // smaller coplanar fragment of it (derived_absorbs_coplanar). Derived
    // planes only come in and found ones only go out, so it ends.
    for (bool changed = o.derived_displaces_fraction > 0 || o.derived_absorbs_coplanar; changed;) {
      changed = false;
      for (int d : by_score) {
        if (in[d] || replaced[d] || !p[d].derived) continue;
        const double area = std::abs(SignedArea(p[d].patch));
        const double limit = o.derived_displaces_fraction * area;
        std::vector<int> rivals;
        bool small = true;
        double f = 0;
        for (int j = 0; j < n && small; ++j) {
          if (!in[j] || !conflict(d, j, &f)) continue;
          const double a = std::abs(SignedArea(p[j].patch));
          small =
              !p[j].derived &&
              (a < limit ||
               (o.derived_absorbs_coplanar && a < area && CoplanarWith(p[d], p[j], o) &&
                LineDepthInside(p[d].patch, p[j].lines_xy) <= o.derived_absorbs_max_line_depth_m));
          rivals.push_back(j);
        }
        if (!small || rivals.empty()) continue;
        for (int j : rivals) {
          in[j] = 0;
          reason[j] =
              std::abs(SignedArea(p[j].patch)) < limit
                  ? StrFormat("%s: lies in the derived %s, more than %.0f times its area",
                              p[j].id.c_str(), p[d].id.c_str(), 1 / o.derived_displaces_fraction)
                  : StrFormat("%s: lies in the derived %s, larger and coplanar with it",
                              p[j].id.c_str(), p[d].id.c_str());
        }
        in[d] = 1;
        reason[d].clear();
        changed = true;
      }
    }
  };

  // True when a plane was replaced that had not been before.
  auto replace_by_several = [&]() {
    bool fresh = false;
    // One strong plane against several: the greedy order compares pairs, so
    // a plane carried over two neighbouring faces (the north faces of two
    // terraced houses whose ridges differ by a metre) beats each by its
    // area, though each fits the images better. Where such rejected planes
    // conflict with no kept plane but that one, do not conflict with each
    // other, each fit the images clearly better (conflict_replace_min_gain
    // higher verified similarity), have min_lines lines and
    // one of conflict_replace_min_line_m, and together hold more
    // evidence (score) than it, they replace it: a local improvement of the
    // kept set's total evidence, so it ends.
    // Faces, not fragments: small planes of one short line fit a few
    // samples well, and together outweighed a flat roof (realistic s17);
    // later stages drop them.
    auto stands_as_face = [&](int q, int big) {
      return !replaced[q] && ConflictClass(p[q]) <= ConflictClass(p[big]) &&
             p[q].lines >= o.min_lines && p[q].longest_line_m >= o.conflict_replace_min_line_m;
    };
    auto better = [&](int q, int big) {
      return p[q].similarity >= p[big].similarity + o.conflict_replace_min_gain;
    };
    auto line_off = [&](int q, int big) {
      return o.conflict_replace_min_step_m > 0 &&
             LineOffPlane(p[q], p[big], o.conflict_replace_min_step_m);
    };
    for (bool changed = o.conflict_replace_by_several; changed;) {
      changed = false;
      for (int big : by_score) {
        if (!in[big]) continue;
        std::vector<int> chosen;
        double sum = 0;
        int by_line = 0;
        // The faces that fit the images clearly better are chosen first;
        // those with a line off the kept plane fill in where they do not
        // clash with them.
        for (int pass = 0; pass < 2; ++pass)
          for (int q : by_score) {
            if (in[q] || !stands_as_face(q, big)) continue;
            if (pass == 0 ? !better(q, big) : better(q, big) || !line_off(q, big)) continue;
            double f = 0;
            if (!conflict(q, big, &f)) continue;
            auto clashes = [&](int j) { return j != big && j != q && conflict(q, j, &f); };
            bool free = true;
            for (int j = 0; j < n && free; ++j) free = !(in[j] && clashes(j));
            for (size_t c = 0; c < chosen.size() && free; ++c) free = !clashes(chosen[c]);
            if (!free) continue;
            chosen.push_back(q);
            sum += p[q].score;
            by_line += pass;
          }
        if (chosen.size() < 2 || !(sum > p[big].score)) {
          // The faces for a cut: as above, but they may clash with other
          // kept planes (a row can be carried by several planes, each cut
          // in turn), and kept faces that lie in the plane's patch count
          // too (one cut back to its side of a crease with it).
          std::vector<int> across;
          for (int q : by_score) {
            if (!cuts || q == big || !stands_as_face(q, big)) continue;
            // Another face, not a part of this one fitted again nor a box
            // on a flat roof (normals conflict_cut_min_slope_deg apart at
            // least), that fits the images at least as well.
            if (p[q].similarity < p[big].similarity ||
                std::abs(
                    p[q].plane.head<3>().normalized().dot(p[big].plane.head<3>().normalized())) >
                    std::cos(o.conflict_cut_min_slope_deg * kDeg))
              continue;
            if (!better(q, big) && !line_off(q, big)) continue;
            double f = 0;
            if (in[q] ? !(std::abs(SignedArea(IntersectConvex(p[q].patch, p[big].patch))) >=
                          o.max_overlap * std::abs(SignedArea(p[q].patch)))
                      : !conflict(q, big, &f))
              continue;
            bool free = true;
            for (size_t c = 0; c < across.size() && free; ++c) free = !conflict(q, across[c], &f);
            if (free) across.push_back(q);
          }
          if (!across.empty())
            if (std::optional<FallCut> cut = CutAcrossFall(p, big, across, o))
              cuts->push_back(std::move(*cut));
          continue;
        }
        std::string names;
        for (int q : chosen) {
          in[q] = 1;
          reason[q].clear();
          names += (names.empty() ? "" : ", ") + p[q].id;
        }
        in[big] = 0;
        if (o.conflict_redecide && !replaced[big]) {
          replaced[big] = 1;
          for (int q : chosen) promoted[q] = 1;
          fresh = true;
        }
        reason[big] = StrFormat(
            "%s: overlaps %zu planes that each fit the images better%s and together hold more "
            "evidence (%.1f against %.1f): %s",
            p[big].id.c_str(), chosen.size(), by_line > 0 ? " or hold a line off it," : "", sum,
            p[big].score, names.c_str());
        changed = true;
      }
    }
    return fresh;
  };

  for (bool again = true; again;) {
    decide_in_order();
    admit_derived();
    again = replace_by_several();
  }

  std::vector<std::string> rejected;
  for (int k : by_score)
    if (!in[k]) rejected.push_back(reason[k]);
  std::vector<RoofPlaneHypothesis> out;
  for (int k = 0; k < n; ++k)
    if (in[k]) out.push_back(std::move(p[k]));
  p = std::move(out);
  return rejected;
}

}  // namespace

std::vector<std::string> ResolveConflicts(std::vector<RoofPlaneHypothesis>* planes,
                                          const GroupingOptions& o) {
  if (!o.conflict_cut_across_fall) return ResolveConflictsOnce(planes, o, nullptr);
  const std::vector<RoofPlaneHypothesis> input = *planes;
  std::set<std::string> input_ids;
  for (const RoofPlaneHypothesis& h : input) input_ids.insert(h.id);
  // The cuts made, by the id of the plane cut, and those undone.
  std::map<std::string, FallCut> made;
  std::set<std::string> undone;
  auto apply = [&]() {
    std::vector<RoofPlaneHypothesis> next;
    for (const RoofPlaneHypothesis& h : input) {
      const auto it = made.find(h.id);
      if (it == made.end()) {
        next.push_back(h);
        continue;
      }
      const FallCut& c = it->second;
      const auto [a_lo, a_hi] = ConvexExtent(h.patch, c.across);
      std::vector<Ring2> pieces;
      if (c.lo - a_lo >= o.conflict_cut_min_width_m)
        pieces.push_back(ConvexSlab(h.patch, c.across, a_lo - 1, c.lo));
      if (a_hi - c.hi >= o.conflict_cut_min_width_m)
        pieces.push_back(ConvexSlab(h.patch, c.across, c.hi, a_hi + 1));
      // The larger piece keeps the plane's id, as CutRefutedFallLinePieces
      // does; its weight in the conflicts shrinks with its patch.
      std::sort(pieces.begin(), pieces.end(), [](const Ring2& x, const Ring2& y) {
        return std::abs(SignedArea(x)) > std::abs(SignedArea(y));
      });
      for (size_t k = 0; k < pieces.size(); ++k) {
        RoofPlaneHypothesis q = h;
        q.patch = std::move(pieces[k]);
        q.score = std::abs(SignedArea(q.patch)) * q.similarity;
        if (k > 0) q.id += " part " + std::to_string(k + 1);
        next.push_back(std::move(q));
      }
    }
    return next;
  };
  // Each round cuts the planes kept in it; the next one may keep a plane
  // the cut one had pushed out, which lies over the faces too (a row was
  // carried by four such planes on `realistic-17` s1). A cut whose faces
  // do not all stay is undone: the plane is not cut where nothing roofs the
  // gap.
  for (int round = 0;; ++round) {
    *planes = apply();
    std::vector<FallCut> cuts;
    std::vector<std::string> reasons = ResolveConflictsOnce(planes, o, round < 8 ? &cuts : nullptr);
    std::set<std::string> kept;
    for (const RoofPlaneHypothesis& h : *planes) kept.insert(h.id);
    bool changed = false;
    for (auto it = made.begin(); it != made.end();) {
      const bool stays = std::all_of(it->second.faces.begin(), it->second.faces.end(),
                                     [&](const std::string& id) { return kept.count(id) > 0; });
      if (stays) {
        ++it;
        continue;
      }
      undone.insert(it->first);
      it = made.erase(it);
      changed = true;
    }
    if (!changed && round < 8)
      for (FallCut& c : cuts)
        if (!made.count(c.plane) && !undone.count(c.plane) && input_ids.count(c.plane)) {
          const std::string id = c.plane;
          made.emplace(id, std::move(c));
          changed = true;
        }
    if (changed && round >= 10) {
      // Not settled: no cut at all.
      made.clear();
      *planes = apply();
      return ResolveConflictsOnce(planes, o, nullptr);
    }
    if (!changed) {
      std::vector<std::string> notes;
      for (const auto& [id, c] : made) notes.push_back(c.reason);
      reasons.insert(reasons.begin(), notes.begin(), notes.end());
      return reasons;
    }
  }
}

namespace {

// For each plane flagged in `needs`: does it meet another of `planes` along
// a virtual line? Patch boxes grown by the gap first: a city tile holds
// thousands of planes, and only neighbours can share a virtual line.
std::vector<char> HasVirtualLine(const std::vector<PlaneGroup>& planes,
                                 const std::vector<char>& needs, const GroupingOptions& o) {
  const int n = static_cast<int>(planes.size());
  std::vector<Eigen::Vector4d> box(n);
  for (int i = 0; i < n; ++i) {
    box[i] = RingBounds(planes[i].patch);
    box[i] += Eigen::Vector4d(-o.max_gap_m, -o.max_gap_m, o.max_gap_m, o.max_gap_m);
  }
  std::vector<char> found(n, 0);
  for (int i = 0; i < n; ++i) {
    if (!needs[i]) continue;
    for (int j = 0; j < n && !found[i]; ++j)
      if (j != i && BoundsMeet(box[i], box[j]) && VirtualLine(planes[i], planes[j], o))
        found[i] = 1;
  }
  return found;
}

}  // namespace

std::vector<std::string> DropWeaklySupported(std::vector<PlaneGroup>* planes,
                                             const GroupingOptions& o) {
  const int n = static_cast<int>(planes->size());
  std::vector<int> support(n);
  for (int i = 0; i < n; ++i) support[i] = static_cast<int>((*planes)[i].lines.size());
  // Virtual lines are looked for among all the planes before any is
  // dropped, as in the paper's cooperating grouping; one per plane counts.
  if (o.virtual_lines) {
    std::vector<char> needs(n);
    for (int i = 0; i < n; ++i)
      needs[i] = support[i] < o.min_lines && support[i] + 1 >= o.min_lines;
    const std::vector<char> has_virtual = HasVirtualLine(*planes, needs, o);
    for (int i = 0; i < n; ++i) support[i] += has_virtual[i];
  }
  std::vector<std::string> reasons;
  std::vector<PlaneGroup> kept;
  for (int i = 0; i < n; ++i) {
    PlaneGroup& g = (*planes)[i];
    if (support[i] < o.min_lines) {
      char buf[160];
      std::snprintf(buf, sizeof buf, "plane of line %d: %zu supporting line(s) < %d%s",
                    g.lines.empty() ? -1 : g.lines[0], g.lines.size(), o.min_lines,
                    o.virtual_lines ? ", no virtual line with a neighbouring plane" : "");
      reasons.push_back(buf);
      continue;
    }
    kept.push_back(std::move(g));
  }
  *planes = std::move(kept);
  return reasons;
}

std::vector<std::string> DropOrphanedPlanes(std::vector<RoofPlaneHypothesis>* planes,
                                            const GroupingOptions& o) {
  std::vector<std::string> reasons;
  if (!o.virtual_lines) return reasons;
  // Until nothing changes: a plane dropped here may have been the partner
  // of another.
  for (bool dropped = true; dropped;) {
    dropped = false;
    const int n = static_cast<int>(planes->size());
    std::vector<PlaneGroup> shapes(n);
    std::vector<char> needs(n);
    for (int i = 0; i < n; ++i) {
      shapes[i].plane = (*planes)[i].plane;
      shapes[i].patch = (*planes)[i].patch;
      needs[i] = (*planes)[i].lines < o.min_lines;
    }
    const std::vector<char> has_virtual = HasVirtualLine(shapes, needs, o);
    std::vector<RoofPlaneHypothesis> kept;
    for (int i = 0; i < n; ++i) {
      RoofPlaneHypothesis& h = (*planes)[i];
      if (needs[i] && !has_virtual[i]) {
        reasons.push_back(h.id +
                          StrFormat(": %d supporting line(s) < %d, and no plane left that it "
                                    "meets along a virtual line",
                                    h.lines, o.min_lines));
        dropped = true;
        continue;
      }
      kept.push_back(std::move(h));
    }
    *planes = std::move(kept);
  }
  return reasons;
}

std::vector<std::string> SettleVerifiedPlanes(std::vector<RoofPlaneHypothesis>* planes,
                                              const GroupingOptions& o) {
  std::vector<std::string> reasons = DropOrphanedPlanes(planes, o);
  const std::vector<std::string> conflicts = ResolveConflicts(planes, o);
  reasons.insert(reasons.end(), conflicts.begin(), conflicts.end());
  const std::vector<std::string> orphans = DropOrphanedPlanes(planes, o);
  reasons.insert(reasons.end(), orphans.begin(), orphans.end());
  return reasons;
}

std::vector<RoofPlaneHypothesis> ToRoofPlanes(const std::vector<PlaneGroup>& groups,
                                              const std::vector<SweepLine>* lines) {
  std::vector<RoofPlaneHypothesis> out;
  for (size_t k = 0; k < groups.size(); ++k) {
    const PlaneGroup& g = groups[k];
    RoofPlaneHypothesis h;
    h.plane = g.plane;
    h.patch = g.patch;
    h.score = g.score;
    h.lines = static_cast<int>(g.lines.size());
    h.longest_line_m = g.longest_line_m;
    h.similarity = g.similarity;
    double sq = 0;
    if (lines)
      for (int l : g.lines)
        if (l >= 0 && l < static_cast<int>(lines->size())) {
          const SweepLine& s = (*lines)[l];
          h.lines_xy.push_back({s.segment.a.head<2>(), s.segment.b.head<2>()});
          if (std::isfinite(s.rms_px)) {
            sq += s.rms_px * s.rms_px;
            ++h.reprojection_lines;
          }
        }
    if (h.reprojection_lines > 0) h.reprojection_rms_px = std::sqrt(sq / h.reprojection_lines);
    char buf[64];
    std::snprintf(buf, sizeof buf, "plane %zu (line %d)", k, g.lines.empty() ? -1 : g.lines[0]);
    h.id = buf;
    out.push_back(std::move(h));
  }
  return out;
}

}  // namespace roofsweep
