#include "algorithms/buildings/assemble_buildings.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <set>

#include "algorithms/buildings/classify_roof_type.h"
#include "algorithms/buildings/convex_polygon2.h"
#include "algorithms/buildings/polygon2.h"
#include "algorithms/buildings/right_corners.h"
#include "algorithms/buildings/solid_check.h"
#include "algorithms/core/format.h"
#include "algorithms/geometry/slope.h"

namespace roofsweep {
namespace {

constexpr double kDeg = M_PI / 180.0;

double PlaneZ(const Eigen::Vector4d& pl, const Eigen::Vector2d& p) {
  return -(pl[0] * p.x() + pl[1] * p.y() + pl[3]) / pl[2];
}

Eigen::Vector2d Centroid(const Ring2& r) {
  const double a = SignedArea(r);
  if (std::abs(a) < 1e-12) {
    Eigen::Vector2d c = Eigen::Vector2d::Zero();
    for (const auto& p : r) c += p;
    return r.empty() ? c : Eigen::Vector2d(c / r.size());
  }
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
  for (size_t i = 0, n = r.size(); i < n; ++i) {
    const auto& p = r[i];
    const auto& q = r[(i + 1) % n];
    const double w = p.x() * q.y() - q.x() * p.y();
    c += (p + q) * w;
  }
  return c / (6 * a);
}

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(int n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int Find(int i) { return parent[i] == i ? i : parent[i] = Find(parent[i]); }
  void Join(int a, int b) {
    a = Find(a), b = Find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

// Region of plane `i` in the lower envelope of `active` over `outline`.
Ring2 EnvelopeRegion(const std::vector<RoofPlaneHypothesis>& planes, const std::vector<int>& active,
                     int i, const Ring2& outline) {
  Ring2 r = outline;
  const Eigen::Vector4d& pi = planes[i].plane;
  // z_i = -(a_i x + b_i y + d_i) / c_i; z_i - z_j <= 0 is linear in x, y.
  const Eigen::Vector3d fi(-pi[0] / pi[2], -pi[1] / pi[2], -pi[3] / pi[2]);
  for (int j : active) {
    if (j == i || r.size() < 3) continue;
    const Eigen::Vector4d& pj = planes[j].plane;
    const Eigen::Vector3d fj(-pj[0] / pj[2], -pj[1] / pj[2], -pj[3] / pj[2]);
    const Eigen::Vector3d f = fi - fj;
    // Ties (the same plane twice) go to the lower index.
    if (f.head<2>().norm() < 1e-12 && std::abs(f[2]) < 1e-9 && j > i) continue;
    r = ClipHalfPlane(r, f[0], f[1], f[2]);
  }
  return r.size() >= 3 && SignedArea(r) > 1e-9 ? r : Ring2{};
}

// Welds plan-view vertices closer than `tol`; returns the representative
// of each input point.
class Welder {
 public:
  explicit Welder(double tol) : tol_(tol) {}
  int Add(const Eigen::Vector2d& p) {
    for (size_t i = 0; i < pts_.size(); ++i)
      if ((pts_[i] - p).norm() <= tol_) return static_cast<int>(i);
    pts_.push_back(p);
    return static_cast<int>(pts_.size()) - 1;
  }
  const std::vector<Eigen::Vector2d>& points() const { return pts_; }
  // Welded vertices strictly inside segment u -> v (within tol), ordered
  // from u to v.
  std::vector<int> OnSegment(int u, int v) const {
    const Eigen::Vector2d a = pts_[u], b = pts_[v];
    const double len2 = (b - a).squaredNorm();
    std::vector<std::pair<double, int>> hits;
    for (size_t k = 0; k < pts_.size(); ++k) {
      if (static_cast<int>(k) == u || static_cast<int>(k) == v || len2 <= 0) continue;
      const double t = (pts_[k] - a).dot(b - a) / len2;
      if (t <= 0 || t >= 1) continue;
      if (PointSegmentDistance(pts_[k], a, b) <= tol_) hits.emplace_back(t, static_cast<int>(k));
    }
    std::sort(hits.begin(), hits.end());
    std::vector<int> out;
    for (const auto& h : hits) out.push_back(h.second);
    return out;
  }

 private:
  double tol_;
  std::vector<Eigen::Vector2d> pts_;
};

// A ring of welded ids with the T-junction vertices inserted and repeated
// ids removed.
std::vector<int> CloseRing(const Welder& w, const std::vector<int>& ids) {
  std::vector<int> ring;
  for (size_t k = 0; k < ids.size(); ++k) {
    const int u = ids[k], v = ids[(k + 1) % ids.size()];
    if (u == v) continue;
    ring.push_back(u);
    for (int m : w.OnSegment(u, v)) ring.push_back(m);
  }
  std::vector<int> out;
  for (int id : ring)
    if (out.empty() || out.back() != id) out.push_back(id);
  while (out.size() > 1 && out.front() == out.back()) out.pop_back();
  return out;
}

// Two patches belong to one roof when they come within adjacency_gap_m of
// each other in plan and their planes meet there (heights within
// max_step_m where their grown patches overlap). `grown_*`: the patches
// grown by adjacency_gap_m.
bool PlanesMeet(const RoofPlaneHypothesis& p, const Ring2& grown_p, const RoofPlaneHypothesis& q,
                const Ring2& grown_q, const AssemblyOptions& o) {
  if (ConvexDistance(p.patch, q.patch) > o.adjacency_gap_m) return false;
  const Ring2 meet = IntersectConvex(grown_p, grown_q);
  if (meet.empty()) return false;
  const Eigen::Vector2d c = Centroid(meet);
  return std::abs(PlaneZ(p.plane, c) - PlaneZ(q.plane, c)) <= o.max_step_m;
}

// The part of the patch within 1 mm of the line normal . x + offset = 0.
Ring2 AlongLine(const Ring2& patch, const Eigen::Vector2d& normal, double offset) {
  return ClipHalfPlane(ClipHalfPlane(patch, normal.x(), normal.y(), offset - 1e-3), -normal.x(),
                       -normal.y(), -offset - 1e-3);
}

double Diameter(const Ring2& ring) {
  double d = 0;
  for (size_t a = 0; a < ring.size(); ++a)
    for (size_t b = a + 1; b < ring.size(); ++b) d = std::max(d, (ring[a] - ring[b]).norm());
  return d;
}

// False when the planes cross along a line that runs across the strip where
// their grown patches overlap rather than along it (see
// AssemblyOptions::split_across_edges).
bool CrossAlongMeet(const RoofPlaneHypothesis& p, const Ring2& grown_p,
                    const RoofPlaneHypothesis& q, const Ring2& grown_q, double min_along) {
  // z = g . x + h per plane; they cross where (g_p - g_q) . x + h_p - h_q = 0.
  const Eigen::Vector4d& a = p.plane;
  const Eigen::Vector4d& b = q.plane;
  const Eigen::Vector2d n(-a[0] / a[2] + b[0] / b[2], -a[1] / a[2] + b[1] / b[2]);
  if (n.norm() < 0.1) return true;
  const Ring2 meet = IntersectConvex(grown_p, grown_q);
  if (meet.size() < 3) return true;
  const double k = -a[3] / a[2] + b[3] / b[2];
  const double chord = Diameter(AlongLine(meet, n / n.norm(), k / n.norm()));
  return chord == 0 || chord >= min_along * Diameter(meet);
}

// Two faces of one gable: slopes of at least gable_min_slope_deg within
// gable_max_slope_difference_deg of each other, falling opposite ways
// within gable_max_azimuth_deg (AssemblyOptions::join_gable_to_corners).
bool GableFaces(const RoofPlaneHypothesis& p, const RoofPlaneHypothesis& q,
                const AssemblyOptions& o) {
  // PlausiblePlanes has checked both normals to be unit vectors; turned up.
  const Eigen::Vector3d np = p.plane.head<3>() * (p.plane[2] < 0 ? -1 : 1);
  const Eigen::Vector3d nq = q.plane.head<3>() * (q.plane[2] < 0 ? -1 : 1);
  const double sp = std::acos(std::clamp(np.z(), -1.0, 1.0));
  const double sq = std::acos(std::clamp(nq.z(), -1.0, 1.0));
  if (std::min(sp, sq) < o.gable_min_slope_deg * kDeg ||
      std::abs(sp - sq) > o.gable_max_slope_difference_deg * kDeg)
    return false;
  return np.head<2>().normalized().dot(nq.head<2>().normalized()) <=
         -std::cos(o.gable_max_azimuth_deg * kDeg);
}

// Two supporting lines that form a right-angled corner in plan (see
// AssemblyOptions::keep_right_corners).
bool HasRightCorner(const RoofPlaneHypothesis& p, const AssemblyOptions& o) {
  return CountRightCorners(p.lines_xy,
                           {o.corner_min_arm_m, o.corner_max_angle_deg, o.adjacency_gap_m}) > 0;
}

}  // namespace

AssemblyOptions AssemblyOptionsFor(const AssemblyOptions& options, bool with_footprints) {
  AssemblyOptions o = options;
  if (with_footprints) {
    o.min_height_m = options.footprint_min_height_m;
    o.min_line_length_m = options.footprint_min_line_length_m;
  }
  return o;
}

std::string RoofRefusal(const RoofPlaneHypothesis& p, const GroundModel& ground,
                        const AssemblyOptions& o) {
  const Eigen::Vector3d nrm = p.plane.head<3>();
  if (p.patch.size() < 3 || !(std::abs(SignedArea(p.patch)) > 0) || !nrm.allFinite() ||
      std::abs(nrm.norm() - 1) > 1e-6)
    return "degenerate plane or patch";
  if (p.longest_line_m < o.min_line_length_m && p.longest_line_m < o.min_attached_line_length_m)
    return StrFormat("longest supporting line %.2f m < %.2f m", p.longest_line_m,
                     o.min_line_length_m);
  const double slope = std::acos(std::clamp(nrm.z(), -1.0, 1.0)) / kDeg;
  if (slope > o.max_roof_slope_deg)
    return StrFormat("slope %.1f deg > %.1f deg (a wall?)", slope, o.max_roof_slope_deg);
  const Eigen::Vector2d c = Centroid(p.patch);
  const double g = ground.HeightAt(c.x(), c.y());
  if (!std::isfinite(g)) return "no ground height there";
  const double h = PlaneZ(p.plane, c) - g;
  if (h < o.min_height_m) return StrFormat("%.2f m above the ground < %.2f m", h, o.min_height_m);
  return {};
}

std::vector<std::string> DropRefusedRoofs(std::vector<RoofPlaneHypothesis>* planes,
                                          const GroundModel& ground, const AssemblyOptions& o,
                                          const std::vector<char>* spare_short) {
  AssemblyOptions any_lines = o;
  any_lines.min_line_length_m = any_lines.min_attached_line_length_m = 0;
  std::vector<std::string> reasons;
  std::vector<RoofPlaneHypothesis> kept;
  for (size_t i = 0; i < planes->size(); ++i) {
    RoofPlaneHypothesis& p = (*planes)[i];
    const bool spared = spare_short && i < spare_short->size() && (*spare_short)[i];
    const std::string why = RoofRefusal(p, ground, spared ? any_lines : o);
    if (why.empty())
      kept.push_back(std::move(p));
    else
      reasons.push_back(p.id + ": " + why);
  }
  *planes = std::move(kept);
  return reasons;
}

namespace {

// The pieces of `patch` over each footprint it meets by at least
// min_piece_m2, and its area over all footprints.
struct OverFootprints {
  std::vector<std::pair<int, std::vector<Ring2>>> pieces;
  double inside = 0;
};
OverFootprints PatchOverFootprints(const Ring2& patch, const std::vector<Footprint>& footprints,
                                   const std::vector<Eigen::Vector4d>& bounds,
                                   double min_piece_m2) {
  OverFootprints out;
  const Eigen::Vector4d pb = RingBounds(patch);
  for (size_t f = 0; f < footprints.size(); ++f) {
    if (!BoundsMeet(pb, bounds[f])) continue;
    std::vector<Ring2> pieces = IntersectPolygons(patch, footprints[f].outline);
    const double a = AreaOfPieces(pieces);
    out.inside += a;
    if (a >= min_piece_m2) out.pieces.emplace_back(static_cast<int>(f), std::move(pieces));
  }
  return out;
}

std::string OutsideFootprintsReason(double inside, double area, const AssemblyOptions& o) {
  return StrFormat(": %.0f %% of its patch over a footprint < %.0f %%", 100 * inside / area,
                   100 * o.footprint_min_inside);
}

}  // namespace

std::vector<std::string> DropOutsideFootprints(std::vector<RoofPlaneHypothesis>* planes,
                                               const std::vector<Footprint>& footprints,
                                               const AssemblyOptions& o) {
  if (footprints.empty()) return {};
  std::vector<Eigen::Vector4d> bounds;
  for (const Footprint& f : footprints) bounds.push_back(RingBounds(f.outline));
  std::vector<std::string> reasons;
  std::vector<RoofPlaneHypothesis> kept;
  for (RoofPlaneHypothesis& p : *planes) {
    const double area = std::abs(SignedArea(p.patch));
    const OverFootprints over =
        PatchOverFootprints(p.patch, footprints, bounds, o.footprint_min_piece_m2);
    if (over.inside < o.footprint_min_inside * area || over.pieces.empty())
      reasons.push_back(p.id + OutsideFootprintsReason(over.inside, area, o));
    else
      kept.push_back(std::move(p));
  }
  *planes = std::move(kept);
  return reasons;
}

namespace {

// Plausible roof planes of the input, with the reasons for the others.
std::vector<int> PlausiblePlanes(const std::vector<RoofPlaneHypothesis>& planes,
                                 const GroundModel& ground, const AssemblyOptions& o,
                                 std::vector<std::string>* rejected,
                                 std::vector<std::vector<int>>* kept_for) {
  kept_for->assign(planes.size(), {});
  std::vector<int> keep, attached;
  for (int i = 0; i < static_cast<int>(planes.size()); ++i) {
    const RoofPlaneHypothesis& p = planes[i];
    const std::string name = p.id.empty() ? StrFormat("plane %d", i) : p.id;
    const std::string refusal = RoofRefusal(p, ground, o);
    if (!refusal.empty()) {
      rejected->push_back(name + ": " + refusal);
      continue;
    }
    if (p.longest_line_m < o.min_line_length_m) {
      attached.push_back(i);
      continue;
    }
    keep.push_back(i);
  }
  // Short-lined planes that meet a plausible plane: dormers, hip ends,
  // porches. A hedge, a car or a tree crown does not join a roof, nor
  // draws a square corner as a garage does.
  const size_t n_keep = keep.size();
  // A short-lined plane kept for its square corner is a roof too: the other
  // face of its gable (a garden shed's, whose one line is often the ridge)
  // may join it. Only that face: tree crowns hold chains of small facets
  // with square corners between them.
  std::vector<char> cornered(attached.size());
  for (size_t a = 0; a < attached.size(); ++a)
    cornered[a] = o.keep_right_corners && HasRightCorner(planes[attached[a]], o);
  // Every plane it meets is recorded (kept_for), so the passing planes'
  // grown patches are made once.
  std::vector<Ring2> grown_keep(n_keep);
  for (size_t k = 0; k < n_keep; ++k)
    grown_keep[k] = GrowConvex(planes[keep[k]].patch, o.adjacency_gap_m);
  for (size_t a = 0; a < attached.size(); ++a) {
    const int i = attached[a];
    const RoofPlaneHypothesis& p = planes[i];
    const Ring2 grown = GrowConvex(p.patch, o.adjacency_gap_m);
    std::vector<int> meets;
    for (size_t k = 0; k < n_keep; ++k)
      if (PlanesMeet(p, grown, planes[keep[k]], grown_keep[k], o)) meets.push_back(keep[k]);
    for (size_t b = 0;
         b < attached.size() && meets.empty() && !cornered[a] && o.join_gable_to_corners; ++b) {
      const RoofPlaneHypothesis& q = planes[attached[b]];
      if (cornered[b] && GableFaces(p, q, o) &&
          PlanesMeet(p, grown, q, GrowConvex(q.patch, o.adjacency_gap_m), o))
        meets.push_back(attached[b]);
    }
    if (!meets.empty() || cornered[a]) {
      keep.push_back(i);
      if (!cornered[a]) (*kept_for)[i] = std::move(meets);
    } else {
      rejected->push_back((p.id.empty() ? StrFormat("plane %d", i) : p.id) +
                          StrFormat(": longest supporting line %.2f m < %.2f m, it joins no "
                                    "roof plane and has no right-angled corner",
                                    p.longest_line_m, o.min_line_length_m));
    }
  }
  std::sort(keep.begin(), keep.end());
  return keep;
}

// Cuts every plane's patch at the footprints: one copy per footprint it
// covers (a plane found across a row of terraced houses becomes one plane
// per house), dropping planes that lie mostly outside every footprint.
// `footprint_of` receives the footprint index of each output plane.
std::vector<RoofPlaneHypothesis> CutAtFootprints(
    const std::vector<RoofPlaneHypothesis>& planes, const std::vector<int>& keep,
    const std::vector<Footprint>& footprints, const AssemblyOptions& o,
    std::vector<int>* footprint_of, std::vector<int>* origin, std::vector<std::string>* rejected) {
  std::vector<Eigen::Vector4d> bounds;
  for (const Footprint& f : footprints) bounds.push_back(RingBounds(f.outline));
  std::vector<RoofPlaneHypothesis> out;
  for (int i : keep) {
    const RoofPlaneHypothesis& p = planes[i];
    const std::string name = p.id.empty() ? StrFormat("plane %d", i) : p.id;
    const double area = std::abs(SignedArea(p.patch));
    auto [over, inside] =
        PatchOverFootprints(p.patch, footprints, bounds, o.footprint_min_piece_m2);
    if (inside < o.footprint_min_inside * area || over.empty()) {
      rejected->push_back(name + OutsideFootprintsReason(inside, area, o));
      continue;
    }
    for (auto& [f, pieces] : over) {
      RoofPlaneHypothesis q = p;
      std::vector<Eigen::Vector2d> pts;
      for (const Ring2& r : pieces) pts.insert(pts.end(), r.begin(), r.end());
      q.patch = ConvexHull(pts);
      if (over.size() > 1) q.id = name + " (footprint " + footprints[f].id + ")";
      out.push_back(std::move(q));
      footprint_of->push_back(f);
      origin->push_back(i);
    }
  }
  return out;
}

// The lower envelope of `active` over `outline` (any simple polygon), and
// the face with the least evidence.
struct Envelope {
  Ring2 outline;
  double ground_z = 0;
  std::vector<std::vector<Ring2>> regions;  // pieces of each active plane's face
  std::vector<double> face_area;            // per active plane
  int worst = -1;                           // index into active; -1: every face is supported
  std::string worst_reason;
};

// True when more than max_overlap of active[k]'s patch lies in the other
// active planes' patches: a plane hidden where it was seen together with
// the planes that hide it is a second fit of their face, while a roof at
// another height is hidden by their extensions beside it.
bool HiddenWhereOthersWereSeen(const std::vector<RoofPlaneHypothesis>& planes,
                               const std::vector<int>& active, size_t k, double max_overlap) {
  const Ring2& patch = planes[active[k]].patch;
  const double area = std::abs(SignedArea(patch));
  double shared = 0;
  for (size_t j = 0; j < active.size(); ++j)
    if (j != k) shared += IntersectionArea(patch, planes[active[j]].patch);
  return area > 0 && shared > max_overlap * area;
}

Envelope LowerEnvelope(const std::vector<RoofPlaneHypothesis>& planes,
                       const std::vector<int>& active, const Ring2& outline,
                       const std::vector<Ring2>& grown, const GroundModel& ground,
                       const AssemblyOptions& o, double min_support) {
  Envelope e;
  e.outline = outline;
  e.ground_z = std::numeric_limits<double>::infinity();
  for (const auto& p : outline) e.ground_z = std::min(e.ground_z, ground.HeightAt(p.x(), p.y()));
  // The convex routines are exact on convex outlines (the usual case
  // without footprints); a non-convex footprint is clipped by Boost.
  const bool convex = IsConvexRing(outline);
  const Ring2 hull = convex ? outline : ConvexHull(outline);
  e.regions.assign(active.size(), {});
  e.face_area.assign(active.size(), 0.0);
  double worst_value = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k < active.size(); ++k) {
    const int i = active[k];
    const Ring2 region = EnvelopeRegion(planes, active, i, hull);
    double area = 0, seen = 0;
    if (convex) {
      if (!region.empty()) {
        e.regions[k].push_back(region);
        area = SignedArea(region);
        const Ring2 inside = IntersectConvex(region, grown[i]);
        seen = inside.empty() ? 0.0 : SignedArea(inside);
      }
    } else if (!region.empty()) {
      e.regions[k] = IntersectPolygons(region, outline);
      for (const Ring2& r : e.regions[k]) {
        area += SignedArea(r);
        seen += IntersectionArea(r, grown[i]);
      }
    }
    e.face_area[k] = area;
    const double support = area > 0 ? seen / area : 0.0;
    double low = std::numeric_limits<double>::infinity();
    for (const Ring2& r : e.regions[k])
      for (const auto& p : r) low = std::min(low, PlaneZ(planes[i].plane, p));
    // Rank failures by how little evidence the face has.
    double value = std::numeric_limits<double>::infinity();
    std::string why;
    if (area < o.min_face_area_m2) {
      // After the unsupported faces: a plane above the roof everywhere is
      // often a true plane that a wrongly extended one hides, and dropping
      // it first would lose it for good.
      value = 1 + area;
      why = StrFormat(": roof face of %.2f m2 < %.2f m2 (%s)", area, o.min_face_area_m2,
                      area == 0 ? "above the roof everywhere" : "sliver");
    } else if (support < min_support) {
      value = support;
      why = StrFormat(": only %.0f %% of its roof face lies where the images saw the plane",
                      100 * support);
    } else if (low - e.ground_z < 0.5 * o.min_height_m) {
      value = -1;  // a roof below the walls' minimum height is never right
      why = StrFormat(": its roof face comes down to %.2f m above the ground", low - e.ground_z);
    }
    if (value < worst_value ||
        (value == worst_value && e.worst >= 0 && planes[i].score < planes[active[e.worst]].score)) {
      worst_value = value;
      e.worst = static_cast<int>(k);
      e.worst_reason = why;
    }
  }
  if (e.worst_reason.empty()) e.worst = -1;
  return e;
}

// The closed solid of one building from its envelope: roof faces, walls
// from every outline edge down to the ground, a planar ground surface.
Building BuildSolid(const std::vector<RoofPlaneHypothesis>& planes, const std::vector<int>& active,
                    const Envelope& e, const AssemblyOptions& o) {
  // Shared vertices: weld, then build faces from welded ids so that
  // neighbouring faces and the walls use the very same coordinates.
  Welder welder(o.weld_m);
  std::vector<std::vector<std::vector<int>>> region_ids(active.size());
  for (size_t k = 0; k < active.size(); ++k)
    for (const Ring2& r : e.regions[k]) {
      region_ids[k].emplace_back();
      for (const auto& p : r) region_ids[k].back().push_back(welder.Add(p));
    }
  std::vector<int> outline_ids;
  for (const auto& p : e.outline) outline_ids.push_back(welder.Add(p));
  auto roof_z = [&](int id) {
    double z = std::numeric_limits<double>::infinity();
    for (int i : active) z = std::min(z, PlaneZ(planes[i].plane, welder.points()[id]));
    return z;
  };
  auto top = [&](int id) {
    const Eigen::Vector2d& p = welder.points()[id];
    return Eigen::Vector3d(p.x(), p.y(), roof_z(id));
  };

  Building b;
  double lines = 0, sim = 0, score = 0;
  double reprojection_sq = 0;
  int reprojection_lines = 0;
  std::vector<Polygon3> roof_faces;
  for (size_t k = 0; k < active.size(); ++k) {
    bool used = false;
    for (const std::vector<int>& ids : region_ids[k]) {
      const std::vector<int> ring = CloseRing(welder, ids);
      if (ring.size() < 3) continue;
      Polygon3 poly;
      for (int id : ring) poly.exterior.push_back(top(id));
      roof_faces.push_back(poly);
      used = true;
    }
    if (!used) continue;
    const RoofPlaneHypothesis& p = planes[active[k]];
    lines += p.lines;
    reprojection_sq += p.reprojection_lines * p.reprojection_rms_px * p.reprojection_rms_px;
    reprojection_lines += p.reprojection_lines;
    sim += p.similarity;
    score += p.score;
  }
  std::vector<Surface> walls;
  const std::vector<int> ring = CloseRing(welder, outline_ids);
  // Outline vertices in the welded ring order, for the walls' corners.
  std::vector<size_t> corners;
  for (size_t k = 0; k < ring.size(); ++k)
    if (std::find(outline_ids.begin(), outline_ids.end(), ring[k]) != outline_ids.end())
      corners.push_back(k);
  for (size_t c = 0; c < corners.size(); ++c) {
    const size_t from = corners[c], to = corners[(c + 1) % corners.size()];
    std::vector<int> chain;
    for (size_t k = from;; k = (k + 1) % ring.size()) {
      chain.push_back(ring[k]);
      if (k == to) break;
    }
    const Eigen::Vector2d& p = welder.points()[chain.front()];
    const Eigen::Vector2d& q = welder.points()[chain.back()];
    Polygon3 wall;
    wall.exterior.emplace_back(p.x(), p.y(), e.ground_z);
    wall.exterior.emplace_back(q.x(), q.y(), e.ground_z);
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) wall.exterior.push_back(top(*it));
    walls.push_back({SurfaceType::kWall, "", {wall}});
  }
  Polygon3 floor;
  for (auto it = corners.rbegin(); it != corners.rend(); ++it) {
    const Eigen::Vector2d& p = welder.points()[ring[*it]];
    floor.exterior.emplace_back(p.x(), p.y(), e.ground_z);
  }
  b.surfaces.push_back({SurfaceType::kGround, "", {floor}});
  for (const Polygon3& r : roof_faces) b.surfaces.push_back({SurfaceType::kRoof, "", {r}});
  for (Surface& w : walls) b.surfaces.push_back(std::move(w));
  b.roof_type = ClassifyRoofType(roof_faces);
  double top_z = -std::numeric_limits<double>::infinity();
  for (const Polygon3& r : roof_faces)
    for (const auto& v : r.exterior) top_z = std::max(top_z, v.z());
  b.measured_height = top_z - e.ground_z;
  b.double_attributes["roof_planes"] = static_cast<double>(roof_faces.size());
  b.double_attributes["supporting_lines"] = lines;
  b.double_attributes["photometric_score"] = roof_faces.empty() ? 0.0 : sim / roof_faces.size();
  b.double_attributes["reliability"] = score;
  b.double_attributes["footprint_m2"] = SignedArea(e.outline);
  if (reprojection_lines > 0)
    b.double_attributes["reprojection_rms_px"] = std::sqrt(reprojection_sq / reprojection_lines);
  return b;
}

// Where a supporting line (plan view) lies along the outline edge a-b of a
// counter-clockwise ring, when within border_max_angle_deg of it and
// border_max_offset_m of its line: its mean offset along the edge's outward
// normal (on the right of a -> b) and the length of the edge it spans.
struct LineAlongEdge {
  double offset = 0, overlap = 0;
};
std::optional<LineAlongEdge> PlaceAlongEdge(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                            const std::array<Eigen::Vector2d, 2>& l,
                                            const AssemblyOptions& o) {
  const Eigen::Vector2d d = l[1] - l[0], e = b - a;
  const double len = d.norm(), elen = e.norm();
  if (len < 1e-6 || elen < 1e-6) return std::nullopt;
  if (std::abs(e.dot(d)) < std::cos(o.border_max_angle_deg * kDeg) * elen * len)
    return std::nullopt;
  const Eigen::Vector2d u = e / elen, outward(u.y(), -u.x());
  const double o0 = (l[0] - a).dot(outward), o1 = (l[1] - a).dot(outward);
  if (std::max(std::abs(o0), std::abs(o1)) > o.border_max_offset_m) return std::nullopt;
  const double t0 = std::clamp((l[0] - a).dot(u), 0.0, elen);
  const double t1 = std::clamp((l[1] - a).dot(u), 0.0, elen);
  return LineAlongEdge{0.5 * (o0 + o1), std::abs(t1 - t0)};
}

// The outline moved onto the border lines of its planes (see
// AssemblyOptions::border_lines): for each hull edge the qualifying line
// farthest out; the hull is first grown out to the lines outside it, then
// cut at each line. Convex in, convex out.
Ring2 FollowBorderLines(const Ring2& hull, const std::vector<RoofPlaneHypothesis>& planes,
                        const std::vector<int>& active, const AssemblyOptions& o) {
  if (!o.border_lines || hull.size() < 3) return hull;
  const size_t n = hull.size();
  // Counter-clockwise ring: each edge's outward normal is on its right.
  std::vector<Eigen::Vector2d> outward(n);
  for (size_t k = 0; k < n; ++k) {
    const Eigen::Vector2d e = (hull[(k + 1) % n] - hull[k]).normalized();
    outward[k] = Eigen::Vector2d(e.y(), -e.x());
  }
  // Per hull edge: the chosen line's offset along the outward normal.
  std::vector<double> best(n, -std::numeric_limits<double>::infinity());
  std::vector<std::array<Eigen::Vector2d, 2>> chosen(n);
  for (int i : active)
    for (const auto& l : planes[i].lines_xy)
      for (size_t k = 0; k < n; ++k) {
        // Half the line along the edge: a line is a border where it runs.
        const auto along = PlaceAlongEdge(hull[k], hull[(k + 1) % n], l, o);
        if (!along || along->overlap < 0.5 * (l[1] - l[0]).norm()) continue;
        if (along->offset > best[k]) best[k] = along->offset, chosen[k] = l;
      }
  // An edge inside its line moves out to it whole (the line's end points
  // alone would chamfer the corners); one outside is cut below.
  std::vector<Eigen::Vector2d> pts(hull.begin(), hull.end());
  bool any = false;
  for (size_t k = 0; k < n; ++k) {
    if (!std::isfinite(best[k])) continue;
    any = true;
    if (best[k] <= 0) continue;
    pts.push_back(hull[k] + best[k] * outward[k]);
    pts.push_back(hull[(k + 1) % n] + best[k] * outward[k]);
  }
  if (!any) return hull;
  Ring2 r = ConvexHull(pts);
  const Eigen::Vector2d c = Centroid(hull);
  for (size_t k = 0; k < n && r.size() >= 3; ++k) {
    if (!std::isfinite(best[k])) continue;
    const Eigen::Vector2d p = chosen[k][0], q = chosen[k][1];
    // Keep the side of the line holding the hull's centroid: a x + b y + c <= 0.
    Eigen::Vector2d nrm(q.y() - p.y(), p.x() - q.x());
    double off = -nrm.dot(p);
    if (nrm.dot(c) + off > 0) nrm = -nrm, off = -off;
    r = ClipHalfPlane(r, nrm.x(), nrm.y(), off);
  }
  // Clipping next to nearly collinear hull vertices can leave slivers of
  // millimetres that the polygon clipper downstream rejects as invalid.
  if (r.size() >= 3) r = ConvexHull(std::vector<Eigen::Vector2d>(r.begin(), r.end()));
  return r.size() >= 3 && SignedArea(r) > 1e-9 ? r : hull;
}

// True when a supporting line of the planes lies along the edge a-b over
// half the edge: the edge is the building's own, not a cut corner.
bool LineAlong(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
               const std::vector<RoofPlaneHypothesis>& planes, const std::vector<int>& active,
               const AssemblyOptions& o) {
  for (int i : active)
    for (const auto& l : planes[i].lines_xy) {
      const auto along = PlaceAlongEdge(a, b, l, o);
      if (along && along->overlap >= 0.5 * (b - a).norm()) return true;
    }
  return false;
}

// The outline with its rounded or cut corners squared (see
// AssemblyOptions::square_corners). Convex in, convex out: each corner
// point lies on the extensions of two edges, so the hull with it drops the
// chain between them and nothing else.
Ring2 SquareCorners(const Ring2& outline, const std::vector<RoofPlaneHypothesis>& planes,
                    const std::vector<int>& active, const AssemblyOptions& o) {
  const size_t n = outline.size();
  if (!o.square_corners || n < 4) return outline;
  const double tol = o.corner_max_angle_deg * kDeg;
  auto dir = [&](size_t k) {
    const Eigen::Vector2d d = outline[(k + 1) % n] - outline[k % n];
    return std::atan2(d.y(), d.x());
  };
  auto len = [&](size_t k) { return (outline[(k + 1) % n] - outline[k % n]).norm(); };
  std::vector<Eigen::Vector2d> pts(outline.begin(), outline.end());
  bool any = false;
  for (size_t i = 0; i < n; ++i) {
    if (len(i) < o.corner_min_side_m) continue;
    // Counter-clockwise, the edges turn left monotonically: the first edge
    // turned by 90 - tol or more either is the other side of a right angle
    // or there is none.
    size_t j = i + 1;
    double turn = 0;
    for (; j < i + n; ++j) {
      turn = std::remainder(dir(j) - dir(i), 2 * M_PI);
      if (turn < 0) turn += 2 * M_PI;
      if (turn >= M_PI / 2 - tol) break;
    }
    if (j == i + 1 || j >= i + n || turn > M_PI / 2 + tol || len(j) < o.corner_min_side_m) continue;
    bool supported = false;
    for (size_t k = i + 1; k < j && !supported; ++k)
      supported = LineAlong(outline[k % n], outline[(k + 1) % n], planes, active, o);
    if (supported) continue;
    // Where the two edges' lines meet.
    const Eigen::Vector2d a = outline[i], da = outline[(i + 1) % n] - a;
    const Eigen::Vector2d b = outline[j % n], db = outline[(j + 1) % n] - b;
    const double den = da.x() * db.y() - da.y() * db.x();
    if (std::abs(den) < 1e-9) continue;
    const double t = ((b - a).x() * db.y() - (b - a).y() * db.x()) / den;
    const Eigen::Vector2d c = a + t * da;
    double dist = std::numeric_limits<double>::infinity();
    for (size_t k = i + 1; k < j; ++k)
      dist = std::min(dist, PointSegmentDistance(c, outline[k % n], outline[(k + 1) % n]));
    if (dist > o.corner_max_fill_m) continue;
    pts.push_back(c);
    any = true;
  }
  if (!any) return outline;
  Ring2 r = ConvexHull(pts);
  return r.size() >= 3 && SignedArea(r) > 1e-9 ? r : outline;
}

// A cut line in plan: the points where normal . x + offset = 0.
struct PartyCut {
  Eigen::Vector2d normal = Eigen::Vector2d::Zero();
  double offset = 0;
  // The stretch of the cut line that cuts: the party line extended by the
  // face's depth at both ends (over the ridge into the facing roof face).
  Eigen::Vector2d from = Eigen::Vector2d::Zero(), to = Eigen::Vector2d::Zero();
};

// True when the cut's stretch crosses the patch.
bool CutReaches(const PartyCut& c, const Ring2& patch) {
  const Eigen::Vector2d along = c.to - c.from;
  Ring2 r = AlongLine(patch, c.normal, c.offset);
  r = ClipHalfPlane(r, -along.x(), -along.y(), along.dot(c.from));
  r = ClipHalfPlane(r, along.x(), along.y(), -along.dot(c.to));
  return r.size() >= 3;
}

// The first party line (see AssemblyOptions::split_at_party_lines) among
// the supporting lines of `members`, as the cut along it.
std::optional<PartyCut> FindPartyCut(const std::vector<RoofPlaneHypothesis>& planes,
                                     const std::vector<int>& members, const AssemblyOptions& o) {
  const double cos_max = std::cos(o.party_max_angle_deg * kDeg);
  const double sin_max = std::sin(o.party_max_angle_deg * kDeg);
  for (int i : members) {
    const RoofPlaneHypothesis& p = planes[i];
    const Eigen::Vector2d g = p.plane.head<2>();
    // |n_xy| = sin(slope) for a unit normal.
    if (g.norm() < std::sin(o.party_min_slope_deg * kDeg) || p.patch.size() < 3) continue;
    const Eigen::Vector2d fall = g.normalized(), across(-fall.y(), fall.x());
    const Ring2 near = GrowConvex(p.patch, o.adjacency_gap_m);
    const size_t n_lines = p.lines_xy.size();
    for (size_t li = 0; li < n_lines + p.colour_breaks.size(); ++li) {
      // A colour break alone may be the end of a patch that reaches past
      // its roof (onto the ground or a lower neighbour): it cuts only where
      // another face shows the wall too.
      const bool from_colour = li >= n_lines;
      const auto& l = from_colour ? p.colour_breaks[li - n_lines] : p.lines_xy[li];
      const Eigen::Vector2d d = l[1] - l[0];
      const double len = d.norm();
      if (len < 1e-6 || std::abs(d.dot(fall)) < cos_max * len) continue;
      if (!InsideConvex(near, l[0]) || !InsideConvex(near, l[1])) continue;
      // The cut runs down the fall line through the line's middle.
      const Eigen::Vector2d m = 0.5 * (l[0] + l[1]);
      double width_lo = 0, width_hi = 0;
      for (const auto& q : p.patch) {
        const double side = (q - m).dot(across);
        width_lo = std::max(width_lo, -side), width_hi = std::max(width_hi, side);
      }
      if (width_lo < o.party_min_width_m || width_hi < o.party_min_width_m) continue;
      // The face's depth along the cut: the chord of the patch.
      const Ring2 chord = AlongLine(p.patch, across, -across.dot(m));
      double c_lo = std::numeric_limits<double>::infinity(), c_hi = -c_lo;
      for (const auto& q : chord) {
        const double along = (q - m).dot(fall);
        c_lo = std::min(c_lo, along), c_hi = std::max(c_hi, along);
      }
      if (c_hi - c_lo < o.party_min_depth_m ||
          std::abs(d.dot(fall)) < o.party_min_span * (c_hi - c_lo))
        continue;
      const double reach = c_hi - c_lo;
      const PartyCut cut{across, -across.dot(m), m + (c_lo - reach) * fall,
                         m + (c_hi + reach) * fall};
      // Every other face the cut runs through must show the party wall too
      // (a line along the cut): one roof face may span several units where
      // its neighbour across the ridge is divided.
      bool confirmed = true;
      int confirmations = 0;
      for (int k : members) {
        const RoofPlaneHypothesis& q = planes[k];
        if (k == i || !CutReaches(cut, q.patch) ||
            std::abs(q.plane.head<3>().dot(p.plane.head<3>())) >= cos_max)
          continue;
        bool seen = false;
        for (const auto* marks_q : {&q.lines_xy, &q.colour_breaks})
          for (const auto& lq : *marks_q) {
            const Eigen::Vector2d dq = lq[1] - lq[0];
            seen = seen || (dq.norm() >= o.party_confirm_length_m &&
                            std::abs(dq.dot(across)) <= sin_max * dq.norm() &&
                            std::abs(across.dot(lq[0]) + cut.offset) <= o.party_confirm_offset_m &&
                            std::abs(across.dot(lq[1]) + cut.offset) <= o.party_confirm_offset_m);
          }
        confirmed = confirmed && seen;
        confirmations += seen;
      }
      if (!confirmed || (from_colour && confirmations == 0)) continue;
      return cut;
    }
  }
  return std::nullopt;
}

// Connected pieces of `active` (ascending plane indices) under `links`,
// each ascending, ordered by their smallest index.
std::vector<std::vector<int>> ConnectedPieces(const std::vector<int>& active,
                                              const std::vector<std::vector<int>>& links) {
  std::map<int, int> piece_of;  // plane -> piece, -1 unvisited
  for (int i : active) piece_of[i] = -1;
  std::vector<std::vector<int>> pieces;
  for (int start : active) {
    if (piece_of[start] >= 0) continue;
    const int id = static_cast<int>(pieces.size());
    pieces.emplace_back();
    std::vector<int> stack{start};
    piece_of[start] = id;
    while (!stack.empty()) {
      const int i = stack.back();
      stack.pop_back();
      pieces[id].push_back(i);
      for (int j : links[i]) {
        auto it = piece_of.find(j);
        if (it == piece_of.end() || it->second >= 0) continue;
        it->second = id;
        stack.push_back(j);
      }
    }
    std::sort(pieces[id].begin(), pieces[id].end());
  }
  return pieces;
}

// The roof polygons of one solid.
std::vector<Polygon3> RoofFaces(const Building& solid) {
  std::vector<Polygon3> roofs;
  for (const Surface& s : solid.surfaces)
    if (s.type == SurfaceType::kRoof)
      roofs.insert(roofs.end(), s.polygons.begin(), s.polygons.end());
  return roofs;
}

// The ridge of a single-face (shed) roof: its highest vertices.
struct ShedRidge {
  bool valid = false;
  Eigen::Vector2d downhill = Eigen::Vector2d::Zero();                        // unit, plan
  Eigen::Vector2d a = Eigen::Vector2d::Zero(), b = Eigen::Vector2d::Zero();  // ends, plan
  double z = 0;
};

ShedRidge RidgeOfShed(const Building& solid) {
  ShedRidge r;
  const std::vector<Polygon3> roofs = RoofFaces(solid);
  if (ClassifyRoofType(roofs) != roof_type::kMonopitch) return r;
  const Polygon3* face = &roofs.front();
  for (const Polygon3& p : roofs)
    if (p.Area() > face->Area()) face = &p;
  const Eigen::Vector3d n = face->Normal();
  const Eigen::Vector2d g(n.x(), n.y());
  if (g.norm() < std::sin(10 * kDeg)) return r;
  r.downhill = g.normalized();
  const Eigen::Vector2d along(-r.downhill.y(), r.downhill.x());
  double top = -std::numeric_limits<double>::infinity();
  for (const auto& v : face->exterior) top = std::max(top, v.z());
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& v : face->exterior) {
    if (v.z() < top - 0.15) continue;
    const double s = along.dot(v.head<2>());
    if (s < lo) lo = s, r.a = v.head<2>();
    if (s > hi) hi = s, r.b = v.head<2>();
  }
  r.z = top;
  r.valid = hi - lo > 0.5;
  return r;
}

// The two faces of one gable built as two shed-roof solids (see
// AssemblyOptions::join_gable_halves): their join keys made one.
void JoinGableHalves(const std::vector<Building>& solids, const AssemblyOptions& o,
                     std::vector<std::string>* key) {
  const size_t n = solids.size();
  std::vector<ShedRidge> ridge(n);
  for (size_t i = 0; i < n; ++i) ridge[i] = RidgeOfShed(solids[i]);
  UnionFind uf(static_cast<int>(n));
  std::map<std::string, size_t> first_of_key;
  for (size_t i = 0; i < n; ++i)
    if (!(*key)[i].empty()) {
      const auto [it, fresh] = first_of_key.emplace((*key)[i], i);
      if (!fresh) uf.Join(static_cast<int>(it->second), static_cast<int>(i));
    }
  bool joined = false;
  const double cos_apart = std::cos(20 * kDeg);
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 1; j < n; ++j) {
      const ShedRidge& p = ridge[i];
      const ShedRidge& q = ridge[j];
      if (!p.valid || !q.valid ||
          solids[i].double_attributes.at("building_group") !=
              solids[j].double_attributes.at("building_group") ||
          -p.downhill.dot(q.downhill) < cos_apart || std::abs(p.z - q.z) > o.gable_ridge_max_step_m)
        continue;
      // q's ridge ends within the offset of p's ridge line, and the two
      // overlap along it over half the shorter one.
      const Eigen::Vector2d along = (p.b - p.a).normalized();
      const Eigen::Vector2d across(-along.y(), along.x());
      if (std::abs(across.dot(q.a - p.a)) > o.gable_ridge_max_offset_m ||
          std::abs(across.dot(q.b - p.a)) > o.gable_ridge_max_offset_m)
        continue;
      const double p0 = 0, p1 = along.dot(p.b - p.a);
      double q0 = along.dot(q.a - p.a), q1 = along.dot(q.b - p.a);
      if (q0 > q1) std::swap(q0, q1);
      const double common = std::min(p1, q1) - std::max(p0, q0);
      if (common < 0.5 * std::min(p1 - p0, q1 - q0)) continue;
      uf.Join(static_cast<int>(i), static_cast<int>(j));
      joined = true;
    }
  if (!joined) return;
  std::map<int, int> size;
  for (size_t i = 0; i < n; ++i) ++size[uf.Find(static_cast<int>(i))];
  for (size_t i = 0; i < n; ++i) {
    const int root = uf.Find(static_cast<int>(i));
    if (size[root] > 1) (*key)[i] = StrFormat("joined %d", root);
  }
}

