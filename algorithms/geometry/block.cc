#include "algorithms/geometry/block.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace roofsweep {

double GroundModel::HeightAt(double x, double y) const {
  if (grid && grid->rows > 0 && grid->cols > 0) {
    const Grid& g = *grid;
    const double fc = (x - g.x0) / g.dx - 0.5;
    const double fr = (g.y0 - y) / g.dy - 0.5;
    const int c0 = static_cast<int>(std::floor(fc)), r0 = static_cast<int>(std::floor(fr));
    const double tc = fc - c0, tr = fr - r0;
    double sum = 0, wsum = 0;
    for (int dr = 0; dr <= 1; ++dr) {
      for (int dc = 0; dc <= 1; ++dc) {
        const int r = std::clamp(r0 + dr, 0, g.rows - 1), c = std::clamp(c0 + dc, 0, g.cols - 1);
        const float z = g.z[static_cast<size_t>(r) * g.cols + c];
        if (std::isnan(z)) continue;
        const double w = (dr ? tr : 1 - tr) * (dc ? tc : 1 - tc);
        sum += w * z;
        wsum += w;
      }
    }
    if (wsum > 1e-9) return sum / wsum;
  }
  if (height) return *height;
  return std::numeric_limits<double>::quiet_NaN();
}

Eigen::Vector4d GroundModel::PlaneAt(double x, double y, double radius) const {
  const double z = HeightAt(x, y);
  if (!std::isfinite(z)) return Eigen::Vector4d::Constant(std::numeric_limits<double>::quiet_NaN());
  auto slope = [&](double ax, double ay) {
    const double s =
        (HeightAt(x + ax * radius, y + ay * radius) - HeightAt(x - ax * radius, y - ay * radius)) /
        (2 * radius);
    return std::isfinite(s) ? s : 0.0;
  };
  const double gx = radius > 0 ? slope(1, 0) : 0.0, gy = radius > 0 ? slope(0, 1) : 0.0;
  if (gx == 0 && gy == 0) return Eigen::Vector4d(0, 0, 1, -z);
  const Eigen::Vector3d n = Eigen::Vector3d(-gx, -gy, 1).normalized();
  return Eigen::Vector4d(n.x(), n.y(), n.z(), -n.dot(Eigen::Vector3d(x, y, z)));
}

int Block::FindView(const std::string& name) const {
  for (size_t i = 0; i < views.size(); ++i)
    if (views[i].name == name) return static_cast<int>(i);
  return -1;
}

}  // namespace roofsweep
