#include "algorithms/buildings/footprint_growth.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "algorithms/buildings/polygon2.h"

namespace roofsweep {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The convex hull of a ∩ b (b may be non-convex); empty when they do not
// overlap.
Ring2 HullOfIntersection(const Ring2& a, const Ring2& b) {
  std::vector<Eigen::Vector2d> pts;
  for (const Ring2& r : IntersectPolygons(a, b)) pts.insert(pts.end(), r.begin(), r.end());
  return pts.size() < 3 ? Ring2{} : ConvexHull(std::move(pts));
}

}  // namespace

std::vector<PatchExtension> ExtensionsAlongFootprints(
    const std::vector<RoofPlaneHypothesis>& planes, const std::vector<Footprint>& footprints,
    const FootprintGrowthOptions& o) {
  const size_t nf = footprints.size(), np = planes.size();
  std::vector<Eigen::Vector4d> fb(nf), pb(np);
  for (size_t f = 0; f < nf; ++f) fb[f] = RingBounds(footprints[f].outline);
  for (size_t i = 0; i < np; ++i) pb[i] = RingBounds(planes[i].patch);
  const double min_gradient = std::sin(o.min_slope_deg * M_PI / 180);
  const double coplanar = std::cos(o.coplanar_angle_deg * M_PI / 180);
  std::vector<PatchExtension> out;
  for (size_t f = 0; f < nf; ++f) {
    const Ring2& outline = footprints[f].outline;
    // The pieces of every plane over this footprint.
    std::vector<int> over;
    std::vector<Ring2> piece;
    for (size_t i = 0; i < np; ++i) {
      if (!BoundsMeet(fb[f], pb[i])) continue;
      Ring2 p = HullOfIntersection(planes[i].patch, outline);
      if (p.empty() || std::abs(SignedArea(p)) < o.min_piece_m2) continue;
      over.push_back(static_cast<int>(i));
      piece.push_back(std::move(p));
    }
    for (size_t k = 0; k < over.size(); ++k) {
      const RoofPlaneHypothesis& q = planes[over[k]];
      const Eigen::Vector2d g = q.plane.head<2>();
      if (g.norm() < min_gradient) continue;
      // u down the fall line, t along the contour lines; the piece spans
      // [s0, s1] down and [p0, p1] along.
      const Eigen::Vector2d u = g.normalized(), t(-u.y(), u.x());
      double s0 = kInf, s1 = -kInf, p0 = kInf, p1 = -kInf, lo = kInf, hi = -kInf;
      for (const auto& v : piece[k]) {
        s0 = std::min(s0, u.dot(v)), s1 = std::max(s1, u.dot(v));
        p0 = std::min(p0, t.dot(v)), p1 = std::max(p1, t.dot(v));
      }
      for (const auto& v : outline) lo = std::min(lo, t.dot(v)), hi = std::max(hi, t.dot(v));
      lo -= 1, hi += 1;  // past the footprint: the clip to it decides
      auto band = [&](double a, double b) {
        return Ring2{s0 * u + a * t, s1 * u + a * t, s1 * u + b * t, s0 * u + b * t};
      };
      const Ring2 whole = band(lo, hi);
      for (size_t j = 0; j < over.size(); ++j) {
        if (j == k || planes[over[j]].plane.head<3>().dot(q.plane.head<3>()) >= coplanar) continue;
        for (const Ring2& r : IntersectPolygons(whole, piece[j])) {
          if (std::abs(SignedArea(r)) < o.stop_min_m2) continue;
          double ja = kInf, jb = -kInf;
          for (const auto& v : r) ja = std::min(ja, t.dot(v)), jb = std::max(jb, t.dot(v));
          // A patch that overlaps this one along the band is a rival the
          // conflicts let stand, not a face beyond it.
          if (ja >= p1) hi = std::min(hi, ja);
          if (jb <= p0) lo = std::max(lo, jb);
        }
      }
      auto propose = [&](Ring2 patch, const std::string& how) {
        PatchExtension e;
        e.plane = over[k];
        e.strip = q;
        e.strip.patch = std::move(patch);
        e.strip.id = q.id + how + footprints[f].id;
        out.push_back(std::move(e));
      };
      // The strips of the footprint beyond the piece along the band, up to
      // the stops.
      const std::pair<double, double> sides[2] = {{lo, p0}, {p1, hi}};
      for (const auto& [a, b] : sides) {
        if (!(b > a)) continue;
        Ring2 strip = HullOfIntersection(band(a, b), outline);
        if (strip.empty() || std::abs(SignedArea(strip)) < o.min_strip_m2) continue;
        propose(std::move(strip), " grown along footprint ");
      }
      if (!o.fill_band) continue;
      // Within the band: what the face's own rectangle (contour lines by
      // fall line, in the footprint) holds beyond each edge of the piece.
      // A convex piece leaves out the rectangle's corners, each beyond one
      // of its edges (a triangle from an eave and a verge leaves one).
      const Ring2 rect = HullOfIntersection(band(p0, p1), outline);
      if (rect.size() < 3) continue;
      const Ring2& pc = piece[k];
      for (size_t m = 0; m < pc.size(); ++m) {
        const Eigen::Vector2d a = pc[m], b = pc[(m + 1) % pc.size()];
        // Beyond a counter-clockwise edge: to its right, r . (x - a) >= 0.
        const Eigen::Vector2d r(b.y() - a.y(), a.x() - b.x());
        Ring2 corner = ClipHalfPlane(rect, -r.x(), -r.y(), r.dot(a));
        if (corner.size() < 3 || std::abs(SignedArea(corner)) < o.min_strip_m2) continue;
        // Another face's patch there: the corner is that face's (a hip
        // end beside a triangular hip face), not this one's.
        bool taken = false;
        for (size_t j = 0; j < over.size() && !taken; ++j)
          taken = j != k && planes[over[j]].plane.head<3>().dot(q.plane.head<3>()) < coplanar &&
                  IntersectionArea(corner, piece[j]) >= o.stop_min_m2;
        if (!taken) propose(std::move(corner), " filled within footprint ");
      }
    }
  }
  return out;
}

}  // namespace roofsweep
