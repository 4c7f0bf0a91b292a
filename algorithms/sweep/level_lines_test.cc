#include "algorithms/sweep/level_lines.h"

#include <gtest/gtest.h>

#include <cmath>

#include "algorithms/geometry/view.h"
#include "algorithms/sweep/test_scene.h"

namespace roofsweep {
namespace {

using sweep_test::Quad;
using sweep_test::TestScene;

constexpr double kDeg = M_PI / 180.0;

// One strip: three nadir views 100 m up along x, as FourViewBlock's
// cameras. A line along x lies along every pair's epipolar lines.
Block StripBlock() {
  Block block = sweep_test::FourViewBlock();
  block.views.resize(3);
  const double xs[3] = {-12, 0, 12};
  for (int i = 0; i < 3; ++i) block.views[i].pose.C = Eigen::Vector3d(xs[i], -8, 100);
  block.ground.height = 0.0;
  return block;
}

// A gable roof, ridge along x at z = 10 over y = 0, faces falling 35 deg to
// eaves 5 m either side, over the textured ground.
TestScene Gable() {
  TestScene scene;
  const double run = 5, drop = run * std::tan(35 * kDeg);
  for (int side : {1, -1}) {
    Quad q;
    q.origin = {-6, 0, 10};
    q.u = {12, 0, 0};
    q.v = {0, side * run, -drop};
    q.seed = side > 0 ? 3 : 4;
    scene.quads.push_back(q);
  }
  return scene;
}

struct Strip {
  Block block = StripBlock();
  std::vector<Segments2D> segments{3};
  std::vector<std::vector<bool>> used{3};
  std::vector<ViewTexture> textures;
  std::vector<Segment3> known;

  explicit Strip(const TestScene& scene) {
    textures = PrepareViewTextures(block, sweep_test::RenderAll(scene, block), SweepOptions());
  }
  // The edge a-b as every view sees it.
  void See(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    for (size_t v = 0; v < 3; ++v) {
      const View& view = block.views[v];
      Segment2D s;
      s.p0 = *Project(block.CameraOf(view), view.pose, a);
      s.p1 = *Project(block.CameraOf(view), view.pose, b);
      segments[v].push_back(s);
      used[v].push_back(false);
    }
  }
  std::vector<LevelLine> Sweep(const LevelLineOptions& o, LevelLineStats* stats) {
    NullProgress progress;
    return SweepLevelLines(block, textures, segments, used, {}, known, 0.0, 0.2, SweepOptions(), o,
                           progress, stats);
  }
};

double OffLine(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d d = (b - a).normalized();
  return ((p - a) - (p - a).dot(d) * d).norm();
}

// The ridge along the strip: correspondence cannot place it, the faces
// beside it can. Found once (the three views see the same edge), at its
// height.
TEST(SweepLevelLines, ARidgeAlongTheStripIsPlacedByItsFaces) {
  Strip s(Gable());
  const Eigen::Vector3d a(-5, 0, 10), b(5, 0, 10);
  s.See(a, b);
  LevelLineStats stats;
  const std::vector<LevelLine> lines = s.Sweep(LevelLineOptions(), &stats);
  EXPECT_EQ(stats.candidates, 1);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_NEAR(lines[0].height_m, 10.0, 0.15);
  EXPECT_LT(OffLine(lines[0].segment.a, a, b), 0.15);
  EXPECT_LT(OffLine(lines[0].segment.b, a, b), 0.15);
  EXPECT_GE(lines[0].height_ratio, 2.0);
  // Its face: one of the two 35 deg faces.
  EXPECT_NEAR(std::acos(lines[0].side.plane.z()) / kDeg, 35.0, 3.0);
}

// A segment across the baselines is left to correspondence; one used by a
// 3D line already is not swept again.
TEST(SweepLevelLines, SegmentsTheViewsFixOrALineUsesAreNotSwept) {
  Strip s(Gable());
  s.See({0, -4, 10 - 4 * std::tan(35 * kDeg)}, {0, 4, 10 - 4 * std::tan(35 * kDeg)});
  s.See({-5, 0, 10}, {5, 0, 10});
  for (auto& u : s.used) u[1] = true;
  LevelLineStats stats;
  EXPECT_TRUE(s.Sweep(LevelLineOptions(), &stats).empty());
  EXPECT_EQ(stats.candidates, 0);
  // Unmarked, but along a known 3D line's projection.
  for (auto& u : s.used) u[1] = false;
  s.known.push_back({{-6, 0, 10}, {6, 0, 10}});
  EXPECT_TRUE(s.Sweep(LevelLineOptions(), &stats).empty());
  EXPECT_EQ(stats.candidates, 0);
}

// A mark on the ground along the strip: the texture beside it peaks at
// the ground, below the lowest roof height, so nothing is placed.
TEST(SweepLevelLines, AGroundMarkIsNotLifted) {
  TestScene ground;
  Strip s(ground);
  s.See({-5, 3, 0}, {5, 3, 0});
  LevelLineStats stats;
  EXPECT_TRUE(s.Sweep(LevelLineOptions(), &stats).empty());
  EXPECT_EQ(stats.candidates, 1);
}

}  // namespace
}  // namespace roofsweep
