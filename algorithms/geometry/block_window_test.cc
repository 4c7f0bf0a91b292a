#include "algorithms/geometry/block_window.h"

#include <gtest/gtest.h>

#include "algorithms/geometry/test_blocks.h"

namespace roofsweep {
namespace {

TEST(CropBlockToRegion, KeepsTheViewsThatSeeTheRegionAndTheirWindows) {
  // Nadir views from 100 m, 10 cm GSD on the ground, 1000 px wide: the
  // first sees the region at its centre, the second has it 55..65 m to the
  // side (beyond its 50 m half-width), the third far away.
  Block block = NadirTestBlock({{0, 0, 100}, {60, 0, 100}, {500, 0, 100}});
  const BlockWindows w = CropBlockToRegion(block, Eigen::Vector4d(-5, -5, 5, 5), 0, 20, 10);
  ASSERT_EQ(w.block.views.size(), 1u);
  EXPECT_EQ(w.source_view, std::vector<int>{0});
  // The top of the box (80 m away) images 62.5 px either side of the centre.
  const PixelWindow& p = w.windows[0];
  EXPECT_EQ(p.x, 500 - 63 - 10);
  EXPECT_EQ(p.y, 500 - 63 - 10);
  EXPECT_EQ(p.x + p.width, 500 + 63 + 10);
  EXPECT_EQ(p.y + p.height, 500 + 63 + 10);
  const Camera& c = w.block.CameraOf(w.block.views[0]);
  EXPECT_EQ(c.width, p.width);
  EXPECT_EQ(c.height, p.height);
}

TEST(CropBlockToRegion, ProjectingIntoTheWindowIsProjectingIntoTheImageLessItsCorner) {
  Block block = NadirTestBlock({{3, -2, 100}});
  block.cameras[0].k1 = -0.08;
  block.cameras[0].p2 = 0.001;
  const BlockWindows w = CropBlockToRegion(block, Eigen::Vector4d(10, 5, 30, 20), 0, 20, 4);
  ASSERT_EQ(w.block.views.size(), 1u);
  const PixelWindow& p = w.windows[0];
  for (double x : {10.0, 17.0, 30.0})
    for (double y : {5.0, 11.0, 20.0})
      for (double z : {0.0, 7.0, 20.0}) {
        const Eigen::Vector3d X(x, y, z);
        const auto full = Project(block.cameras[0], block.views[0].pose, X);
        const auto cut = Project(w.block.cameras[0], w.block.views[0].pose, X);
        ASSERT_TRUE(full && cut);
        EXPECT_NEAR(cut->x(), full->x() - p.x, 1e-9);
        EXPECT_NEAR(cut->y(), full->y() - p.y, 1e-9);
        // Inside the window, at least the margin from its inner edges.
        EXPECT_GE(cut->x(), 4 - 1e-9);
        EXPECT_GE(cut->y(), 4 - 1e-9);
        EXPECT_LE(cut->x(), p.width - 4 + 1e-9);
        EXPECT_LE(cut->y(), p.height - 4 + 1e-9);
      }
}

TEST(CropBlockToRegion, AViewWithPartOfTheRegionBehindItKeepsItsWholeImage) {
  // A camera standing inside the box looks down: the box's top is behind it.
  Block block = NadirTestBlock({{0, 0, 10}});
  const BlockWindows w = CropBlockToRegion(block, Eigen::Vector4d(-5, -5, 5, 5), 0, 20, 10);
  ASSERT_EQ(w.windows.size(), 1u);
  EXPECT_EQ(w.windows[0].x, 0);
  EXPECT_EQ(w.windows[0].width, 1000);
  EXPECT_EQ(w.windows[0].height, 1000);
}

}  // namespace
}  // namespace roofsweep
