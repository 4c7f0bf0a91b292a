#include "algorithms/edges/edge_linking.h"

#include <cmath>

namespace roofsweep {
namespace {

constexpr double kPi = 3.14159265358979323846;

// What linking reads of an edge point, in 16 bytes rather than the
// point's 32: position and unit gradient.
struct LinkPoint {
  float x, y, ux, uy;
};

LinkPoint ToLinkPoint(const EdgePoint& p) {
  const float n = std::sqrt(p.gx * p.gx + p.gy * p.gy);
  return n > 0 ? LinkPoint{p.x, p.y, p.gx / n, p.gy / n} : LinkPoint{p.x, p.y, 1.f, 0.f};
}

}  // namespace

std::vector<std::vector<int>> LinkEdgePoints(const EdgeMap& map, double max_angle_deg,
                                             int min_points) {
  const auto& pts = map.points;
  const int n = static_cast<int>(pts.size());
  const float min_cos = static_cast<float>(std::cos(max_angle_deg * kPi / 180.0));
  std::vector<LinkPoint> lp(n);
  for (int i = 0; i < n; ++i) lp[i] = ToLinkPoint(pts[i]);

  // best[2 i + side]: the nearest compatible neighbour on that side of the
  // tangent (side 0: along +t, t = gradient turned by +90°).
  std::vector<int> best(2 * static_cast<size_t>(n), -1);
  auto side_of = [&](int i, int j) {
    const float dx = lp[j].x - lp[i].x;
    const float dy = lp[j].y - lp[i].y;
    const float along = -lp[i].uy * dx + lp[i].ux * dy;
    return along > 0 ? 0 : 1;
  };
  // The 8 neighbours in the raster index, in the order that breaks ties
  // between equally near ones (row by row, left to right).
  const int w = map.index.cols;
  const int neighbours[8] = {-w - 1, -w, -w + 1, -1, 1, w - 1, w, w + 1};
  const int* index = map.index.ptr<int>(0);
  for (int i = 0; i < n; ++i) {
    const LinkPoint p = lp[i];
    const int* centre = index + static_cast<size_t>(pts[i].py) * w + pts[i].px;
    float best_d2[2] = {1e30f, 1e30f};
    for (int o : neighbours) {
      const int j = centre[o];
      if (j < 0) continue;
      const LinkPoint q = lp[j];
      if (std::fabs(p.ux * q.ux + p.uy * q.uy) < min_cos) continue;
      const float ex = q.x - p.x;
      const float ey = q.y - p.y;
      const float along = -p.uy * ex + p.ux * ey;
      const float across = p.ux * ex + p.uy * ey;
      if (std::fabs(across) >= std::fabs(along)) continue;
      const int side = along > 0 ? 0 : 1;
      const float d2 = ex * ex + ey * ey;
      if (d2 < best_d2[side]) {
        best_d2[side] = d2;
        best[2 * i + side] = j;
      }
    }
  }

  std::vector<int> link(2 * static_cast<size_t>(n), -1);
  for (int i = 0; i < n; ++i) {
    for (int side = 0; side < 2; ++side) {
      const int j = best[2 * i + side];
      if (j >= 0 && best[2 * j + side_of(j, i)] == i) link[2 * i + side] = j;
    }
  }

  std::vector<std::vector<int>> chains;
  std::vector<char> visited(n, 0);
  std::vector<int> chain;
  auto walk = [&](int start) {
    chain.clear();
    int prev = -1;
    int cur = start;
    while (cur >= 0 && !visited[cur]) {
      visited[cur] = 1;
      chain.push_back(cur);
      const int a = link[2 * cur];
      const int b = link[2 * cur + 1];
      const int next = a >= 0 && a != prev ? a : (b != prev ? b : -1);
      prev = cur;
      cur = next;
    }
    if (static_cast<int>(chain.size()) >= min_points) chains.push_back(chain);
  };
  // Open chains first, from an end; what is left are closed loops.
  for (int i = 0; i < n; ++i) {
    if (!visited[i] && (link[2 * i] < 0 || link[2 * i + 1] < 0)) walk(i);
  }
  for (int i = 0; i < n; ++i) {
    if (!visited[i]) walk(i);
  }
  return chains;
}

}  // namespace roofsweep
