#include "algorithms/buildings/footprint_completion.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "algorithms/buildings/polygon2.h"
#include "algorithms/geometry/slope.h"

namespace roofsweep {
namespace {

constexpr const char* kExtended = " extended over footprint ";

// Plan distance between two rings that do not overlap (vertex to edge,
// both ways).
double RingGap(const Ring2& a, const Ring2& b) {
  double d = std::numeric_limits<double>::infinity();
  for (int pass = 0; pass < 2; ++pass) {
    const Ring2& p = pass ? b : a;
    const Ring2& q = pass ? a : b;
    for (const auto& v : p)
      for (size_t i = 0; i < q.size(); ++i)
        d = std::min(d, PointSegmentDistance(v, q[i], q[(i + 1) % q.size()]));
  }
  return d;
}

}  // namespace

std::vector<RoofPlaneHypothesis> PlanesFromNeighbourFootprints(
    const std::vector<RoofPlaneHypothesis>& planes, const std::vector<Footprint>& footprints,
    const FootprintCompletionOptions& o) {
  const size_t nf = footprints.size();
  // The planes over each footprint; bounding boxes keep the clipping to
  // the pairs that can meet (a city tile has thousands of footprints).
  std::vector<Eigen::Vector4d> fb(nf), pb(planes.size());
  for (size_t f = 0; f < nf; ++f) fb[f] = RingBounds(footprints[f].outline);
  for (size_t i = 0; i < planes.size(); ++i) pb[i] = RingBounds(planes[i].patch);
  std::vector<std::vector<int>> over(nf);
  for (size_t f = 0; f < nf; ++f)
    for (size_t i = 0; i < planes.size(); ++i)
      if (BoundsMeet(fb[f], pb[i]) &&
          IntersectionArea(planes[i].patch, footprints[f].outline) >= o.min_over_neighbour_m2)
        over[f].push_back(static_cast<int>(i));
  const Eigen::Vector4d gap(-o.neighbour_gap_m, -o.neighbour_gap_m, o.neighbour_gap_m,
                            o.neighbour_gap_m);
  auto same_plane = [&](const RoofPlaneHypothesis& a, const RoofPlaneHypothesis& b) {
    return a.plane.head<3>().dot(b.plane.head<3>()) >= std::cos(o.same_angle_deg * M_PI / 180) &&
           std::abs(a.plane[3] - b.plane[3]) <= o.same_offset_m;
  };
  std::vector<RoofPlaneHypothesis> out;
  for (size_t f = 0; f < nf; ++f) {
    const Ring2& outline = footprints[f].outline;
    if (std::abs(SignedArea(outline)) <= 0) continue;
    const Ring2 hull = ConvexHull(outline);
    std::vector<RoofPlaneHypothesis> mine;
    for (size_t g = 0; g < nf; ++g) {
      if (g == f || over[g].empty() || !BoundsMeet(fb[f] + gap, fb[g]) ||
          RingGap(outline, footprints[g].outline) > o.neighbour_gap_m)
        continue;
      for (int i : over[g]) {
        const RoofPlaneHypothesis& p = planes[i];
        Ring2 patch = hull;
        const Eigen::Vector2d n2 = p.plane.head<2>();
        if (n2.norm() > 1e-6) {
          // The band the neighbour's patch spans across the slope.
          const Eigen::Vector2d u = n2.normalized();
          double lo = std::numeric_limits<double>::infinity(), hi = -lo;
          for (const auto& v : p.patch) lo = std::min(lo, v.dot(u)), hi = std::max(hi, v.dot(u));
          patch = ClipHalfPlane(patch, u.x(), u.y(), -hi);   // v.u <= hi
          patch = ClipHalfPlane(patch, -u.x(), -u.y(), lo);  // v.u >= lo
        }
        if (patch.size() < 3 || SignedArea(patch) < o.min_patch_m2) continue;
        bool same = false;
        for (const RoofPlaneHypothesis& q : mine) same = same || same_plane(q, p);
        // The footprint has this plane over the band already. A plane of
        // its own over part of the band, or another plane there, does not
        // stop the proposal: verification and conflict management choose.
        for (int j : over[f])
          same = same || (same_plane(planes[j], p) && IntersectionArea(planes[j].patch, patch) >=
                                                          o.same_cover * SignedArea(patch));
        if (same) continue;
        RoofPlaneHypothesis q = p;
        q.patch = std::move(patch);
        q.score = 0;
        q.derived = true;
        q.lines_xy.clear();  // the neighbour's lines bound the neighbour
        // Named after the plane the sweep found, not the chain of houses.
        q.id = p.id.substr(0, p.id.find(kExtended)) + kExtended + footprints[f].id;
        mine.push_back(std::move(q));
      }
    }
    for (RoofPlaneHypothesis& q : mine) out.push_back(std::move(q));
  }
  return out;
}

std::vector<int> BareFootprints(const std::vector<RoofPlaneHypothesis>& planes,
                                const std::vector<Footprint>& footprints, double min_cover) {
  std::vector<Eigen::Vector4d> pb(planes.size());
  for (size_t i = 0; i < planes.size(); ++i) pb[i] = RingBounds(planes[i].patch);
  std::vector<int> bare;
  for (size_t f = 0; f < footprints.size(); ++f) {
    const Ring2& outline = footprints[f].outline;
    const double area = std::abs(SignedArea(outline));
    if (!(area > 0)) continue;
    const Eigen::Vector4d b = RingBounds(outline);
    double covered = 0;
    for (size_t i = 0; i < planes.size() && covered < min_cover * area; ++i) {
      if (!BoundsMeet(pb[i], b)) continue;
      covered += IntersectionArea(planes[i].patch, outline);
    }
    if (covered < min_cover * area) bare.push_back(static_cast<int>(f));
  }
  return bare;
}

std::vector<FootprintBeyondRidge> FootprintsBeyondRidges(
    const std::vector<RoofPlaneHypothesis>& planes, const std::vector<Footprint>& footprints,
    const BeyondRidgeOptions& o) {
  const double min_gradient = std::sin(o.min_slope_deg * M_PI / 180);
  const double same = std::cos(o.same_angle_deg * M_PI / 180);
  std::vector<Eigen::Vector4d> pb(planes.size());
  for (size_t i = 0; i < planes.size(); ++i) pb[i] = RingBounds(planes[i].patch);
  std::vector<FootprintBeyondRidge> out;
  for (size_t f = 0; f < footprints.size(); ++f) {
    const Ring2& outline = footprints[f].outline;
    const double area = std::abs(SignedArea(outline));
    if (!(area > 0)) continue;
    const Eigen::Vector4d b = RingBounds(outline);
    int face = -1;
    bool one = true;
    std::vector<Ring2> pieces;
    for (size_t i = 0; i < planes.size() && one; ++i) {
      if (!BoundsMeet(pb[i], b)) continue;
      const std::vector<Ring2> in = IntersectPolygons(planes[i].patch, outline);
      const double a = AreaOfPieces(in);
      if (a < std::max(2.0, o.min_face_fraction * area)) continue;
      if (face < 0) face = static_cast<int>(i);
      one = planes[i].plane.head<3>().dot(planes[face].plane.head<3>()) >= same;
      pieces.insert(pieces.end(), in.begin(), in.end());
    }
    if (face < 0 || !one) continue;
    // n = (a, b, c), c > 0: the face rises against (a, b).
    const Eigen::Vector2d g = planes[face].plane.head<2>();
    if (g.norm() < min_gradient) continue;
    const Eigen::Vector2d up = -g.normalized(), along(-up.y(), up.x());
    double top = -std::numeric_limits<double>::infinity(), reach = 0;
    for (const Ring2& r : pieces)
      for (const auto& v : r) top = std::max(top, up.dot(v));
    for (const auto& v : outline) reach = std::max(reach, (v - outline[0]).norm());
    // A box from the top line uphill past the footprint, clipped to it.
    const Eigen::Vector2d o0 = top * up + along.dot(outline[0]) * along;
    const Eigen::Vector2d w = 2 * reach * along, h = 2 * reach * up;
    const Ring2 part = LargestIntersection({o0 - w, o0 + w, o0 + w + h, o0 - w + h}, outline);
    if (part.size() < 3) continue;
    const double a = SignedArea(part);
    if (a < o.min_fraction * area || a < o.min_area_m2) continue;
    FootprintBeyondRidge r;
    r.part.id = footprints[f].id + " beyond " + planes[face].id;
    r.part.outline = part;
    r.footprint = static_cast<int>(f);
    r.plane = face;
    r.face_slope_deg = SlopeDeg(planes[face].plane.head<3>());
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace roofsweep
