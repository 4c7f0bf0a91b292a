#include "algorithms/simulate/scene.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <map>

#include "algorithms/simulate/presets.h"
#include "algorithms/simulate/renderer.h"
#include "algorithms/simulate/scene_truth.h"

namespace roofsweep {
namespace sim {
namespace {

// The bench flight at a quarter of the resolution (same ground coverage,
// 20 cm pixels), with the scene generated over the covered ground as
// Simulate() does.
struct SmallBench {
  Scene scene;
  std::vector<SimulatedView> views;
  std::vector<GeometryMaps> maps;
  std::vector<FaceInfo> faces;
};

SmallBench RenderSmallBench(uint64_t seed) {
  SimulationOptions o = SimulationPreset("bench");
  o.cameras.image_width = o.cameras.image_height = 512;
  o.cameras.gsd *= 4;
  o.cameras.focal_mm /= 4;  // same flying height as the full-size flight
  o.seed = seed;
  SmallBench b;
  b.scene = GenerateScene(FitSceneToFlight(o), seed);
  b.views = LayoutCameras(b.scene.area, b.scene.ground.z, o.cameras, seed);
  const Renderer renderer(b.scene, o.render);
  for (const SimulatedView& v : b.views)
    b.maps.push_back(renderer.RenderGeometry(v.camera, v.pose));
  b.faces = renderer.faces();
  return b;
}

bool IsBuilding(FaceKind k) {
  return k == FaceKind::kRoof || k == FaceKind::kWall || k == FaceKind::kClosure;
}

// Every image is built up: buildings cover a share of each image typical of
// suburban (10-25 %) to urban (30-50 %) aerial images, not empty lawn and
// not solid roofs. The first and last image of a strip are the emptiest:
// buildings seen by only one image are left out.
TEST(Scene, BuildingsFillEveryImage) {
  for (uint64_t seed : {1, 3}) {
    const SmallBench b = RenderSmallBench(seed);
    ASSERT_EQ(b.views.size(), 6u);
    EXPECT_GE(b.scene.city.buildings.size(), 35u);
    EXPECT_LE(b.scene.city.buildings.size(), 75u);
    for (size_t v = 0; v < b.views.size(); ++v) {
      const cv::Mat& face = b.maps[v].face;
      int building = 0, roof_object = 0;
      for (int y = 0; y < face.rows; ++y)
        for (int x = 0; x < face.cols; ++x) {
          const int f = face.at<int>(y, x);
          if (f < 0) continue;
          building += IsBuilding(b.faces[f].kind);
          roof_object += b.faces[f].kind == FaceKind::kProp;
        }
      const double share = static_cast<double>(building) / face.total();
      std::printf("seed %d view %s: buildings %.1f %% of the image, props %.1f %%\n",
                  static_cast<int>(seed), b.views[v].name.c_str(), 100 * share,
                  100.0 * roof_object / face.total());
      EXPECT_GT(share, 0.10) << b.views[v].name;
      EXPECT_LT(share, 0.6) << b.views[v].name;
    }
  }
}

// Every building is seen (at least 8 pixels of 20 cm, i.e. 0.3 m^2) in at
// least two views, so that it can be reconstructed.
TEST(Scene, EveryBuildingVisibleInTwoViews) {
  const SmallBench b = RenderSmallBench(3);
  std::vector<std::map<int, int>> pixels(b.scene.city.buildings.size());  // view -> count
  for (size_t v = 0; v < b.views.size(); ++v) {
    const cv::Mat& face = b.maps[v].face;
    for (int y = 0; y < face.rows; ++y)
      for (int x = 0; x < face.cols; ++x) {
        const int f = face.at<int>(y, x);
        if (f >= 0 && b.faces[f].building >= 0) ++pixels[b.faces[f].building][static_cast<int>(v)];
      }
  }
  for (size_t i = 0; i < pixels.size(); ++i) {
    int views = 0;
    for (const auto& [v, n] : pixels[i]) views += n >= 8;
    EXPECT_GE(views, 2) << b.scene.city.buildings[i].id;
  }
}

// Chimneys, solar panels and roof windows are props: they occlude roofs in
// the images but change neither the buildings nor the ground truth.
TEST(Scene, RoofObjectsAreOccludersNotRoofPlanes) {
  SceneOptions with;
  with.extent_x = with.extent_y = 140;
  with.building_count = 60;
  SceneOptions without = with;
  without.roof_objects = false;
  const Scene a = GenerateScene(with, 7), b = GenerateScene(without, 7);
  std::map<PropKind, int> kinds;
  for (const Prop& p : a.props) ++kinds[p.kind];
  EXPECT_GT(kinds[PropKind::kChimney], 0);
  EXPECT_GT(kinds[PropKind::kSolarPanel] + kinds[PropKind::kSkylight], 0);
  for (const Prop& p : b.props)
    EXPECT_TRUE(p.kind == PropKind::kCar || p.kind == PropKind::kHedge) << PropKindName(p.kind);
  ASSERT_EQ(a.city.buildings.size(), b.city.buildings.size());
  const SceneTruth ta = TruthOf(a), tb = TruthOf(b);
  ASSERT_EQ(ta.roof_planes.size(), tb.roof_planes.size());
  for (size_t i = 0; i < ta.roof_planes.size(); ++i)
    EXPECT_EQ(ta.roof_planes[i].polygon.exterior, tb.roof_planes[i].polygon.exterior);
  // The same edges but the props' (which the objects add to).
  auto count = [](const SceneTruth& t, bool props) {
    return std::count_if(t.edges.begin(), t.edges.end(),
                         [&](const TrueEdge& e) { return (e.kind == EdgeKind::kProp) == props; });
  };
  EXPECT_EQ(count(ta, false), count(tb, false));
  EXPECT_GT(count(ta, true), count(tb, true));
  // Rendered, the objects do occlude roofs.
  const Renderer renderer(a, RenderOptions{});
  Camera cam;
  cam.width = cam.height = 700;
  cam.fx = cam.fy = 1000;
  cam.cx = cam.cy = 350;
  Eigen::Matrix3d R;
  R << 1, 0, 0, 0, -1, 0, 0, 0, -1;
  const GeometryMaps m = renderer.RenderGeometry(cam, Pose{R, Eigen::Vector3d(0, 0, 200)});
  int on_roofs = 0;
  for (int y = 0; y < m.face.rows; ++y)
    for (int x = 0; x < m.face.cols; ++x) {
      const int f = m.face.at<int>(y, x);
      if (f < 0 || renderer.faces()[f].kind != FaceKind::kProp) continue;
      const PropKind k = a.props[renderer.faces()[f].prop].kind;
      on_roofs += k == PropKind::kChimney || k == PropKind::kSolarPanel || k == PropKind::kSkylight;
    }
  EXPECT_GT(on_roofs, 50);
}

// Cars stand on the ground, never inside a building.
TEST(Scene, CarsStayOffBuildings) {
  SceneOptions o;
  o.extent_x = o.extent_y = 140;
  o.building_count = 80;
  const Scene s = GenerateScene(o, 4);
  int cars = 0;
  for (const Prop& p : s.props) {
    if (p.kind != PropKind::kCar) continue;
    ++cars;
    for (const Building& b : s.city.buildings) {
      double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
      for (const Surface& sf : b.surfaces)
        for (const Polygon3& poly : sf.polygons)
          for (const Eigen::Vector3d& q : poly.exterior)
            x0 = std::min(x0, q.x()), y0 = std::min(y0, q.y()), x1 = std::max(x1, q.x()),
            y1 = std::max(y1, q.y());
      const bool inside = p.center.x() > x0 + 0.3 && p.center.x() < x1 - 0.3 &&
                          p.center.y() > y0 + 0.3 && p.center.y() < y1 - 0.3;
      EXPECT_FALSE(inside) << "car at " << p.center.transpose() << " in " << b.id;
    }
  }
  EXPECT_GT(cars, 20);
}

// On a slope or over hills every building stands on the lowest ground
// under it (its walls reach the terrain all round), cars and hedges touch
// the ground without floating, trees stand on it, and the truth's wall feet
// and ground markings lie on it, along their whole length. The terrain only
// lifts things: the town in plan is the flat one.
void ExpectEverythingOnTheGround(const Eigen::Vector2d& slope, double relief) {
  SceneOptions o;
  o.extent_x = o.extent_y = 140;
  o.building_count = 40;
  const Scene flat = GenerateScene(o, 6);
  o.ground_slope = slope;
  o.terrain_relief_m = relief;
  const Scene s = GenerateScene(o, 6);
  const GroundLayout& g = s.ground;
  ASSERT_EQ(s.city.buildings.size(), flat.city.buildings.size());
  ASSERT_GT(s.city.buildings.size(), 20u);
  for (size_t i = 0; i < s.city.buildings.size(); ++i) {
    const Building& b = s.city.buildings[i];
    double low = 1e300, base = 1e300;
    for (const Surface& sf : b.surfaces) {
      if (sf.type != SurfaceType::kGround) continue;
      for (const Polygon3& poly : sf.polygons)
        for (const Eigen::Vector3d& q : poly.exterior) {
          low = std::min(low, g.HeightAt(q.head<2>()));
          base = std::min(base, q.z());
          EXPECT_LE(q.z(), g.HeightAt(q.head<2>()) + 1e-9) << b.id;
        }
    }
    EXPECT_NEAR(base, low, 1e-9) << b.id;
    const Eigen::Vector3d& a = b.surfaces[0].polygons[0].exterior[0];
    const Eigen::Vector3d& f = flat.city.buildings[i].surfaces[0].polygons[0].exterior[0];
    EXPECT_NEAR((a - f).head<2>().norm(), 0, 1e-9) << b.id;
  }
  int boxes = 0;
  for (const Prop& p : s.props) {
    if (p.kind != PropKind::kCar && p.kind != PropKind::kHedge) continue;
    const double bottom = p.center.z() - p.half.z();
    double low = 1e300;
    for (int sx : {-1, 1})
      for (int sy : {-1, 1})
        low = std::min(low, g.HeightAt((p.center + sx * p.half.x() * p.axes.col(0) +
                                        sy * p.half.y() * p.axes.col(1))
                                           .head<2>()));
    // A car's body stands 0.2 m up on its wheels and its cabin higher.
    EXPECT_GE(bottom, low - 1e-9);
    EXPECT_LE(bottom, low + 1.0);
    ++boxes;
  }
  EXPECT_GT(boxes, 20);
  for (const Tree& t : s.trees) EXPECT_NEAR(t.base.z(), g.HeightAt(t.base.head<2>()), 1e-9);
  int on_ground = 0;
  for (const TrueEdge& e : TruthOf(s).edges) {
    if (e.kind != EdgeKind::kFootprint && e.kind != EdgeKind::kGroundMarking) continue;
    EXPECT_NEAR(e.a.z(), g.HeightAt(e.a.head<2>()), 1e-9);
    EXPECT_NEAR(e.b.z(), g.HeightAt(e.b.head<2>()), 1e-9);
    const Eigen::Vector3d m = 0.5 * (e.a + e.b);
    EXPECT_NEAR(m.z(), g.HeightAt(m.head<2>()), 0.005);
    ++on_ground;
  }
  EXPECT_GT(on_ground, 100);
}

TEST(Scene, OnASlopeEverythingStandsOnTheGround) {
  ExpectEverythingOnTheGround(Eigen::Vector2d(0.07, -0.04), 0);
}

// Hills 35-90 m wide spanning up to 12 m: the ground under the town varies
// by several metres, across one building by up to a metre.
TEST(Scene, OverHillsEverythingStandsOnTheGround) {
  ExpectEverythingOnTheGround(Eigen::Vector2d::Zero(), 12);
  SceneOptions o;
  o.extent_x = o.extent_y = 140;
  o.terrain_relief_m = 12;
  const GroundLayout g = GenerateScene(o, 6).ground;
  double lo = 1e300, hi = -1e300;
  for (double x = -70; x <= 70; x += 5)
    for (double y = -70; y <= 70; y += 5) {
      const Eigen::Vector2d p(x, y);
      lo = std::min(lo, g.HeightAt(p)), hi = std::max(hi, g.HeightAt(p));
      // The analytic gradient is the one the renderer shades and traces by.
      const double h = 1e-4;
      const Eigen::Vector2d num(
          (g.HeightAt(p + Eigen::Vector2d(h, 0)) - g.HeightAt(p - Eigen::Vector2d(h, 0))) / (2 * h),
          (g.HeightAt(p + Eigen::Vector2d(0, h)) - g.HeightAt(p - Eigen::Vector2d(0, h))) /
              (2 * h));
      EXPECT_NEAR((g.GradientAt(p) - num).norm(), 0, 1e-6);
    }
  EXPECT_GT(hi - lo, 3.0);
  EXPECT_LT(hi - lo, 12.0 * 6);
}

}  // namespace
}  // namespace sim
}  // namespace roofsweep