// The solids with one key become the parts of one building (an empty key
// stands alone). With footprints the key is the footprint's id: the solids
// built over one footprint (wings or units at different heights, pieces
// split where one envelope could not roof them) are one building carrying
// the id, as a cadastre's user counts and joins them; the pieces of a
// multipolygon footprint share its id and so its building. Without, it is
// building_group. Top-level ids run in order; parts are
// "<building id>_p<k>"; `plane_building` follows.
void JoinParts(const std::vector<std::string>& key_of_building, bool footprint_keys,
               AssemblyResult* res) {
  std::vector<Building> solids = std::move(res->model.buildings);
  res->model.buildings.clear();
  std::map<std::string, std::string> renamed;
  std::map<std::string, std::vector<size_t>> of_key;
  for (size_t i = 0; i < solids.size(); ++i)
    if (!key_of_building[i].empty()) of_key[key_of_building[i]].push_back(i);
  std::vector<bool> done(solids.size(), false);
  for (size_t i = 0; i < solids.size(); ++i) {
    if (done[i]) continue;
    const std::string& key = key_of_building[i];
    const std::string id = StrFormat("rs_b%04d", static_cast<int>(res->model.buildings.size()) + 1);
    if (key.empty() || of_key[key].size() == 1) {
      renamed[solids[i].id] = id;
      solids[i].id = id;
      res->model.buildings.push_back(std::move(solids[i]));
      done[i] = true;
      continue;
    }
    Building b;
    b.id = id;
    if (footprint_keys)
      b.string_attributes["footprint_id"] = key;
    else
      b.double_attributes["building_group"] = solids[i].double_attributes.at("building_group");
    double planes = 0, lines = 0, score = 0, photometric = 0, area = 0;
    std::set<std::string> outlines;  // what the parts' walls stand on
    for (size_t k : of_key[key]) {
      Building& part = solids[k];
      done[k] = true;
      const auto outline = part.string_attributes.find("outline");
      if (outline != part.string_attributes.end()) outlines.insert(outline->second);
      const std::string part_id =
          StrFormat("%s_p%d", id.c_str(), static_cast<int>(b.parts.size()) + 1);
      renamed[part.id] = part_id;
      part.id = part_id;
      const auto& a = part.double_attributes;
      planes += a.at("roof_planes");
      lines += a.at("supporting_lines");
      score += a.at("reliability");
      photometric += a.at("photometric_score") * a.at("roof_planes");
      area += a.at("footprint_m2");
      b.parts.push_back(std::move(part));
    }
    // The roof type of the largest part: a house with an annex is gabled,
    // as cadastres and city models label it, and the parts say the rest.
    const auto largest =
        std::max_element(b.parts.begin(), b.parts.end(), [](const Building& x, const Building& y) {
          return x.double_attributes.at("footprint_m2") < y.double_attributes.at("footprint_m2");
        });
    b.roof_type = largest->roof_type;
    // ... unless the parts' faces together make a gable (or a half-hipped
    // one): its two faces built apart as shed roofs, back to back.
    std::vector<Polygon3> faces;
    for (const Building& part : b.parts) {
      const std::vector<Polygon3> roofs = RoofFaces(part);
      faces.insert(faces.end(), roofs.begin(), roofs.end());
    }
    const int together = ClassifyRoofType(faces);
    if (together == roof_type::kGabled || together == roof_type::kHalfHipped)
      b.roof_type = together;
    b.measured_height = b.RoofTopZ() - b.GroundZ();
    if (!outlines.empty()) {
      std::string& outline = b.string_attributes["outline"];
      for (const std::string& o : outlines) outline += (outline.empty() ? "" : "; ") + o;
    }
    b.double_attributes["building_parts"] = static_cast<double>(b.parts.size());
    b.double_attributes["roof_planes"] = planes;
    b.double_attributes["supporting_lines"] = lines;
    b.double_attributes["reliability"] = score;
    b.double_attributes["photometric_score"] = planes > 0 ? photometric / planes : 0.0;
    b.double_attributes["footprint_m2"] = area;
    res->model.buildings.push_back(std::move(b));
  }
  for (std::string& pb : res->plane_building)
    if (!pb.empty()) pb = renamed.at(pb);
}

