#include "algorithms/geometry/block_overview.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "algorithms/geometry/rotation.h"
#include "algorithms/geometry/test_blocks.h"

namespace roofsweep {
namespace {

// A strip of nadir images 1000 px wide, f = 1000 px, 500 m above ground:
// GSD 0.5 m, footprint 500 m; centres 200 m apart => 60% forward overlap.
Block NadirStrip(int n, double spacing) {
  std::vector<Eigen::Vector3d> centres;
  for (int i = 0; i < n; ++i) centres.emplace_back(i * spacing, 0, 500);
  return NadirTestBlock(centres, "img");
}

TEST(BlockOverview, NadirStripGsdAndOverlap) {
  const BlockOverview o = AnalyzeBlock(NadirStrip(3, 200));
  ASSERT_EQ(o.footprints.size(), 3u);
  EXPECT_TRUE(o.plane_is_ground);
  for (const auto& fp : o.footprints) {
    EXPECT_NEAR(fp.gsd_m, 0.5, 1e-6);
    EXPECT_NEAR(fp.area_m2, 500.0 * 500.0, 1.0);
    EXPECT_NEAR(fp.off_nadir_deg, 0.0, 1e-6);
  }
  // 0-1 and 1-2 overlap 60%, 0-2 20%.
  ASSERT_EQ(o.overlaps.size(), 3u);
  EXPECT_NEAR(o.overlaps[0].fraction, 0.6, 1e-3);
  EXPECT_NEAR(o.overlaps[1].fraction, 0.2, 1e-3);
  EXPECT_NEAR(o.overlaps[2].fraction, 0.6, 1e-3);
  EXPECT_TRUE(o.warnings.empty());
}

TEST(BlockOverview, WarnsAboutIsolatedImageAndCameraBelowGround) {
  Block b = NadirStrip(3, 200);
  b.views[2].pose.C.x() = 5000;  // far away
  b.views[1].pose.C.z() = -10;
  const BlockOverview o = AnalyzeBlock(b);
  bool isolated = false, below = false;
  for (const auto& w : o.warnings) {
    isolated |= w.find("'img2' overlaps no other") != std::string::npos;
    below |= w.find("'img1': camera is below the ground") != std::string::npos;
  }
  EXPECT_TRUE(isolated);
  EXPECT_TRUE(below);
}

TEST(BlockOverview, ConvergentViewsWithoutGroundUseScenePlane) {
  Block b = NadirStrip(2, 0);
  b.ground = GroundModel{};
  // Two cameras 10 m apart looking at the origin from 20 m.
  for (int i = 0; i < 2; ++i) {
    const Eigen::Vector3d C(i ? 5 : -5, 0, 20);
    const Eigen::Vector3d z = (-C).normalized();
    const Eigen::Vector3d x = Eigen::Vector3d::UnitY().cross(z).normalized();
    const Eigen::Vector3d y = z.cross(x);
    b.views[i].pose.R.row(0) = x;
    b.views[i].pose.R.row(1) = y;
    b.views[i].pose.R.row(2) = z;
    b.views[i].pose.C = C;
  }
  const BlockOverview o = AnalyzeBlock(b);
  EXPECT_FALSE(o.plane_is_ground);
  // The scene plane passes through the origin; GSD ~ distance / f.
  EXPECT_NEAR(o.footprints[0].gsd_m, std::sqrt(425.0) / 1000.0, 2e-3);
  ASSERT_EQ(o.overlaps.size(), 1u);
  EXPECT_GT(o.overlaps[0].fraction, 0.5);
}

TEST(BlockOverview, DivergingAxesWithoutGroundGiveNoGsd) {
  Block b = NadirStrip(2, 100);
  b.ground = GroundModel{};
  // Tilt the two cameras 30 degrees away from each other.
  b.views[0].pose.R = PatbToCv(OpkToRotation(0, 30, 0));   // looks towards -x
  b.views[1].pose.R = PatbToCv(OpkToRotation(0, -30, 0));  // towards +x
  const BlockOverview o = AnalyzeBlock(b);
  ASSERT_EQ(o.footprints.size(), 2u);
  EXPECT_FALSE(o.footprints[0].valid);
  EXPECT_EQ(o.footprints[0].gsd_m, 0.0);
  ASSERT_EQ(o.warnings.size(), 1u);
  EXPECT_NE(o.warnings[0].find("do not converge"), std::string::npos);
}

// A 60 x 60 grid of `spacing` m cells on a plane rising `slope_deg` along x,
// with a 10 m high box of 12 x 12 cells on it when `building`.
GroundModel SlopeGrid(double spacing, double slope_deg, bool building) {
  GroundModel g;
  GroundModel::Grid grid;
  grid.dx = grid.dy = spacing;
  grid.rows = grid.cols = 60;
  for (int r = 0; r < grid.rows; ++r)
    for (int c = 0; c < grid.cols; ++c) {
      const bool roof = building && r >= 20 && r < 32 && c >= 20 && c < 32;
      grid.z.push_back(static_cast<float>(c * spacing * std::tan(slope_deg * M_PI / 180.0) +
                                          (roof ? 10.0 : 0.0)));
    }
  g.grid = grid;
  return g;
}

TEST(BlockOverview, WarnsWhenTheDtmIsASurfaceModel) {
  // Walls: 48 of 7080 neighbouring pairs step by 10 m (0.7 %).
  const auto w = SurfaceModelWarning(SlopeGrid(0.5, 5, true));
  ASSERT_TRUE(w.has_value());
  EXPECT_NE(w->find("surface model"), std::string::npos);
  Block block = NadirStrip(2, 200);
  block.ground = SlopeGrid(0.5, 5, true);
  int dsm_warnings = 0;
  for (const std::string& line : AnalyzeBlock(block).warnings)
    dsm_warnings += line.find("surface model") != std::string::npos;
  EXPECT_EQ(dsm_warnings, 1);
  // Bare terrain, even steep: a 50 degree slope over 0.5 m cells, a 45
  // degree one over 24 m cells (steps of 24 m, under the 60 degree bound).
  EXPECT_FALSE(SurfaceModelWarning(SlopeGrid(0.5, 50, false)).has_value());
  EXPECT_FALSE(SurfaceModelWarning(SlopeGrid(24, 45, false)).has_value());
  // A constant ground height has no grid to judge.
  GroundModel flat;
  flat.height = 0;
  EXPECT_FALSE(SurfaceModelWarning(flat).has_value());
}

}  // namespace
}  // namespace roofsweep
