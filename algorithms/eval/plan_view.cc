#include "algorithms/eval/plan_view.h"

#include <cmath>
#include <numeric>

namespace roofsweep::eval {
namespace {

constexpr double kDegToRad = M_PI / 180.0;

struct Candidate {
  int surface, polygon;
  Eigen::Vector3d normal;  // upward unit
  Eigen::Vector3d point;   // a point on the plane (vertex mean)
  double weight;           // 3D area, for the area-weighted plane normal
  MultiPolygon2 plan;
  Box2 box;
};

int Find(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

double MaxPlaneDistance(const Polygon3& p, const Eigen::Vector3d& n, const Eigen::Vector3d& q) {
  double d = 0;
  for (const auto& v : p.exterior) d = std::max(d, std::abs(n.dot(v - q)));
  return d;
}

}  // namespace

Eigen::Vector3d UpwardNormal(const Polygon3& polygon) {
  Eigen::Vector3d n = polygon.Normal();
  if (n.z() < 0) n = -n;
  return n;
}

Polygon2 ProjectXY(const Polygon3& polygon) {
  Polygon2 out;
  for (const auto& v : polygon.exterior) out.outer.push_back(v.head<2>());
  for (const auto& h : polygon.holes) {
    Ring2 r;
    for (const auto& v : h) r.push_back(v.head<2>());
    out.holes.push_back(std::move(r));
  }
  return out;
}

RoofPlaneSet ExtractRoofPlanes(const CityModel& model, const RoofPlaneOptions& options) {
  RoofPlaneSet set;
  const double min_nz = std::sin((90.0 - options.vertical_roof_deg) * kDegToRad);
  const double cos_coplanar = std::cos(options.coplanar_angle_deg * kDegToRad);
  for (int b = 0; b < static_cast<int>(model.buildings.size()); ++b) {
    const Building& building = model.buildings[b];
    std::vector<Candidate> cands;
    std::vector<const Polygon3*> polys;
    for (int s = 0; s < static_cast<int>(building.surfaces.size()); ++s) {
      const Surface& surface = building.surfaces[s];
      if (surface.type != SurfaceType::kRoof) continue;
      for (int p = 0; p < static_cast<int>(surface.polygons.size()); ++p) {
        const Polygon3& poly = surface.polygons[p];
        ++set.roof_polygons;
        const Eigen::Vector3d raw = poly.Normal();
        if (raw.isZero() || poly.exterior.size() < 3) {
          ++set.degenerate_polygons;
          continue;
        }
        if (raw.z() < 0) ++set.downward_polygons;
        const Eigen::Vector3d n = raw.z() < 0 ? Eigen::Vector3d(-raw) : raw;
        if (n.z() < min_nz) {
          ++set.vertical_polygons;
          continue;
        }
        UnionStats stats;
        MultiPolygon2 plan = MakeRegion({ProjectXY(poly)}, &stats);
        set.degenerate_polygons += stats.degenerate;
        set.invalid_polygons += stats.invalid;
        if (plan.empty()) continue;
        Eigen::Vector3d mean = Eigen::Vector3d::Zero();
        for (const auto& v : poly.exterior) mean += v;
        mean /= static_cast<double>(poly.exterior.size());
        Box2 box = BoundsOf(plan);
        cands.push_back({s, p, n, mean, std::abs(poly.Area()), std::move(plan), box});
        polys.push_back(&poly);
      }
    }
    // Union-find over coplanar, touching pairs; O(k²) per building is fine
    // for the tens to hundreds of roof polygons a building has.
    const int k = static_cast<int>(cands.size());
    std::vector<int> parent(k);
    std::iota(parent.begin(), parent.end(), 0);
    for (int i = 0; i < k; ++i)
      for (int j = i + 1; j < k; ++j) {
        const Candidate& a = cands[i];
        const Candidate& c = cands[j];
        if (a.normal.dot(c.normal) < cos_coplanar) continue;
        if (!a.box.Intersects(c.box, options.group_gap_m)) continue;
        if (MaxPlaneDistance(*polys[j], a.normal, a.point) > options.coplanar_distance_m ||
            MaxPlaneDistance(*polys[i], c.normal, c.point) > options.coplanar_distance_m)
          continue;
        if (Find(parent, i) == Find(parent, j)) continue;
        if (Distance(a.plan, c.plan) > options.group_gap_m) continue;
        parent[Find(parent, j)] = Find(parent, i);
      }
    std::vector<int> plane_of(k, -1);
    std::vector<std::vector<Polygon2>> pieces;
    std::vector<Eigen::Vector3d> normal_sum;
    const size_t first = set.planes.size();
    for (int i = 0; i < k; ++i) {
      const int root = Find(parent, i);
      if (plane_of[root] < 0) {
        plane_of[root] = static_cast<int>(set.planes.size() - first);
        set.planes.emplace_back();
        set.planes.back().building = b;
        pieces.emplace_back();
        normal_sum.push_back(Eigen::Vector3d::Zero());
      }
      const int g = plane_of[root];
      RoofPlane& plane = set.planes[first + g];
      plane.polygons.emplace_back(cands[i].surface, cands[i].polygon);
      for (const auto& pp : cands[i].plan) pieces[g].push_back(pp);
      normal_sum[g] += cands[i].weight * cands[i].normal;
    }
    for (size_t g = 0; g < pieces.size(); ++g) {
      RoofPlane& plane = set.planes[first + g];
      plane.normal = normal_sum[g].normalized();
      plane.plan = std::move(pieces[g]);  // already checked by MakeRegion
      plane.outline = Outline(plane.plan);
      plane.plan_area = Area(plane.plan);
      plane.box = BoundsOf(plane.plan);
    }
  }
  return set;
}

MultiPolygon2 BuildingFootprint(const Building& building, const RoofPlaneOptions& options) {
  std::vector<Polygon2> ground, roof;
  const double min_nz = std::sin((90.0 - options.vertical_roof_deg) * kDegToRad);
  for (const auto& s : building.surfaces) {
    if (s.type == SurfaceType::kGround) {
      for (const auto& p : s.polygons) ground.push_back(ProjectXY(p));
    } else if (s.type == SurfaceType::kRoof) {
      for (const auto& p : s.polygons)
        if (std::abs(p.Normal().z()) >= min_nz) roof.push_back(ProjectXY(p));
    }
  }
  return MakeRegion(ground.empty() ? roof : ground);
}

}  // namespace roofsweep::eval
