#include "algorithms/sweep/coplanar_lines.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>

#include "algorithms/buildings/convex_polygon2.h"
#include "algorithms/sweep/plane_fit.h"

namespace roofsweep {
namespace {

constexpr double kDeg = M_PI / 180.0;

bool OnPlane(const Eigen::Vector4d& plane, const Segment3& s, double tol) {
  return PlaneDistance(plane, s.a) <= tol && PlaneDistance(plane, s.b) <= tol;
}

Ring2 PlanSegment(const Segment3& s) { return {s.a.head<2>(), s.b.head<2>()}; }

// The lines are the measurements; the previous plane, sampled at its patch
// corners with a small weight, only keeps the fit determined when all lines
// are parallel (the sweep's strips played that part in the grouping).
Eigen::Vector4d Refit(const std::vector<SweepLine>& lines, const PlaneGroup& g) {
  std::vector<WeightedPoint> pts;
  for (int l : g.lines) {
    pts.push_back({lines[l].segment.a, 1.0});
    pts.push_back({lines[l].segment.b, 1.0});
  }
  for (const Eigen::Vector2d& p : g.patch)
    pts.push_back({{p.x(), p.y(), PlaneZ(g.plane, p.x(), p.y())}, 0.25});
  return FitPlane(pts, g.plane);
}

// Adds line l to g when it keeps the plane within the options; true if added.
bool TryJoin(const std::vector<SweepLine>& lines, int l, PlaneGroup* g, const CoplanarOptions& o) {
  const Segment3& s = lines[l].segment;
  if (!OnPlane(g->plane, s, o.max_distance_m)) return false;
  PlaneGroup trial = *g;
  trial.lines.push_back(l);
  trial.plane = Refit(lines, trial);
  if (trial.plane.head<3>().dot(g->plane.head<3>()) < std::cos(o.max_angle_deg * kDeg))
    return false;
  for (int k : trial.lines)
    if (!OnPlane(trial.plane, lines[k].segment, o.max_distance_m)) return false;
  Ring2 corners = trial.patch;
  corners.push_back(s.a.head<2>());
  corners.push_back(s.b.head<2>());
  trial.patch = ConvexHull(corners);
  trial.longest_line_m = std::max(trial.longest_line_m, s.Length());
  *g = std::move(trial);
  return true;
}

// Length of line `s` over the patch (shrunk by its own sampling step) that
// lies more than `offset` off the plane.
double OffPlaneLengthOver(const Eigen::Vector4d& plane, const Ring2& patch, const Segment3& s,
                          double offset) {
  const double len = s.Length();
  const int n = std::max(2, static_cast<int>(std::ceil(len / 0.25)));
  double off = 0;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d x = s.At((i + 0.5) / n);
    if (!InsideConvex(patch, x.head<2>())) continue;
    if (PlaneDistance(plane, x) > offset) off += len / n;
  }
  return off;
}

// Closest points of the infinite lines through a and b: parameters along
// each (in metres from a.a and b.a); false when parallel.
bool ClosestPoints(const Segment3& a, const Segment3& b, double* ta, double* tb) {
  const Eigen::Vector3d u = a.Direction(), v = b.Direction(), w = a.a - b.a;
  const double uv = u.dot(v), den = 1 - uv * uv;
  if (den < 1e-9) return false;
  *ta = (uv * v.dot(w) - u.dot(w)) / den;
  *tb = (v.dot(w) - uv * u.dot(w)) / den;
  return true;
}

// Distance from parameter t to the interval [0, len].
double OutsideBy(double t, double len) { return std::max({0.0, -t, t - len}); }

// The plane two lines make, or nothing (see CoplanarOptions).
bool PairPlane(const std::vector<SweepLine>& lines, int i, int j, const CoplanarOptions& o,
               PlaneGroup* out, bool* parallel) {
  const Segment3& a = lines[i].segment;
  const Segment3& b = lines[j].segment;
  const Eigen::Vector3d u = a.Direction(), v = b.Direction();
  const double c = std::abs(u.dot(v));
  std::vector<WeightedPoint> pts = {{a.a, 1}, {a.b, 1}, {b.a, 1}, {b.b, 1}};
  Ring2 corners = {a.a.head<2>(), a.b.head<2>(), b.a.head<2>(), b.b.head<2>()};
  Eigen::Vector3d n;
  *parallel = c >= std::cos(o.parallel_angle_deg * kDeg);
  if (*parallel) {
    // Parallel: a roof face's two long edges (ridge and eave).
    const Eigen::Vector2d d2 = u.head<2>().normalized();
    if (!d2.allFinite()) return false;  // vertical lines bound walls
    const Eigen::Vector2d nrm(-d2.y(), d2.x());
    const double dist = std::abs(nrm.dot(b.At(0.5).head<2>() - a.a.head<2>()));
    if (dist < o.min_pair_distance_m || dist > o.max_pair_distance_m) return false;
    const double a0 = 0, a1 = d2.dot(a.b.head<2>() - a.a.head<2>());
    double b0 = d2.dot(b.a.head<2>() - a.a.head<2>()), b1 = d2.dot(b.b.head<2>() - a.a.head<2>());
    if (b0 > b1) std::swap(b0, b1);
    const double overlap = std::min(a1, b1) - std::max(a0, b0);
    if (overlap < o.min_overlap * std::min(a1 - a0, b1 - b0)) return false;
    n = u.cross(b.At(0.5) - a.a).normalized();
  } else {
    if (c > std::cos(o.min_junction_angle_deg * kDeg)) return false;
    double ta, tb;
    if (!ClosestPoints(a, b, &ta, &tb)) return false;
    const Eigen::Vector3d pa = a.a + ta * u, pb = b.a + tb * v;
    if ((pa - pb).norm() > o.max_distance_m) return false;
    if (OutsideBy(ta, a.Length()) > o.junction_gap_m ||
        OutsideBy(tb, b.Length()) > o.junction_gap_m)
      return false;
    const Eigen::Vector3d x = 0.5 * (pa + pb);
    pts.push_back({x, 1});
    corners.push_back(x.head<2>());
    n = u.cross(v).normalized();
  }
  if (n.z() < 0) n = -n;
  const Eigen::Vector4d guess(n.x(), n.y(), n.z(), -n.dot(a.a));
  const Eigen::Vector4d plane = FitPlane(pts, guess);
  if (plane[2] < std::cos(o.max_slope_deg * kDeg)) return false;
  for (const WeightedPoint& p : pts)
    if (PlaneDistance(plane, p.x) > o.max_distance_m) return false;
  out->plane = plane;
  out->lines = {i, j};
  out->patch = ConvexHull(corners);
  out->longest_line_m = std::max(a.Length(), b.Length());
  out->score = std::abs(SignedArea(out->patch));
  return out->score >= o.min_area_m2;
}

// True when other lines run over the patch off the plane for
// max(crossing_min_m, crossing_fraction x the longest line) in all.
bool Crossed(const std::vector<SweepLine>& lines, const PlaneGroup& g, const CoplanarOptions& o) {
  const double limit = std::max(o.crossing_min_m, o.crossing_fraction * g.longest_line_m);
  Eigen::Vector2d lo = g.patch[0], hi = g.patch[0];
  for (const Eigen::Vector2d& p : g.patch) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  double off = 0;
  for (size_t k = 0; k < lines.size() && off < limit; ++k) {
    const Segment3& s = lines[k].segment;
    if (std::max(s.a.x(), s.b.x()) < lo.x() || std::min(s.a.x(), s.b.x()) > hi.x() ||
        std::max(s.a.y(), s.b.y()) < lo.y() || std::min(s.a.y(), s.b.y()) > hi.y())
      continue;
    if (std::find(g.lines.begin(), g.lines.end(), static_cast<int>(k)) != g.lines.end()) continue;
    off += OffPlaneLengthOver(g.plane, g.patch, s, o.crossing_offset_m);
  }
  return off >= limit;
}

// Two parallel lines bound one face only when no third long parallel line
// lies between them (the ridge between two eaves, the inner verge between
// the verges of two neighbouring houses): perceptual adjacency.
bool Adjacent(const std::vector<SweepLine>& lines, int i, int j, const CoplanarOptions& o) {
  const Segment3& a = lines[i].segment;
  const Segment3& b = lines[j].segment;
  const Eigen::Vector2d d2 = (a.b - a.a).head<2>().normalized();
  if (!d2.allFinite()) return true;
  const Eigen::Vector2d nrm(-d2.y(), d2.x());
  const Eigen::Vector2d o2 = a.a.head<2>();
  const auto along = [&](const Eigen::Vector3d& x) { return d2.dot(x.head<2>() - o2); };
  const auto across = [&](const Eigen::Vector3d& x) { return nrm.dot(x.head<2>() - o2); };
  const double s0 = std::max(std::min(along(a.a), along(a.b)), std::min(along(b.a), along(b.b)));
  const double s1 = std::min(std::max(along(a.a), along(a.b)), std::max(along(b.a), along(b.b)));
  const double c0 = 0, c1 = across(b.At(0.5));
  const double lo = std::min(c0, c1) + 0.5, hi = std::max(c0, c1) - 0.5;
  const double cos_par = std::cos(o.parallel_angle_deg * kDeg);
  for (size_t k = 0; k < lines.size(); ++k) {
    if (static_cast<int>(k) == i || static_cast<int>(k) == j) continue;
    const Segment3& s = lines[k].segment;
    const Eigen::Vector2d e = (s.b - s.a).head<2>();
    if (e.norm() < 1e-9 || std::abs(d2.dot(e.normalized())) < cos_par) continue;
    const double c = across(s.At(0.5));
    if (c <= lo || c >= hi) continue;
    const double t0 = std::min(along(s.a), along(s.b)), t1 = std::max(along(s.a), along(s.b));
    if (std::min(t1, s1) - std::max(t0, s0) >= o.min_overlap * (s1 - s0)) return false;
  }
  return true;
}

// ... and on which line j lies (its midpoint).
int SideToward(const Segment3& i, const Segment3& j) { return SideOf(i, j.At(0.5).head<2>()); }

// A swept side that proposes (is a candidate for) a plane within the
// angle whose cosine is cos_max of `plane`.
bool CoplanarCandidate(const HalfPlane* h, const Eigen::Vector4d& plane, double cos_max) {
  return h && h->candidate && std::abs(h->plane.head<3>().dot(plane.head<3>())) >= cos_max;
}

// Per line, its half-planes on its sides -1 and +1 (null when not swept).
std::vector<std::array<const HalfPlane*, 2>> SidesOf(const std::vector<SweepLine>& lines,
                                                     const std::vector<HalfPlane>& half_planes) {
  std::vector<std::array<const HalfPlane*, 2>> sides(lines.size(), {nullptr, nullptr});
  for (const HalfPlane& h : half_planes)
    if (h.line >= 0 && h.line < static_cast<int>(lines.size()) && (h.side == 1 || h.side == -1))
      sides[h.line][h.side > 0 ? 1 : 0] = &h;
  return sides;
}

// See CoplanarOptions::refuse_past_bounding_line. `sides[l]`: the
// half-planes of line l on its sides -1 and +1 (null when not swept).
bool RunsPastBoundingLine(const std::vector<SweepLine>& lines,
                          const std::vector<std::array<const HalfPlane*, 2>>& sides,
                          const PlaneGroup& g, const CoplanarOptions& o) {
  const double cos_max = std::cos(o.continuation_angle_deg * kDeg);
  const double sin_horizontal = std::sin(o.parallel_angle_deg * kDeg);
  const auto coplanar = [&](const HalfPlane* h) { return CoplanarCandidate(h, g.plane, cos_max); };
  for (int k = 0; k < 2; ++k) {
    const int i = g.lines[k], j = g.lines[1 - k];
    if (i < 0 || i >= static_cast<int>(sides.size())) continue;
    // Only a horizontal line bounds a face this way (an eave); a sloped
    // one inside a terraced row is the party wall's verge, with the
    // neighbour's coplanar face beyond it.
    if (std::abs(lines[i].segment.Direction().z()) > sin_horizontal) continue;
    const int toward = SideToward(lines[i].segment, lines[j].segment);
    if (toward == 0) continue;
    const HalfPlane* facing = sides[i][toward > 0 ? 1 : 0];
    const HalfPlane* away = sides[i][toward > 0 ? 0 : 1];
    if (coplanar(away) && !coplanar(facing)) return true;
  }
  return false;
}

bool Compatible(const std::vector<SweepLine>& lines, const PlaneGroup& g, const PlaneGroup& h,
                const CoplanarOptions& o) {
  if (g.plane.head<3>().dot(h.plane.head<3>()) < std::cos(o.max_angle_deg * kDeg)) return false;
  for (int l : h.lines)
    if (!OnPlane(g.plane, lines[l].segment, o.max_distance_m)) return false;
  // The same face: patches that only touch stay apart, as the gap between
  // two coplanar neighbours bounded by their verges is a hypothesis of its
  // own, for the verification to refute.
  const Ring2 common = IntersectConvex(g.patch, h.patch);
  if (common.size() < 3) return false;
  return std::abs(SignedArea(common)) >=
         o.min_overlap * std::min(std::abs(SignedArea(g.patch)), std::abs(SignedArea(h.patch)));
}

}  // namespace

