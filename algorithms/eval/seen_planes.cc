#include "algorithms/eval/seen_planes.h"

#include <cmath>
#include <map>
#include <utility>

#include "algorithms/eval/plan_view.h"

namespace roofsweep {

SeenPlaneScores ScoreSeenPlanes(const CityModel& truth, const EvalResult& eval,
                                const std::vector<SeenPolygon>& polygons,
                                const SeenPlaneOptions& o) {
  // Records bucketed by the cell of their centroid in plan.
  const double cell = std::max(1.0, 4 * o.match_m);
  auto key = [&](double x, double y) {
    return std::make_pair(static_cast<long long>(std::floor(x / cell)),
                          static_cast<long long>(std::floor(y / cell)));
  };
  std::map<std::pair<long long, long long>, std::vector<size_t>> grid;
  for (size_t i = 0; i < polygons.size(); ++i)
    grid[key(polygons[i].centroid.x(), polygons[i].centroid.y())].push_back(i);
  auto find = [&](const Eigen::Vector3d& c) -> const SeenPolygon* {
    const auto [cx, cy] = key(c.x(), c.y());
    const SeenPolygon* best = nullptr;
    double best_d = o.match_m;
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy) {
        const auto it = grid.find({cx + dx, cy + dy});
        if (it == grid.end()) continue;
        for (size_t i : it->second) {
          const double d = (polygons[i].centroid - c).norm();
          if (d <= best_d) best_d = d, best = &polygons[i];
        }
      }
    return best;
  };

  const eval::RoofPlaneSet ref = eval::ExtractRoofPlanes(truth, eval.options.planes);
  SeenPlaneScores s;
  s.views.assign(eval.reference_planes.size(), -1);
  for (size_t r = 0; r < ref.planes.size() && r < eval.reference_planes.size(); ++r) {
    const eval::RoofPlane& rp = ref.planes[r];
    const Building& b = truth.buildings[rp.building];
    std::vector<double> seen;
    double total = 0;
    bool known = true;
    for (const auto& [si, pi] : rp.polygons) {
      const Polygon3& polygon = b.surfaces[si].polygons[pi];
      if (polygon.exterior.empty()) continue;
      Eigen::Vector3d c = Eigen::Vector3d::Zero();
      for (const Eigen::Vector3d& v : polygon.exterior) c += v;
      c /= static_cast<double>(polygon.exterior.size());
      // The polygons of one plane share its slope: their areas weigh them
      // as their plan areas would.
      const double area = std::abs(polygon.Area());
      const SeenPolygon* p = find(c);
      if (!p) {
        known = false;
        break;
      }
      if (seen.empty()) seen.assign(p->seen.size(), 0.0);
      if (p->seen.size() != seen.size()) {
        known = false;
        break;
      }
      for (size_t v = 0; v < seen.size(); ++v) seen[v] += area * p->seen[v];
      total += area;
    }
    const bool tp = eval.reference_planes[r].true_positive;
    if (!known || !(total > 0)) {
      ++s.unknown;
      continue;
    }
    int views = 0;
    for (double f : seen) views += f / total >= o.min_fraction;
    s.views[r] = views;
    if (views >= o.min_views) {
      ++s.seen;
      s.seen_true_positive += tp;
    } else {
      ++s.unseen;
      s.unseen_true_positive += tp;
    }
  }
  return s;
}

}  // namespace roofsweep
