#include "algorithms/buildings/mirror_completion.h"

#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "algorithms/buildings/convex_polygon2.h"
#include "algorithms/buildings/polygon2.h"

namespace roofsweep {
namespace {

constexpr double kDeg = M_PI / 180.0;

// The reflection of p across the plan line through r along unit t.
Eigen::Vector2d Reflect(const Eigen::Vector2d& p, const Eigen::Vector2d& r,
                        const Eigen::Vector2d& t) {
  const Eigen::Vector2d d = p - r;
  return r + 2 * d.dot(t) * t - d;
}

// p's mirror image across the vertical plane through the plan line through
// r along unit t: its patch and the horizontal part of its normal
// reflected, the plane through the reflection of the patch's centroid at
// the centroid's height. No 3D line supports it (lines 0); in plan it
// carries p's lines mirrored, which lie on its edges where the roof is
// symmetric. Where the faces beside it run on over it, they let it meet
// them in the creases of its hips (GroupingOptions::
// conflict_cut_at_crease); the verification's test away from its lines
// looks between them; and the assembly, which asks a plane for a line of
// some length (AssemblyOptions::min_line_length_m), takes the longest of
// them, as it takes a mirrored face's ridge. Derived; the caller names it.
RoofPlaneHypothesis MirrorImage(const RoofPlaneHypothesis& p, const Eigen::Vector2d& r,
                                const Eigen::Vector2d& t) {
  RoofPlaneHypothesis q;
  std::vector<Eigen::Vector2d> mirrored;
  for (const Eigen::Vector2d& v : p.patch) mirrored.push_back(Reflect(v, r, t));
  q.patch = ConvexHull(mirrored);
  const Eigen::Vector3d n = p.plane.head<3>();
  const Eigen::Vector2d nh = 2 * n.head<2>().dot(t) * t - n.head<2>();
  const Eigen::Vector3d m(nh.x(), nh.y(), n.z());
  const Eigen::Vector2d c = FirstMoment(p.patch) / SignedArea(p.patch);
  const Eigen::Vector2d cm = Reflect(c, r, t);
  const Eigen::Vector3d x(cm.x(), cm.y(), -(n.head<2>().dot(c) + p.plane[3]) / n.z());
  q.plane << m, -m.dot(x);
  q.score = 0;
  for (const auto& l : p.lines_xy) {
    q.lines_xy.push_back({Reflect(l[0], r, t), Reflect(l[1], r, t)});
    q.longest_line_m = std::max(q.longest_line_m, (l[1] - l[0]).norm());
  }
  q.similarity = p.similarity;
  q.derived = true;
  return q;
}

// Plane z = g . x + h: its uphill gradient g and height h at the origin.
Eigen::Vector3d Gradient(const Eigen::Vector4d& plane) {
  return Eigen::Vector3d(-plane[0], -plane[1], -plane[3]) / plane[2];
}

// True when a plane whose normal lies within same_angle_deg of `normal`
// covers at least same_cover of `patch` already.
bool Covered(const std::vector<RoofPlaneHypothesis>& planes, const Eigen::Vector3d& normal,
             const Ring2& patch, double same_angle_deg, double same_cover) {
  for (const RoofPlaneHypothesis& q : planes)
    if (q.plane.head<3>().dot(normal) >= std::cos(same_angle_deg * kDeg) &&
        IntersectionArea(q.patch, patch) >= same_cover * SignedArea(patch))
      return true;
  return false;
}

// The level line where p meets a plane falling the other way beyond it
// (see MirrorCompletionOptions::virtual_ridges), as a segment across p's
// patch; of several such planes, the one whose line lies highest on p.
bool VirtualRidge(const RoofPlaneHypothesis& p, const std::vector<RoofPlaneHypothesis>& planes,
                  const MirrorCompletionOptions& o, std::array<Eigen::Vector2d, 2>* out) {
  const Eigen::Vector3d gp = Gradient(p.plane);
  const Eigen::Vector2d up = gp.head<2>().normalized();
  const Eigen::Vector2d t(-up.y(), up.x());
  const double area = std::abs(SignedArea(p.patch));
  if (!(area > 1e-9)) return false;
  double best_at = -std::numeric_limits<double>::infinity();
  for (const RoofPlaneHypothesis& q : planes) {
    if (&q == &p || q.patch.size() < 3 || q.plane[2] <= 0 || !(SignedArea(q.patch) > 1e-9))
      continue;
    const double slope = std::acos(std::min(1.0, q.plane[2]));
    if (slope < o.min_slope_deg * kDeg || slope > o.max_slope_deg * kDeg) continue;
    const Eigen::Vector3d gq = Gradient(q.plane);
    if (gq.head<2>().normalized().dot(up) > -std::cos(o.virtual_ridge_max_turn_deg * kDeg))
      continue;
    // They cross where w . x = hq - hp, w = gp - gq (pointing up p's slope).
    const Eigen::Vector2d w = gp.head<2>() - gq.head<2>();
    const double wn = w.norm();
    if (!(wn > 1e-9) || w.dot(up) < std::cos(o.ridge_max_angle_deg * kDeg) * wn) continue;
    const Eigen::Vector2d m = w / wn;
    const double s = (gq.z() - gp.z()) / wn;
    // q beyond the line, near p.
    if (FirstMoment(q.patch).dot(m) / SignedArea(q.patch) <= s ||
        ConvexDistance(p.patch, q.patch) > o.virtual_ridge_gap_m)
      continue;
    // Along up from the patch's centroid to the line.
    const Eigen::Vector2d c = FirstMoment(p.patch) / SignedArea(p.patch);
    const Eigen::Vector2d r = c + up * (s - c.dot(m)) / up.dot(m);
    const double at = r.dot(up);
    if (at <= best_at) continue;
    const Ring2 below = ClipHalfPlane(p.patch, up.x(), up.y(), -at);
    if (below.size() < 3 || std::abs(SignedArea(below)) < o.ridge_min_below * area) continue;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const Eigen::Vector2d& v : below) {
      lo = std::min(lo, (v - r).dot(t));
      hi = std::max(hi, (v - r).dot(t));
    }
    *out = {r + lo * t, r + hi * t};
    best_at = at;
  }
  return std::isfinite(best_at);
}

}  // namespace

