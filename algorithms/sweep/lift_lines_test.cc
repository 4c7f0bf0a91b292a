#include "algorithms/sweep/lift_lines.h"

#include <gtest/gtest.h>

#include <cmath>

#include "algorithms/geometry/test_blocks.h"
#include "algorithms/geometry/view.h"

namespace roofsweep {
namespace {

// Three nadir views 100 m up: v1 beside v0 along x, v2 along y. A flat
// roof at z = 10 over [-5, 5] x [-5, 5].
struct LiftScene {
  Block block = NadirTestBlock({{0, 0, 100}, {30, 0, 100}, {0, 30, 100}});
  std::vector<RoofPlaneHypothesis> planes;
  std::vector<Segments2D> segments{3};
  std::vector<std::vector<bool>> used{3};

  LiftScene() {
    RoofPlaneHypothesis p;
    p.plane = {0, 0, 1, -10};
    p.patch = {{-5, -5}, {5, -5}, {5, 5}, {-5, 5}};
    planes.push_back(p);
  }
  // The edge a-b as every view sees it; returns its segment id (the same
  // in every view).
  int See(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    int id = -1;
    for (size_t v = 0; v < 3; ++v) {
      const View& view = block.views[v];
      Segment2D s;
      s.p0 = *Project(block.CameraOf(view), view.pose, a);
      s.p1 = *Project(block.CameraOf(view), view.pose, b);
      id = static_cast<int>(segments[v].size());
      segments[v].push_back(s);
      used[v].push_back(false);
    }
    return id;
  }
  std::vector<LiftedLine> Lift(const LiftOptions& o, const std::vector<Segment3>& known = {}) {
    return LiftSegmentsOntoPlanes(block, segments, used, planes, known, o);
  }
};

TEST(LiftLines, AnEdgeOnThePlaneIsLiftedAndConfirmedByAViewAcrossIt) {
  LiftScene s;
  s.See({-4, 4, 10}, {4, 4, 10});
  LiftOptions o;
  o.min_fixing = 1;
  const std::vector<LiftedLine> lifted = s.Lift(o);
  ASSERT_EQ(lifted.size(), 1u);
  const Segment3& l = lifted[0].segment;
  EXPECT_LT(std::min((l.a - Eigen::Vector3d(-4, 4, 10)).norm(),
                     (l.b - Eigen::Vector3d(-4, 4, 10)).norm()),
            1e-6);
  EXPECT_NEAR(l.Length(), 8.0, 1e-6);
  EXPECT_EQ(lifted[0].plane, 0);
  // Lifted from one view, confirmed by the two others; only v2's baseline
  // crosses the edge (it runs along x, like v0-v1's baseline).
  EXPECT_EQ(lifted[0].observations.size(), 3u);
  EXPECT_EQ(lifted[0].fixing, 1);
}

TEST(LiftLines, AGroundEdgeAlongTheBaselineNeedsAViewThatFixesItsDepth) {
  LiftScene s;
  // On the ground under the roof's patch as v0 sees it: lifted onto the
  // roof it lands at (0.9 x, -2.7, 10), which v1 sees exactly where it
  // sees the ground edge (the edge runs along their baseline) and v2 does
  // not.
  s.See({-4, -3, 0}, {4, -3, 0});
  LiftOptions o;
  o.min_fixing = 0;
  const std::vector<LiftedLine> loose = s.Lift(o);
  ASSERT_EQ(loose.size(), 1u);
  EXPECT_EQ(loose[0].fixing, 0);
  o.min_fixing = 1;
  EXPECT_TRUE(s.Lift(o).empty());
}

TEST(LiftLines, MatchedSegmentsAndKnownLinesAreNotLiftedAgain) {
  LiftScene s;
  const int id = s.See({-4, 4, 10}, {4, 4, 10});
  LiftOptions o;
  EXPECT_EQ(s.Lift(o, {Segment3{{-3, 4.1, 10}, {3, 4.1, 10.05}}}).size(), 0u);
  EXPECT_EQ(s.Lift(o, {Segment3{{-3, 4.5, 10}, {3, 4.5, 10}}}).size(), 1u);  // 0.5 m away
  for (auto& u : s.used) u[id] = true;
  EXPECT_TRUE(s.Lift(o).empty());
}

TEST(LiftLines, ASegmentIsClippedToThePlanesGrownPatch) {
  LiftScene s;
  // An eave that runs on past the roof along a row of neighbours.
  s.See({-4, 4, 10}, {20, 4, 10});
  LiftOptions o;
  o.patch_margin_m = 1.0;
  const std::vector<LiftedLine> lifted = s.Lift(o);
  ASSERT_EQ(lifted.size(), 1u);
  const Segment3& l = lifted[0].segment;
  EXPECT_NEAR(std::max(l.a.x(), l.b.x()), 6.0, 0.5);  // GrowConvex reaches a little further
  EXPECT_NEAR(std::min(l.a.x(), l.b.x()), -4.0, 1e-6);
}

HalfPlane Side(int side, bool candidate, double slope_deg) {
  HalfPlane h;
  h.side = side;
  h.candidate = candidate;
  const double t = slope_deg * M_PI / 180;
  h.plane = {0, std::sin(t), std::cos(t), 0};
  return h;
}

TEST(LiftLines, OnlyLiftsThatBoundTheirPlaneAreKeptAsBorderLines) {
  LiftScene s;
  // Along +x at y = 4: the patch (centre 0, 0) lies on its right, side -1.
  LiftedLine l;
  l.segment = {{-4, 4, 10}, {4, 4, 10}};
  l.plane = 0;
  const LiftOptions o;
  auto kept = [&](const HalfPlane& left, const HalfPlane& right) {
    return KeepBorderLifts({l}, {left, right}, s.planes, o).size() == 1;
  };
  // The eave of the flat roof: a 40 degree face, or nothing, beyond it.
  EXPECT_TRUE(kept(Side(+1, true, 40), Side(-1, true, 3)));
  EXPECT_TRUE(kept(Side(+1, false, 0), Side(-1, true, 0)));
  // A line inside the face: the plane on both sides.
  EXPECT_FALSE(kept(Side(+1, true, 2), Side(-1, true, 0)));
  // No plane on the patch side (the lift lies beyond the face).
  EXPECT_FALSE(kept(Side(+1, true, 40), Side(-1, false, 0)));
  EXPECT_FALSE(kept(Side(+1, true, 0), Side(-1, true, 30)));
  // The sides of another count of lines: nothing is kept.
  EXPECT_TRUE(KeepBorderLifts({l}, {Side(-1, true, 0)}, s.planes, o).empty());
}

}  // namespace
}  // namespace roofsweep
