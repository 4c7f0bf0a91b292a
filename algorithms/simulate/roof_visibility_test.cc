#include "algorithms/simulate/roof_visibility.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "algorithms/simulate/presets.h"

namespace roofsweep {
namespace sim {
namespace {

SimulatedView Nadir(double x, double y, double z) {
  SimulatedView v;
  v.name = "nadir";
  v.camera.width = v.camera.height = 800;
  v.camera.fx = v.camera.fy = 1000;
  v.camera.cx = v.camera.cy = 400;
  Eigen::Matrix3d R;
  R << 1, 0, 0, 0, -1, 0, 0, 0, -1;  // camera z = world -z
  v.pose.R = R;
  v.pose.C = Eigen::Vector3d(x, y, z);
  return v;
}

// Roofs seen from straight above are seen whole; a tree crown put over one
// building hides its roof, and a view that looks elsewhere sees nothing.
TEST(RoofVisibility, ATreeOverARoofHidesIt) {
  SimulationOptions o = SimulationPreset("easy");
  o.scene.extent_x = o.scene.extent_y = 60;
  o.scene.building_count = 3;
  o.scene.tree_count = 0;
  o.scene.clutter = false;
  Scene scene = GenerateScene(o.scene, 4);
  ASSERT_GE(scene.city.buildings.size(), 2u);
  ASSERT_FALSE(scene.materials.empty());
  // The crown over the first building's roof, wide enough to cover it.
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e9), hi = -lo;
  for (const Surface& s : scene.city.buildings[0].surfaces)
    for (const Polygon3& p : s.polygons)
      for (const Eigen::Vector3d& v : p.exterior) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  // Any material: the geometry is what counts here.
  Tree t;
  t.material = 0;
  t.base = Eigen::Vector3d(0.5 * (lo.x() + hi.x()), 0.5 * (lo.y() + hi.y()), lo.z());
  t.trunk_height = hi.z() - lo.z() + 1;
  t.crown_radius = 0.55 * (hi - lo).head<2>().norm();
  t.crown_height = 4;
  scene.trees.push_back(t);
  const Renderer renderer(scene, o.render);
  const std::vector<SimulatedView> views = {Nadir(0, 0, 150), Nadir(5000, 5000, 150)};
  const std::vector<RoofPolygonVisibility> vis = RoofVisibility(renderer, scene, views);
  ASSERT_FALSE(vis.empty());
  int hidden = 0, seen = 0;
  for (const RoofPolygonVisibility& r : vis) {
    ASSERT_EQ(r.seen.size(), 2u);
    EXPECT_EQ(r.seen[1], 0.0f);  // that view looks 7 km away
    if (r.building == 0) {
      EXPECT_LT(r.seen[0], 0.05f);
      ++hidden;
    } else {
      // Roofs clear of the crown are seen whole.
      const auto& poly = scene.city.buildings[r.building].surfaces[r.surface].polygons[r.polygon];
      double gap = 1e9;
      for (const Eigen::Vector3d& v : poly.exterior)
        gap = std::min(gap, (v - t.base).head<2>().norm() - t.crown_radius);
      if (gap < 1) continue;
      EXPECT_GT(r.seen[0], 0.9f);
      EXPECT_LE(r.seen[0], 1.0f);
      ++seen;
    }
    const auto& ring =
        scene.city.buildings[r.building].surfaces[r.surface].polygons[r.polygon].exterior;
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (const auto& v : ring) c += v;
    EXPECT_LT((c / ring.size() - r.centroid).norm(), 1e-9);
  }
  EXPECT_GT(hidden, 0);
  EXPECT_GT(seen, 0);
}

}  // namespace
}  // namespace sim
}  // namespace roofsweep