std::vector<RoofPlaneHypothesis> MirroredFaces(const std::vector<RoofPlaneHypothesis>& planes,
                                               const MirrorCompletionOptions& o) {
  std::vector<RoofPlaneHypothesis> out;
  for (const RoofPlaneHypothesis& p : planes) {
    const Eigen::Vector3d n = p.plane.head<3>();
    if (p.patch.size() < 3 || n.z() <= 0) continue;
    const double slope = std::acos(std::min(1.0, n.z()));
    if (slope < o.min_slope_deg * kDeg || slope > o.max_slope_deg * kDeg) continue;
    // z = z(r) + g . (x - r) on the plane; g points uphill.
    const Eigen::Vector2d g = -n.head<2>() / n.z();
    const Eigen::Vector2d up = g.normalized();
    const double area = std::abs(SignedArea(p.patch));
    // The highest level line of the face that has most of its patch below.
    const std::array<Eigen::Vector2d, 2>* ridge = nullptr;
    double ridge_at = -std::numeric_limits<double>::infinity();
    for (const auto& l : p.lines_xy) {
      const Eigen::Vector2d d = l[1] - l[0];
      const double len = d.norm();
      if (len < o.ridge_min_length_m ||
          std::abs(d.dot(up)) > std::sin(o.ridge_max_angle_deg * kDeg) * len)
        continue;
      const double at = 0.5 * (l[0] + l[1]).dot(up);
      if (at <= ridge_at) continue;
      // Downhill of the line: x . up <= at.
      const Ring2 below = ClipHalfPlane(p.patch, up.x(), up.y(), -at);
      if (below.size() < 3 || std::abs(SignedArea(below)) < o.ridge_min_below * area) continue;
      ridge = &l;
      ridge_at = at;
    }
    std::array<Eigen::Vector2d, 2> virtual_ridge;
    if (!ridge && o.virtual_ridges && VirtualRidge(p, planes, o, &virtual_ridge)) {
      ridge = &virtual_ridge;
      ridge_at = 0.5 * (virtual_ridge[0] + virtual_ridge[1]).dot(up);
    }
    if (!ridge) continue;
    // The ridge level: the plane's height at the line's middle; the mirror
    // plane falls from it along -up with the same slope.
    const Eigen::Vector2d r = 0.5 * ((*ridge)[0] + (*ridge)[1]);
    const Eigen::Vector2d t(-up.y(), up.x());
    const double zr = -(n.x() * r.x() + n.y() * r.y() + p.plane[3]) / n.z();
    const Ring2 below = ClipHalfPlane(p.patch, up.x(), up.y(), -ridge_at);
    std::vector<Eigen::Vector2d> mirrored;
    for (const auto& v : below) mirrored.push_back(Reflect(v, r, t));
    Ring2 patch = ConvexHull(mirrored);
    if (patch.size() < 3 || std::abs(SignedArea(patch)) < o.min_patch_m2) continue;
    // Mirror normal: the horizontal part reflected across the ridge's
    // vertical plane, which (the ridge being level) reverses it.
    Eigen::Vector3d m(-n.x(), -n.y(), n.z());
    // Keep the plane exactly through the ridge line at its level.
    const Eigen::Vector3d on(r.x(), r.y(), zr);
    if (Covered(planes, m, patch, o.same_angle_deg, o.same_cover)) continue;
    RoofPlaneHypothesis q;
    q.plane << m, -m.dot(on);
    q.patch = std::move(patch);
    q.score = 0;
    q.lines = 1;
    q.longest_line_m = ((*ridge)[1] - (*ridge)[0]).norm();
    q.similarity = p.similarity;
    q.lines_xy = {*ridge};
    q.derived = true;
    q.id = p.id + " mirrored";
    out.push_back(std::move(q));
  }
  return out;
}