// A building as the assembly built it: the planes roofing it (indices into
// the assembly's planes) and its outline.
struct BuiltOutline {
  std::vector<int> active;
  Ring2 outline;
  std::string name;  // "building hypothesis N", as the log names it (ids change when parts join)
};

// How much of the pieces the patches of `active` cover (each plane's share
// summed, at most the pieces' area).
double SeenOver(const std::vector<RoofPlaneHypothesis>& planes, const std::vector<int>& active,
                const std::vector<Ring2>& pieces) {
  double seen = 0;
  for (const Ring2& r : pieces)
    for (int i : active) seen += IntersectionArea(planes[i].patch, r);
  return std::min(seen, AreaOfPieces(pieces));
}

// See AssemblyOptions::max_building_overlap_m2. Buildings are compared in
// their order, each loser rebuilt before the next pair is looked at, so the
// result is deterministic.
void SeparateOverlappingBuildings(const std::vector<RoofPlaneHypothesis>& planes,
                                  const std::vector<int>& origin, const std::vector<Ring2>& grown,
                                  const GroundModel& ground, const AssemblyOptions& o,
                                  std::vector<BuiltOutline>* built,
                                  std::vector<std::string>* join_key, AssemblyResult* res) {
  std::vector<Building>& buildings = res->model.buildings;
  std::vector<char> gone(buildings.size(), 0);
  for (size_t a = 0; a < buildings.size(); ++a)
    for (size_t b = a + 1; b < buildings.size() && !gone[a]; ++b) {
      if (gone[b] || (!(*join_key)[a].empty() && (*join_key)[a] == (*join_key)[b])) continue;
      BuiltOutline &A = (*built)[a], &B = (*built)[b];
      if (!BoundsMeet(RingBounds(A.outline), RingBounds(B.outline))) continue;
      const std::vector<Ring2> overlap = IntersectPolygons(A.outline, B.outline);
      const double area = AreaOfPieces(overlap);
      if (!(area > o.max_building_overlap_m2)) continue;
      const double seen_a = SeenOver(planes, A.active, overlap);
      const double seen_b = SeenOver(planes, B.active, overlap);
      if (!(std::abs(seen_a - seen_b) >= o.overlap_min_seen_margin * area)) continue;
      const bool a_loses = seen_a < seen_b;
      const size_t lose = a_loses ? a : b, win = a_loses ? b : a;
      BuiltOutline& L = (*built)[lose];
      Building& old = buildings[lose];
      const std::string why = StrFormat(
          "overlaps %s by %.1f m2 in plan, seen there over %.1f m2 against %.1f m2",
          (*built)[win].name.c_str(), area, a_loses ? seen_a : seen_b, a_loses ? seen_b : seen_a);
      bool holed = false;
      const Ring2 rest = LargestRing(
          DifferencePolygons(L.outline, (*built)[win].outline, o.overlap_min_width_m, &holed));
      // The other lies inside its outline (a lower annex in a courtyard, a
      // tower over a wing): no outline without a hole is left, and the
      // larger building is not given up for the smaller.
      if (holed) continue;
      std::vector<int> active = L.active;
      std::optional<Building> rebuilt;
      Envelope e;
      while (rest.size() >= 3 && std::abs(SignedArea(rest)) >= o.min_footprint_m2 &&
             !active.empty()) {
        e = LowerEnvelope(planes, active, rest, grown, ground, o, o.min_support);
        if (e.worst >= 0) {
          active.erase(active.begin() + e.worst);
          continue;
        }
        if (!std::isfinite(e.ground_z)) break;
        Building nb = BuildSolid(planes, active, e, o);
        nb.id = old.id;
        nb.double_attributes["building_group"] = old.double_attributes.at("building_group");
        if (CheckBuildingSolid(nb).Valid()) rebuilt = std::move(nb);
        break;
      }
      if (!rebuilt && rest.size() >= 3 && std::abs(SignedArea(rest)) >= o.min_footprint_m2) {
        // Left as it was: a building that cannot be rebuilt is better kept
        // overlapping than lost.
        res->rejected.push_back(L.name + ": " + why + "; could not be rebuilt without it");
        continue;
      }
      for (int i : L.active) {
        if (rebuilt && std::find(active.begin(), active.end(), i) != active.end()) continue;
        if (res->plane_building[origin[i]] == old.id) {
          res->plane_building[origin[i]].clear();
          res->plane_reason[origin[i]] = L.name + ": " + why;
        }
      }
      if (!rebuilt) {
        res->rejected.push_back(L.name + ": " + why + ", less than " +
                                StrFormat("%.1f m2 left", o.min_footprint_m2));
        gone[lose] = 1;
        continue;
      }
      res->rejected.push_back(L.name + ": " + why + ", built again without it");
      old = std::move(*rebuilt);
      L.active = std::move(active);
      L.outline = e.outline;
    }
  std::vector<Building> kept_buildings;
  std::vector<BuiltOutline> kept_built;
  std::vector<std::string> kept_keys;
  for (size_t k = 0; k < buildings.size(); ++k) {
    if (gone[k]) continue;
    kept_buildings.push_back(std::move(buildings[k]));
    kept_built.push_back(std::move((*built)[k]));
    kept_keys.push_back(std::move((*join_key)[k]));
  }
  buildings = std::move(kept_buildings);
  *built = std::move(kept_built);
  *join_key = std::move(kept_keys);
}

}  // namespace

