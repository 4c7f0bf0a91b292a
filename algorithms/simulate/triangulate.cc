#include "algorithms/simulate/triangulate.h"

#include <Eigen/Geometry>
#include <cmath>

namespace roofsweep {
namespace sim {

std::vector<std::array<int, 3>> TriangulatePolygon(const std::vector<Eigen::Vector3d>& ring) {
  std::vector<std::array<int, 3>> out;
  const int n = static_cast<int>(ring.size());
  if (n < 3) return out;
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  for (int i = 0; i < n; ++i) normal += ring[i].cross(ring[(i + 1) % n]);
  int ax = 0;
  normal.cwiseAbs().maxCoeff(&ax);
  const int i0 = (ax + 1) % 3, i1 = (ax + 2) % 3;
  const double sign = normal[ax] >= 0 ? 1.0 : -1.0;
  std::vector<Eigen::Vector2d> p(n);
  for (int i = 0; i < n; ++i) p[i] = Eigen::Vector2d(ring[i][i0], sign * ring[i][i1]);
  auto cross = [&](int a, int b, int c) {
    return (p[b] - p[a]).x() * (p[c] - p[a]).y() - (p[b] - p[a]).y() * (p[c] - p[a]).x();
  };
  std::vector<int> idx(n);
  for (int i = 0; i < n; ++i) idx[i] = i;
  int guard = 0;
  while (idx.size() > 3 && guard++ < 4 * n * n) {
    const int m = static_cast<int>(idx.size());
    bool clipped = false;
    for (int k = 0; k < m && !clipped; ++k) {
      const int a = idx[(k + m - 1) % m], b = idx[k], c = idx[(k + 1) % m];
      if (cross(a, b, c) <= 1e-12) continue;  // reflex or collinear
      bool empty = true;
      for (int q : idx) {
        if (q == a || q == b || q == c) continue;
        if (cross(a, b, q) >= 0 && cross(b, c, q) >= 0 && cross(c, a, q) >= 0) {
          empty = false;
          break;
        }
      }
      if (!empty) continue;
      out.push_back({a, b, c});
      idx.erase(idx.begin() + k);
      clipped = true;
    }
    if (!clipped) break;
  }
  if (idx.size() == 3) {
    out.push_back({idx[0], idx[1], idx[2]});
  } else if (idx.size() > 3) {
    // Degenerate remainder (collinear runs): close it with a fan.
    for (size_t k = 1; k + 1 < idx.size(); ++k) out.push_back({idx[0], idx[k], idx[k + 1]});
  }
  return out;
}

}  // namespace sim
}  // namespace roofsweep