std::vector<RoofPlaneHypothesis> MirroredHipEnds(const std::vector<RoofPlaneHypothesis>& planes,
                                                 const HipEndMirrorOptions& o) {
  // Uphill unit direction in plan of each plane in the slope range; zero
  // for the others.
  // Their plan bounds grown by max_gap_m: only neighbours are measured
  // (a city tile holds thousands of planes).
  std::vector<Eigen::Vector2d> up(planes.size(), Eigen::Vector2d::Zero());
  std::vector<Eigen::Vector4d> box(planes.size());
  for (size_t i = 0; i < planes.size(); ++i) {
    const RoofPlaneHypothesis& p = planes[i];
    if (p.patch.size() < 3 || !(p.plane[2] > 0) || !(std::abs(SignedArea(p.patch)) > 1e-9))
      continue;
    const double slope = std::acos(std::min(1.0, p.plane[2]));
    if (slope < o.min_slope_deg * kDeg || slope > o.max_slope_deg * kDeg) continue;
    up[i] = Gradient(p.plane).head<2>().normalized();
    box[i] = RingBounds(p.patch) + o.max_gap_m * Eigen::Vector4d(-1, -1, 1, 1);
  }
  const double cos_opposite = std::cos(o.opposite_max_turn_deg * kDeg);
  const double cos_end = std::cos(o.end_max_turn_deg * kDeg);
  const double sin_end = std::sin(o.end_max_turn_deg * kDeg);
  std::vector<RoofPlaneHypothesis> out;
  for (size_t h = 0; h < planes.size(); ++h) {
    if (up[h].isZero()) continue;
    const RoofPlaneHypothesis& end = planes[h];
    // The long faces beside it: a pair falling opposite ways whose ridge
    // runs along the end's uphill direction; of several, the pair of most
    // area.
    std::vector<size_t> beside;
    for (size_t i = 0; i < planes.size(); ++i)
      if (i != h && !up[i].isZero() && std::abs(up[i].dot(up[h])) < sin_end &&
          BoundsMeet(box[h], box[i]) && ConvexDistance(end.patch, planes[i].patch) <= o.max_gap_m)
        beside.push_back(i);
    double best_area = 0;
    std::pair<size_t, size_t> pair{0, 0};
    for (size_t a = 0; a < beside.size(); ++a)
      for (size_t b = a + 1; b < beside.size(); ++b) {
        const size_t i = beside[a], j = beside[b];
        if (up[i].dot(up[j]) > -cos_opposite) continue;
        const double area =
            std::abs(SignedArea(planes[i].patch)) + std::abs(SignedArea(planes[j].patch));
        if (area > best_area) best_area = area, pair = {i, j};
      }
    if (!(best_area > 0)) continue;
    // Along the ridge, pointing the way the end rises (into the roof).
    Eigen::Vector2d t(-up[pair.first].y(), up[pair.first].x());
    if (t.dot(up[h]) < 0) t = -t;
    if (t.dot(up[h]) < cos_end) continue;
    // An end meets both long faces in its hips, which rise to the ridge's
    // end: the point where the three planes meet lies at the end's top,
    // on or next to all three patches, with the end below it. A face of
    // another roof beside the pair (a neighbour, a wing at right angles)
    // rises along their ridge too, but meets them elsewhere: one mirrored
    // on `realistic-11` became a second north face a metre and a half
    // below the first.
    Eigen::Matrix3d normals;
    Eigen::Vector3d offsets;
    normals << planes[pair.first].plane.head<3>().transpose(),
        planes[pair.second].plane.head<3>().transpose(), end.plane.head<3>().transpose();
    offsets << -planes[pair.first].plane[3], -planes[pair.second].plane[3], -end.plane[3];
    if (!(std::abs(normals.determinant()) > 1e-6)) continue;
    const Eigen::Vector3d apex = normals.partialPivLu().solve(offsets);
    const Eigen::Vector2d apex_xy = apex.head<2>();
    auto near = [&](const Ring2& patch) {
      return InsideConvex(patch, apex_xy) || DistanceToRing(patch, apex_xy) <= o.max_gap_m;
    };
    double end_top = -std::numeric_limits<double>::infinity();
    for (const Eigen::Vector2d& v : end.patch)
      end_top = std::max(end_top, -(end.plane.head<2>().dot(v) + end.plane[3]) / end.plane[2]);
    if (!near(end.patch) || !near(planes[pair.first].patch) || !near(planes[pair.second].patch) ||
        std::abs(end_top - apex.z()) > o.apex_max_dz_m ||
        !(FirstMoment(end.patch).dot(t) / SignedArea(end.patch) < apex_xy.dot(t)))
      continue;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (size_t i : {pair.first, pair.second})
      for (const Eigen::Vector2d& v : planes[i].patch) {
        lo = std::min(lo, v.dot(t));
        hi = std::max(hi, v.dot(t));
      }
    if (!(hi > lo) ||
        FirstMoment(end.patch).dot(t) / SignedArea(end.patch) - lo > o.end_fraction * (hi - lo))
      continue;
    // The mirror: the vertical plane x . t = mid.
    const double mid = 0.5 * (lo + hi);
    const Eigen::Vector2d on_mirror = mid * t;
    const Eigen::Vector2d along(-t.y(), t.x());
    RoofPlaneHypothesis q = MirrorImage(end, on_mirror, along);
    if (q.patch.size() < 3 || std::abs(SignedArea(q.patch)) < o.min_patch_m2 ||
        Covered(planes, q.plane.head<3>(), q.patch, o.same_angle_deg, o.same_cover))
      continue;
    q.id = end.id + " mirrored along its ridge";
    out.push_back(std::move(q));
  }
  return out;
}