int AttachCoplanarLines(const std::vector<SweepLine>& lines, std::vector<PlaneGroup>* planes,
                        const CoplanarOptions& o, const std::vector<HalfPlane>* half_planes) {
  std::vector<std::array<const HalfPlane*, 2>> sides;
  if (half_planes && o.refuse_other_face) sides = SidesOf(lines, *half_planes);
  const double cos_max = std::cos(o.continuation_angle_deg * kDeg);
  int attached = 0;
  for (PlaneGroup& g : *planes) {
    const auto coplanar = [&](const HalfPlane* h) {
      return CoplanarCandidate(h, g.plane, cos_max);
    };
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    for (const Eigen::Vector2d& p : g.patch) centre += p;
    if (!g.patch.empty()) centre /= static_cast<double>(g.patch.size());
    // The images see another face on the plane's side of line l.
    const auto bounds_other_face = [&](int l) {
      if (sides.empty()) return false;
      const int side = SideOf(lines[l].segment, centre);
      if (side == 0) return false;
      const HalfPlane* facing = sides[l][side > 0 ? 1 : 0];
      const HalfPlane* away = sides[l][side > 0 ? 0 : 1];
      return facing && facing->candidate && !coplanar(facing) && !coplanar(away);
    };
    // Longest lines first: they fix the plane best, and the order makes the
    // result independent of the input order of equally long lines.
    std::vector<int> order;
    for (size_t l = 0; l < lines.size(); ++l) {
      const Segment3& s = lines[l].segment;
      if (s.Length() < o.min_line_length_m || lines[l].level) continue;
      if (std::find(g.lines.begin(), g.lines.end(), static_cast<int>(l)) != g.lines.end()) continue;
      if (!OnPlane(g.plane, s, o.max_distance_m)) continue;
      if (ConvexDistance(g.patch, PlanSegment(s)) > o.max_gap_m) continue;
      if (bounds_other_face(static_cast<int>(l))) continue;
      order.push_back(static_cast<int>(l));
    }
    std::stable_sort(order.begin(), order.end(), [&](int x, int y) {
      return lines[x].segment.Length() > lines[y].segment.Length();
    });
    for (int l : order) attached += TryJoin(lines, l, &g, o);
  }
  return attached;
}

