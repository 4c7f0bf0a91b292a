#include "algorithms/matching/junction_support.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <cmath>

namespace roofsweep {
namespace {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using Point = bg::model::point<double, 3, bg::cs::cartesian>;
using Box = bg::model::box<Point>;
using Value = std::pair<Box, int>;

constexpr double kPi = 3.14159265358979323846;

// Distance from p to segment s (unit direction d) prolonged by `extend`
// at both ends.
double DistanceToProlonged(const Eigen::Vector3d& p, const Segment3& s, const Eigen::Vector3d& d,
                           double extend) {
  const double len = s.Length();
  const double t = std::clamp((p - s.a).dot(d), -extend, len + extend);
  return (p - (s.a + t * d)).norm();
}

bool ShareKey(const std::vector<std::pair<int, int>>& a,
              const std::vector<std::pair<int, int>>& b) {
  for (const auto& k : a)
    if (std::find(b.begin(), b.end(), k) != b.end()) return true;
  return false;
}

}  // namespace

std::vector<int> JunctionSupport(const std::vector<Segment3>& lines,
                                 const std::vector<std::vector<std::pair<int, int>>>& keys,
                                 const JunctionSupportOptions& o) {
  const int n = static_cast<int>(lines.size());
  std::vector<int> out(n, 0);
  const double pad = o.distance_m + o.extend_m;
  std::vector<Value> boxes;
  boxes.reserve(n);
  // Once per line, not once per candidate pair.
  std::vector<Eigen::Vector3d> dir(n);
  for (int i = 0; i < n; ++i) dir[i] = lines[i].Direction();
  for (int i = 0; i < n; ++i) {
    const Segment3& s = lines[i];
    if (!(s.Length() > 0)) continue;
    const Eigen::Vector3d lo = s.a.cwiseMin(s.b).array() - pad;
    const Eigen::Vector3d hi = s.a.cwiseMax(s.b).array() + pad;
    boxes.push_back({Box(Point(lo.x(), lo.y(), lo.z()), Point(hi.x(), hi.y(), hi.z())), i});
  }
  const bgi::rtree<Value, bgi::quadratic<16>> tree(boxes.begin(), boxes.end());
  const double max_cos = std::cos(o.min_angle_deg * kPi / 180.0);
  // Each hypothesis is counted on its own, so the parallel loop gives the
  // serial result.
  tbb::parallel_for(0, n, [&](int i) {
    const Segment3& s = lines[i];
    if (!(s.Length() > 0)) return;
    std::vector<Value> hits;
    for (const Eigen::Vector3d& e : {s.a, s.b}) {
      hits.clear();  // the second end's candidates only (the first end's are far from it)
      tree.query(bgi::intersects(Point(e.x(), e.y(), e.z())), std::back_inserter(hits));
      for (const Value& h : hits) {
        const int j = h.second;
        if (j == i || std::abs(dir[i].dot(dir[j])) > max_cos) continue;
        if (DistanceToProlonged(e, lines[j], dir[j], o.extend_m) > o.distance_m) continue;
        if (ShareKey(keys[i], keys[j])) continue;
        ++out[i];
        break;
      }
    }
  });
  return out;
}

}  // namespace roofsweep
