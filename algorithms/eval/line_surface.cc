#include "algorithms/eval/line_surface.h"

#include <algorithm>
#include <cmath>

namespace roofsweep::eval {
namespace {

// Lowest and highest surface value within `r` of (x, y); false where the
// grid has no data there.
bool SurfaceRange(const GroundModel::Grid& g, double x, double y, double r, double* lo,
                  double* hi) {
  const int c0 = static_cast<int>(std::floor((x - r - g.x0) / g.dx));
  const int c1 = static_cast<int>(std::floor((x + r - g.x0) / g.dx));
  const int r0 = static_cast<int>(std::floor((g.y0 - (y + r)) / g.dy));
  const int r1 = static_cast<int>(std::floor((g.y0 - (y - r)) / g.dy));
  *lo = INFINITY;
  *hi = -INFINITY;
  for (int row = std::max(r0, 0); row <= std::min(r1, g.rows - 1); ++row)
    for (int col = std::max(c0, 0); col <= std::min(c1, g.cols - 1); ++col) {
      const float z = g.z[static_cast<size_t>(row) * g.cols + col];
      if (!std::isfinite(z)) continue;
      *lo = std::min<double>(*lo, z);
      *hi = std::max<double>(*hi, z);
    }
  return std::isfinite(*lo);
}

}  // namespace

SurfaceAgreement LinesOnSurface(const std::vector<Segment3>& lines, const std::vector<int>& views,
                                const GroundModel::Grid& surface,
                                const SurfaceAgreementOptions& o) {
  SurfaceAgreement out;
  for (size_t k = 0; k < lines.size(); ++k) {
    const Segment3& s = lines[k];
    const int n = std::max(1, static_cast<int>(std::ceil(s.Length() / o.step_m)));
    const double piece = s.Length() / n;
    const int kind = k < views.size() && views[k] >= 3 ? 1 : 0;
    double on = 0, over = 0;
    // Midpoints of n equal pieces.
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector3d p = s.a + (s.b - s.a) * ((i + 0.5) / n);
      double lo, hi;
      if (!SurfaceRange(surface, p.x(), p.y(), o.window_m, &lo, &hi)) continue;
      over += piece;
      if (p.z() >= lo - o.tolerance_m && p.z() <= hi + o.tolerance_m) on += piece;
    }
    if (over <= 0) continue;
    ++out.lines[kind];
    out.length_m[kind] += over;
    out.agreeing_m[kind] += on;
  }
  return out;
}

}  // namespace roofsweep::eval