AssemblyResult AssembleBuildings(const std::vector<RoofPlaneHypothesis>& input,
                                 const GroundModel& ground, const AssemblyOptions& options,
                                 const std::vector<Footprint>& footprints) {
  const AssemblyOptions o = AssemblyOptionsFor(options, !footprints.empty());
  AssemblyResult res;
  res.planes_in = static_cast<int>(input.size());
  res.plane_building.assign(input.size(), "");
  res.plane_reason.assign(input.size(), "");

  // 1. Plausible roof planes, cut at the footprints when there are any.
  std::vector<std::vector<int>> kept_for;  // per input plane: the planes it was kept for meeting
  const std::vector<int> plausible = PlausiblePlanes(input, ground, o, &res.rejected, &kept_for);
  std::vector<char> dropped(input.size(), 0);  // per input plane, once the assembly dropped it
  std::vector<RoofPlaneHypothesis> planes;
  std::vector<int> footprint_of, origin;  // per plane: footprint index or -1, input index
  if (footprints.empty()) {
    for (int i : plausible) {
      planes.push_back(input[i]);
      if (planes.back().id.empty()) planes.back().id = StrFormat("plane %d", i);
      footprint_of.push_back(-1);
      origin.push_back(i);
    }
  } else {
    planes =
        CutAtFootprints(input, plausible, footprints, o, &footprint_of, &origin, &res.rejected);
  }
  const int n = static_cast<int>(planes.size());
  auto name = [&](int i) { return planes[i].id; };

  // 2. Buildings: patches that touch and whose planes meet there, over
  // the same footprint.
  UnionFind uf(n);
  // Convex parts as links rather than a union-find: when a plane is
  // dropped below, what it held together may fall apart into separate
  // buildings.
  std::vector<std::vector<int>> part_links(n);
  // The part links whose planes cross along the strip where they meet (see
  // AssemblyOptions::split_across_edges): a part whose envelope keeps every
  // face still falls apart where only crossing-across links hold it
  // together. Applied after the envelope rather than to the links, so that
  // a plane the envelope drops (a false plane in the gap between two
  // roofs) is not rescued as a part of its own.
  const bool split_across = o.split_across_edges && footprints.empty();
  std::vector<std::vector<int>> edge_links(n);
  std::vector<Ring2> grown(n);
  for (int i = 0; i < n; ++i) grown[i] = GrowConvex(planes[i].patch, o.adjacency_gap_m);
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      if (footprint_of[i] != footprint_of[j]) continue;
      if (!PlanesMeet(planes[i], grown[i], planes[j], grown[j], o)) continue;
      uf.Join(i, j);
      // A ridge or hip (each plane lies below the other's extension over
      // its own patch) keeps both planes in one convex part; a valley
      // (each lies above) separates parts, whose lower envelopes are built
      // apart: one envelope over both would cut the higher wing away.
      const Eigen::Vector2d ci = Centroid(planes[i].patch), cj = Centroid(planes[j].patch);
      const bool convex =
          PlaneZ(planes[i].plane, ci) <= PlaneZ(planes[j].plane, ci) + o.max_step_m &&
          PlaneZ(planes[j].plane, cj) <= PlaneZ(planes[i].plane, cj) + o.max_step_m;
      if (convex || !o.split_at_valleys) {
        part_links[i].push_back(j);
        part_links[j].push_back(i);
        if (!split_across ||
            CrossAlongMeet(planes[i], grown[i], planes[j], grown[j], o.edge_min_along)) {
          edge_links[i].push_back(j);
          edge_links[j].push_back(i);
        }
      }
    }
  // Building hypotheses as a queue: a hypothesis that falls apart when a
  // plane is dropped goes on as one hypothesis per connected piece.
  std::vector<int> all(n);
  std::iota(all.begin(), all.end(), 0);
  // Each with whether it was split off its group (a hidden neighbour, a
  // roof beyond an edge, a piece no longer touching): then it is a
  // building of its own, not a part of the group's (join_parts_per_group).
  struct Hypothesis {
    int root;
    std::vector<int> members;
    bool split_off = false;
  };
  std::deque<Hypothesis> groups;
  for (std::vector<int>& piece : ConnectedPieces(all, part_links))
    groups.push_back({piece.front(), std::move(piece)});
  res.hypotheses = static_cast<int>(groups.size());
  std::vector<int> built_over(footprints.size(), 0);
  std::vector<std::vector<int>> planes_over(footprints.size());
  for (int i = 0; i < n; ++i)
    if (footprint_of[i] >= 0) planes_over[footprint_of[i]].push_back(i);
  // Per footprint: 0 not tried yet, 1 built over its whole outline, -1 not.
  std::vector<int> whole(footprints.size(), 0);

  // building_group per hypothesis root; the two sides of a party cut are
  // buildings of their own.
  std::map<int, double> group_of;
  int building_no = 0;
  // Per building: the parts of one building share it (JoinParts); empty
  // when it stands alone.
  std::vector<std::string> join_key;
  std::vector<BuiltOutline> built;  // per building: its planes and outline
  while (!groups.empty()) {
    const int root = groups.front().root;
    std::vector<int> members = std::move(groups.front().members);
    const bool split_off = groups.front().split_off;
    groups.pop_front();
    if (o.split_at_party_lines && footprints.empty()) {
      if (const auto cut = FindPartyCut(planes, members, o)) {
        std::vector<int> side[2];
        for (int i : members) {
          const Ring2 a =
              ClipHalfPlane(planes[i].patch, cut->normal.x(), cut->normal.y(), cut->offset);
          const Ring2 b =
              ClipHalfPlane(planes[i].patch, -cut->normal.x(), -cut->normal.y(), -cut->offset);
          const double area_a = a.size() >= 3 ? std::abs(SignedArea(a)) : 0.0;
          const double area_b = b.size() >= 3 ? std::abs(SignedArea(b)) : 0.0;
          // Beyond the cut's stretch a plane is not cut; it goes with the
          // side that holds more of it.
          const bool reached = CutReaches(*cut, planes[i].patch);
          if (area_b < o.min_face_area_m2 || (!reached && area_a >= area_b)) {
            side[0].push_back(i);
          } else if (area_a < o.min_face_area_m2 || !reached) {
            side[1].push_back(i);
          } else {
            // Both pieces go on: this plane keeps side a, a copy side b.
            const int j = static_cast<int>(planes.size());
            RoofPlaneHypothesis q = planes[i];
            q.patch = b;
            q.id += " (party cut)";
            planes[i].patch = a;
            planes.push_back(std::move(q));
            grown[i] = GrowConvex(planes[i].patch, o.adjacency_gap_m);
            grown.push_back(GrowConvex(planes[j].patch, o.adjacency_gap_m));
            footprint_of.push_back(-1);
            origin.push_back(origin[i]);
            std::vector<int> links = part_links[i];
            part_links.push_back(std::move(links));
            for (int k : part_links[i]) part_links[k].push_back(j);
            std::vector<int> along = edge_links[i];
            edge_links.push_back(std::move(along));
            for (int k : edge_links[i]) edge_links[k].push_back(j);
            side[0].push_back(i);
            side[1].push_back(j);
          }
        }
        if (!side[0].empty() && !side[1].empty()) {
          ++res.party_cuts;
          group_of[side[1].front()] = static_cast<double>(input.size() + res.party_cuts);
          const auto kept = group_of.find(root);
          group_of[side[0].front()] =
              kept != group_of.end() ? kept->second : static_cast<double>(origin[uf.Find(root)]);
          groups.push_front({side[1].front(), std::move(side[1]), split_off});
          groups.push_front({side[0].front(), std::move(side[0]), split_off});
          ++res.hypotheses;
          continue;
        }
      }
    }
    ++building_no;
    const std::string bname = StrFormat("building hypothesis %d", building_no);
    const int f = footprint_of[root];
    const Footprint* fp = f >= 0 ? &footprints[f] : nullptr;
    std::optional<Envelope> env;
    std::optional<Building> solid;  // built (and found valid) over the footprint already
    std::vector<int> active = members;
    std::string outline_source = "roof planes";
    // 3a. A footprint is the outline of one building made of all the
    // planes over it, when their lower envelope is seen over the whole of
    // it: the walls stand on the footprint, as in cadastre-based LoD2. The
    // faces must be seen over more of their area than in the fallback
    // below: a plane seen over half a footprint is more often one side of a
    // roof whose other side was missed than a shed roof, and one wing's
    // plane reaching over the other wing of an L (a valley) is never seen
    // there.
    if (fp) {
      if (whole[f] == 1) {
        --res.hypotheses;  // its planes are in the footprint's building
        continue;
      }
      if (whole[f] == 0) {
        whole[f] = -1;
        const bool one_flat =
            planes_over[f].size() == 1 &&
            SlopeDeg(planes[planes_over[f][0]].plane.head<3>()) <= o.footprint_flat_max_slope_deg;
        Envelope e =
            LowerEnvelope(planes, planes_over[f], fp->outline, grown, ground, o,
                          one_flat ? o.footprint_flat_min_support : o.footprint_min_support);
        if (e.worst < 0 && std::isfinite(e.ground_z))
          solid = BuildSolid(planes, planes_over[f], e, o);
        if (solid && CheckBuildingSolid(*solid).Valid()) {
          env = std::move(e);
          active = planes_over[f];
          outline_source = "footprint";
          whole[f] = 1;
        } else {
          solid.reset();
        }
      }
    }
    // 3b. The convex hull of the patches (cut at the footprint), dropping
    // planes that bound the roof where the images did not see them, until
    // every face is supported.
    while (!env) {
      std::vector<Eigen::Vector2d> all;
      for (int i : active) all.insert(all.end(), planes[i].patch.begin(), planes[i].patch.end());
      Ring2 outline =
          SquareCorners(FollowBorderLines(ConvexHull(all), planes, active, o), planes, active, o);
      if (fp && outline.size() >= 3) {
        outline = LargestIntersection(outline, fp->outline);
        outline_source = "roof planes cut at the footprint";
      }
      if (outline.size() < 3) break;
      Envelope e = LowerEnvelope(planes, active, outline, grown, ground, o, o.min_support);
      if (e.worst < 0) {
        std::vector<std::vector<int>> parts;
        if (split_across) parts = ConnectedPieces(active, edge_links);
        if (parts.size() > 1) {
          for (size_t k = 1; k < parts.size(); ++k) {
            groups.push_back({root, std::move(parts[k]), true});
            ++res.hypotheses;
          }
          active = std::move(parts[0]);
          continue;
        }
        env = std::move(e);
        break;
      }
      // Hidden planes go on together with the hidden planes they form a
      // convex part with (both sides of the higher neighbour's gable),
      // the piece holding the largest hidden patch first.
      std::vector<int> hidden;
      int largest = -1;
      double largest_patch = 0;
      if (o.split_hidden)
        for (size_t k = 0; k < active.size(); ++k) {
          const double patch = std::abs(SignedArea(planes[active[k]].patch));
          if (patch < o.min_face_area_m2 || e.face_area[k] >= o.hidden_max_fraction * patch)
            continue;
          if (o.hidden_duplicate_overlap < 1 &&
              HiddenWhereOthersWereSeen(planes, active, k, o.hidden_duplicate_overlap))
            continue;
          hidden.push_back(active[k]);
          if (patch > largest_patch) largest = active[k], largest_patch = patch;
        }
      if (!hidden.empty() && hidden.size() < active.size()) {
        for (std::vector<int>& piece : ConnectedPieces(hidden, part_links)) {
          if (std::find(piece.begin(), piece.end(), largest) == piece.end()) continue;
          for (int i : piece) active.erase(std::find(active.begin(), active.end(), i));
          groups.push_back({root, std::move(piece), true});
          ++res.hypotheses;
          break;
        }
      } else {
        res.rejected.push_back(name(active[e.worst]) + e.worst_reason);
        dropped[origin[active[e.worst]]] = 1;
        active.erase(active.begin() + e.worst);
      }
      if (active.empty()) break;
      // One envelope over the hull of pieces that no longer touch would
      // roof the gap between them and let one house's planes cut the other.
      std::vector<std::vector<int>> pieces = ConnectedPieces(active, part_links);
      for (size_t k = 1; k < pieces.size(); ++k) {
        groups.push_back({root, std::move(pieces[k]), true});
        ++res.hypotheses;
      }
      active = std::move(pieces[0]);
    }
    if (!env) {
      for (int i : active) dropped[origin[i]] = 1;
      res.rejected.push_back(bname + ": no roof plane left");
      continue;
    }
    // The planes of a hypothesis that fails as a whole share its reason.
    auto reject = [&](const std::string& why) {
      res.rejected.push_back(bname + ": " + why);
      for (int i : active) {
        res.plane_reason[origin[i]] = bname + ": " + why;
        dropped[origin[i]] = 1;
      }
    };
    if (o.drop_lone_companions && footprints.empty() && active.size() == 1) {
      const std::vector<int>& anchors = kept_for[origin[active[0]]];
      if (!anchors.empty() &&
          std::all_of(anchors.begin(), anchors.end(), [&](int a) { return dropped[a] != 0; })) {
        reject("its only plane was kept for meeting roof planes that were dropped");
        continue;
      }
    }
    const double area = SignedArea(env->outline);
    if (area < o.min_footprint_m2) {
      reject(StrFormat("footprint %.1f m2 < %.1f m2", area, o.min_footprint_m2));
      continue;
    }
    if (!std::isfinite(env->ground_z)) {
      reject("no ground height under the outline");
      continue;
    }

    Building b = solid ? std::move(*solid) : BuildSolid(planes, active, *env, o);
    b.id = StrFormat("rs_b%04d", static_cast<int>(res.model.buildings.size()) + 1);
    // Convex parts of one building (split at valleys) share this number;
    // without footprints they become its parts (join_parts_per_group).
    const auto group = group_of.find(root);
    b.double_attributes["building_group"] =
        group != group_of.end() ? group->second : static_cast<double>(origin[uf.Find(root)]);
    if (fp) {
      b.string_attributes["footprint_id"] = fp->id;
      b.string_attributes["outline"] =
          fp->holes > 0 ? outline_source + StrFormat(" (%d courtyards not modelled)", fp->holes)
                        : outline_source;
    }
    const SolidCheckResult check = CheckBuildingSolid(b);
    if (!check.Valid()) {
      reject("solid not valid (" + check.Summary() + ")");
      continue;
    }
    for (int i : active) res.plane_building[origin[i]] = b.id;
    if (f >= 0) ++built_over[f];
    if (!footprints.empty())
      join_key.push_back(fp && o.join_parts_per_footprint ? fp->id : "");
    else
      join_key.push_back(o.join_parts_per_group && !split_off
                             ? StrFormat("%.0f", b.double_attributes.at("building_group"))
                             : "");
    res.model.buildings.push_back(std::move(b));
    built.push_back({active, env->outline, bname});
  }
  if (footprints.empty() && o.max_building_overlap_m2 > 0)
    SeparateOverlappingBuildings(planes, origin, grown, ground, o, &built, &join_key, &res);
  if (footprints.empty() && o.join_gable_halves) JoinGableHalves(res.model.buildings, o, &join_key);
  JoinParts(join_key, !footprints.empty(), &res);
  // Input planes, not their pieces (cut at footprints or party walls).
  for (const std::string& b : res.plane_building) res.planes_used += !b.empty();
  // Every footprint ends as a building or a reason; the pieces of a
  // multipolygon footprint (one id) together.
  std::map<std::string, std::pair<int, int>> by_id;  // id -> (solids built, planes over)
  std::vector<std::string> order;
  for (size_t f = 0; f < footprints.size(); ++f) {
    auto [it, first] = by_id.try_emplace(footprints[f].id, 0, 0);
    if (first) order.push_back(footprints[f].id);
    it->second.first += built_over[f];
    it->second.second += static_cast<int>(planes_over[f].size());
  }
  for (const std::string& id : order) {
    const auto [built, planes_over_it] = by_id[id];
    if (built > 0) continue;
    const std::string why = planes_over_it > 0 ? "its roof planes did not make a valid building"
                                               : "no roof plane found over it";
    res.footprint_rejection[id] = {why, res.rejected.size()};
    res.rejected.push_back("footprint " + id + ": " + why);
  }
  return res;
}

}  // namespace roofsweep