std::vector<PlaneGroup> PlanesFromLinePairs(const std::vector<SweepLine>& lines,
                                            std::vector<PlaneGroup>* existing,
                                            const CoplanarOptions& o,
                                            const std::vector<HalfPlane>* half_planes) {
  std::vector<std::array<const HalfPlane*, 2>> sides;
  if (half_planes && o.refuse_past_bounding_line) sides = SidesOf(lines, *half_planes);
  std::vector<int> usable;
  for (size_t l = 0; l < lines.size(); ++l)
    if (lines[l].segment.Length() >= o.min_line_length_m && !lines[l].level)
      usable.push_back(static_cast<int>(l));
  // Plan bounding boxes grown by the largest pair distance prune the pairs
  // cheaply; the lines of one block number in the thousands at most.
  const double reach = std::max(o.max_pair_distance_m, o.junction_gap_m);
  std::vector<PlaneGroup> pairs;
  for (size_t p = 0; p < usable.size(); ++p) {
    const Segment3& a = lines[usable[p]].segment;
    const Eigen::Vector2d alo = a.a.head<2>().cwiseMin(a.b.head<2>()).array() - reach;
    const Eigen::Vector2d ahi = a.a.head<2>().cwiseMax(a.b.head<2>()).array() + reach;
    for (size_t q = p + 1; q < usable.size(); ++q) {
      const Segment3& b = lines[usable[q]].segment;
      const Eigen::Vector2d blo = b.a.head<2>().cwiseMin(b.b.head<2>());
      const Eigen::Vector2d bhi = b.a.head<2>().cwiseMax(b.b.head<2>());
      if ((blo.array() > ahi.array()).any() || (bhi.array() < alo.array()).any()) continue;
      PlaneGroup g;
      bool parallel = false;
      if (PairPlane(lines, usable[p], usable[q], o, &g, &parallel) && !Crossed(lines, g, o) &&
          (!parallel || Adjacent(lines, usable[p], usable[q], o)) &&
          (sides.empty() || !RunsPastBoundingLine(lines, sides, g, o)))
        pairs.push_back(std::move(g));
    }
  }
  // Strongest first: the pair with the longest lines fixes the plane best.
  std::stable_sort(pairs.begin(), pairs.end(), [&](const PlaneGroup& x, const PlaneGroup& y) {
    const auto len = [&](const PlaneGroup& g) {
      return lines[g.lines[0]].segment.Length() + lines[g.lines[1]].segment.Length();
    };
    return len(x) > len(y);
  });
  std::vector<PlaneGroup> out;
  const auto merge_into = [&](PlaneGroup* g, const PlaneGroup& h) {
    for (int l : h.lines)
      if (std::find(g->lines.begin(), g->lines.end(), l) == g->lines.end()) TryJoin(lines, l, g, o);
  };
  for (PlaneGroup& h : pairs) {
    bool merged = false;
    for (PlaneGroup& g : *existing)
      if (Compatible(lines, g, h, o)) {
        merge_into(&g, h);
        merged = true;
        break;
      }
    if (merged) continue;
    for (PlaneGroup& g : out)
      if (Compatible(lines, g, h, o)) {
        merge_into(&g, h);
        merged = true;
        break;
      }
    if (!merged) out.push_back(std::move(h));
  }
  for (PlaneGroup& g : out) g.score = std::abs(SignedArea(g.patch));
  return out;
}

}  // namespace roofsweep