std::vector<RoofPlaneHypothesis> FacesMirroredAcrossFootprints(
    const std::vector<RoofPlaneHypothesis>& planes, const std::vector<Footprint>& footprints,
    const FootprintMirrorOptions& o) {
  const double cos_turn = std::cos(o.max_turn_deg * kDeg);
  std::vector<Eigen::Vector4d> box(planes.size());
  for (size_t i = 0; i < planes.size(); ++i) box[i] = RingBounds(planes[i].patch);
  std::vector<char> one_face(footprints.size(), 0);
  if (o.leave_one_face)
    for (const FootprintBeyondRidge& b : FootprintsBeyondRidges(planes, footprints, o.beyond))
      one_face[b.footprint] = 1;
  std::vector<RoofPlaneHypothesis> out;
  for (size_t fi = 0; fi < footprints.size(); ++fi) {
    if (one_face[fi]) continue;
    const Footprint& f = footprints[fi];
    const Ring2& ring = f.outline;
    const double area = std::abs(SignedArea(ring));
    if (ring.size() < 3 || !(area > 0)) continue;
    const Eigen::Vector2d c = FirstMoment(ring) / SignedArea(ring);
    // The axes: along the longest edge and across it.
    Eigen::Vector2d e = Eigen::Vector2d::Zero();
    for (size_t k = 0; k < ring.size(); ++k) {
      const Eigen::Vector2d d = ring[(k + 1) % ring.size()] - ring[k];
      if (d.norm() > e.norm()) e = d;
    }
    if (!(e.norm() > 0)) continue;
    e.normalize();
    const Eigen::Vector4d fbox = RingBounds(ring);
    for (const Eigen::Vector2d& along : {e, Eigen::Vector2d(-e.y(), e.x())}) {
      const Eigen::Vector2d across(-along.y(), along.x());
      Ring2 reflected;
      for (const Eigen::Vector2d& v : ring) reflected.push_back(Reflect(v, c, along));
      if (IntersectionArea(ring, reflected) < o.min_symmetry * area) continue;
      for (size_t i = 0; i < planes.size(); ++i) {
        const RoofPlaneHypothesis& p = planes[i];
        // A face with no line in plan gives an image with none, which the
        // assembly refuses (AssemblyOptions::min_line_length_m); accepted
        // on the way, it took the footprint from the roof models beyond a
        // ridge (on `realistic-2` the mirror of a plane carried over from
        // the neighbouring footprint, and the gable lost its south face).
        if (p.patch.size() < 3 || !(p.plane[2] > 0) || p.lines_xy.empty() ||
            !BoundsMeet(box[i], fbox))
          continue;
        const double patch_area = std::abs(SignedArea(p.patch));
        const double slope = std::acos(std::min(1.0, p.plane[2]));
        if (!(patch_area > 1e-9) || slope < o.min_slope_deg * kDeg ||
            slope > o.max_slope_deg * kDeg)
          continue;
        const Eigen::Vector2d up = Gradient(p.plane).head<2>().normalized();
        const Eigen::Vector2d pc = FirstMoment(p.patch) / SignedArea(p.patch);
        // Falling away from the axis, as the faces of a gable, a hipped roof
        // or a mansard do; a face rising away from it is a shed's top or a
        // piece of one, whose mirror image is no face (on `realistic-17` the
        // top strip of an 82 m² shed proposed one falling the other way,
        // which the images of that weakly textured roof did not refute).
        const double offset = (pc - c).dot(across);
        if (std::abs(up.dot(across)) < cos_turn || std::abs(offset) < o.min_offset_m ||
            !(up.dot(across) * offset < 0) ||
            IntersectionArea(p.patch, ring) < o.min_inside * patch_area)
          continue;
        RoofPlaneHypothesis q = MirrorImage(p, c, along);
        if (q.patch.size() < 3 || std::abs(SignedArea(q.patch)) < o.min_patch_m2 ||
            Covered(planes, q.plane.head<3>(), q.patch, o.same_angle_deg, o.same_cover))
          continue;
        q.id = p.id + " mirrored across footprint " + f.id;
        out.push_back(std::move(q));
      }
    }
  }
  return out;
}

}  // namespace roofsweep
