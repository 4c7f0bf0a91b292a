#include "algorithms/sweep/eave_planes.h"

#include <cmath>

#include "algorithms/buildings/convex_polygon2.h"
#include "algorithms/geometry/slope.h"
#include "algorithms/sweep/plane_fit.h"

namespace roofsweep {

std::vector<std::string> FlatPlanesBeyondEaves(const std::vector<RoofPlaneHypothesis>& planes,
                                               const EavePlaneOptions& o) {
  std::vector<std::string> why(planes.size());
  for (size_t f = 0; f < planes.size(); ++f) {
    const RoofPlaneHypothesis& F = planes[f];
    if (F.patch.size() < 3 || SlopeDeg(F.plane.head<3>()) > o.max_flat_slope_deg) continue;
    Eigen::Vector2d c = Eigen::Vector2d::Zero();
    for (const auto& q : F.patch) c += q;
    c /= static_cast<double>(F.patch.size());
    int counted = 0;
    bool all = true;
    std::string faces;
    for (const auto& l : F.lines_xy) {
      const Eigen::Vector2d d = l[1] - l[0];
      const double len = d.norm();
      if (len < o.min_line_m) continue;
      ++counted;
      const Eigen::Vector2d m = 0.5 * (l[0] + l[1]);
      Eigen::Vector2d n(-d.y() / len, d.x() / len);
      if ((c - m).dot(n) > 0) n = -n;  // n points away from the flat patch
      const double zf = PlaneZ(F.plane, m.x(), m.y());
      bool eave = false;
      for (size_t p = 0; p < planes.size() && !eave; ++p) {
        const RoofPlaneHypothesis& P = planes[p];
        if (p == f || P.patch.size() < 3 || SlopeDeg(P.plane.head<3>()) < o.min_face_slope_deg)
          continue;
        const Eigen::Vector2d beyond = m + o.probe_m * n;
        if (!InsideConvex(P.patch, beyond) || InsideConvex(P.patch, c)) continue;
        if (std::abs(PlaneZ(P.plane, m.x(), m.y()) - zf) > o.max_height_step_m) continue;
        if (PlaneZ(P.plane, beyond.x(), beyond.y()) - zf < o.min_rise_m) continue;
        eave = true;
        faces += (faces.empty() ? "" : ", ") + P.id;
      }
      if (!eave) {
        all = false;
        break;
      }
    }
    if (all && counted >= 1)
      why[f] = "flat, at the eaves of " + faces + " only (the yard or a terrace beyond them)";
  }
  return why;
}

}  // namespace roofsweep
