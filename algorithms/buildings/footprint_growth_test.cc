#include "algorithms/buildings/footprint_growth.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "algorithms/buildings/convex_polygon2.h"
#include "algorithms/buildings/test_planes.h"

namespace roofsweep {
namespace {

Eigen::Vector4d Bounds(const Ring2& r) {
  Eigen::Vector4d b(1e9, 1e9, -1e9, -1e9);
  for (const auto& v : r)
    b << std::min(b[0], v.x()), std::min(b[1], v.y()), std::max(b[2], v.x()), std::max(b[3], v.y());
  return b;
}

// A 10 x 8 m house, ridge along x at y = 4, faces of 30 deg.
const double kRidgeZ = 6 + 4 * std::tan(30 * M_PI / 180);
const Eigen::Vector4d kSouth = SlopedPlane({0, 4, kRidgeZ}, 30, -90);
const Eigen::Vector4d kNorth = SlopedPlane({0, 4, kRidgeZ}, 30, 90);

TEST(ExtensionsAlongFootprints, AFaceSeenOverPartOfItsFootprintRunsOnToItsEnds) {
  const std::vector<RoofPlaneHypothesis> planes = {
      TestPlane(kSouth, {{3, 0.2}, {7, 0.2}, {7, 3.9}, {3, 3.9}}, "south"),
      TestPlane(kNorth, {{0, 4.1}, {10, 4.1}, {10, 8}, {0, 8}}, "north")};
  const std::vector<PatchExtension> e =
      ExtensionsAlongFootprints(planes, {TestFootprint("h", {{0, 0}, {10, 0}, {10, 8}, {0, 8}})});
  ASSERT_EQ(e.size(), 2u);
  for (const PatchExtension& x : e) {
    EXPECT_EQ(x.plane, 0);
    EXPECT_EQ(x.strip.plane, kSouth);
    EXPECT_NE(x.strip.id.find("south grown along footprint h"), std::string::npos) << x.strip.id;
    const Eigen::Vector4d b = Bounds(x.strip.patch);
    // Within the band the patch spans down the slope, beyond it along the
    // eave, to the footprint's end.
    EXPECT_NEAR(b[1], 0.2, 1e-9);
    EXPECT_NEAR(b[3], 3.9, 1e-9);
    EXPECT_TRUE((std::abs(b[0]) < 1e-9 && std::abs(b[2] - 3) < 1e-9) ||
                (std::abs(b[0] - 7) < 1e-9 && std::abs(b[2] - 10) < 1e-9))
        << b.transpose();
  }
}

TEST(ExtensionsAlongFootprints, GrowthStopsAtAnotherFaceAndAtTheFootprint) {
  // An L: the main house 0-10 x 0-8 and a wing 0-4 x 8-14 beside it; the
  // south face's patch over x 5-9 is followed west until the patch of a
  // hip end standing in its band at x 1-2.5, and east to the footprint.
  const Ring2 l = {{0, 0}, {10, 0}, {10, 8}, {4, 8}, {4, 14}, {0, 14}};
  const std::vector<RoofPlaneHypothesis> planes = {
      TestPlane(kSouth, {{5, 0.5}, {9, 0.5}, {9, 3.5}, {5, 3.5}}, "south"),
      TestPlane(SlopedPlane({2.5, 2, kRidgeZ}, 45, 180),
                {{1, 0.5}, {2.5, 0.5}, {2.5, 3.5}, {1, 3.5}}, "hip end")};
  const std::vector<PatchExtension> e = ExtensionsAlongFootprints(planes, {TestFootprint("L", l)});
  std::vector<Eigen::Vector4d> south;
  for (const PatchExtension& x : e)
    if (x.plane == 0) south.push_back(Bounds(x.strip.patch));
  ASSERT_EQ(south.size(), 2u);
  std::sort(south.begin(), south.end(),
            [](const Eigen::Vector4d& a, const Eigen::Vector4d& b) { return a[0] < b[0]; });
  EXPECT_NEAR(south[0][0], 2.5, 1e-9);  // stopped by the hip end's patch
  EXPECT_NEAR(south[0][2], 5, 1e-9);
  EXPECT_NEAR(south[1][0], 9, 1e-9);
  EXPECT_NEAR(south[1][2], 10, 1e-9);  // the footprint's end
}

TEST(ExtensionsAlongFootprints, FlatPlanesAndPlanesOffTheFootprintDoNotGrow) {
  const std::vector<RoofPlaneHypothesis> planes = {
      TestPlane({0, 0, 1, -6}, {{3, 1}, {6, 1}, {6, 6}, {3, 6}}, "flat"),
      TestPlane(kSouth, {{30, 0}, {34, 0}, {34, 4}, {30, 4}}, "elsewhere")};
  EXPECT_TRUE(
      ExtensionsAlongFootprints(planes, {TestFootprint("h", {{0, 0}, {10, 0}, {10, 8}, {0, 8}})})
          .empty());
}

// The north face seen as the hull of its eave (y = 8, x 0-10) and the west
// end of its ridge: a triangle, half the face. The corner it leaves out is
// proposed, within the band and the footprint, with the face's plane.
TEST(ExtensionsAlongFootprints, TheCornerATriangularPatchLeavesOutIsProposed) {
  const std::vector<RoofPlaneHypothesis> planes = {
      TestPlane(kNorth, {{0, 4.1}, {10, 8}, {0, 8}}, "north"),
      TestPlane(kSouth, {{0, 0}, {10, 0}, {10, 3.9}, {0, 3.9}}, "south")};
  const Footprint house = TestFootprint("h", {{0, 0}, {10, 0}, {10, 8}, {0, 8}});
  const std::vector<PatchExtension> e = ExtensionsAlongFootprints(planes, {house});
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0].plane, 0);
  EXPECT_EQ(e[0].strip.plane, kNorth);
  EXPECT_NE(e[0].strip.id.find("north filled within footprint h"), std::string::npos)
      << e[0].strip.id;
  // The triangle (0, 4.1), (10, 4.1), (10, 8): together with the patch the
  // whole rectangle of the face.
  EXPECT_NEAR(SignedArea(e[0].strip.patch), 0.5 * 10 * 3.9, 1e-9);
  const Eigen::Vector4d b = Bounds(e[0].strip.patch);
  EXPECT_NEAR(b[0], 0, 1e-9);
  EXPECT_NEAR(b[1], 4.1, 1e-9);
  EXPECT_NEAR(b[2], 10, 1e-9);
  EXPECT_NEAR(b[3], 8, 1e-9);

  FootprintGrowthOptions off;
  off.fill_band = false;
  EXPECT_TRUE(ExtensionsAlongFootprints(planes, {house}, off).empty());
}

// A hip end's patch in the corner: the corner is that face's, and nothing
// is proposed.
TEST(ExtensionsAlongFootprints, ACornerAnotherFaceHoldsIsNotFilled) {
  std::vector<RoofPlaneHypothesis> planes = {
      TestPlane(kNorth, {{0, 4.1}, {10, 8}, {0, 8}}, "north"),
      TestPlane(SlopedPlane({8, 6, kRidgeZ}, 45, 0), {{8, 4.5}, {9.8, 4.5}, {9.8, 7}, {8, 7}},
                "hip end")};
  const Footprint house = TestFootprint("h", {{0, 0}, {10, 0}, {10, 8}, {0, 8}});
  auto filled = [&] {
    int n = 0;
    for (const PatchExtension& x : ExtensionsAlongFootprints(planes, {house}))
      n += x.strip.id.find("north filled") != std::string::npos;
    return n;
  };
  EXPECT_EQ(filled(), 0);
  // The same hip end on the south side, outside the corner: it is filled.
  planes[1].patch = ConvexHull({{8, 0.5}, {9.8, 0.5}, {9.8, 3}, {8, 3}});
  EXPECT_EQ(filled(), 1);
}

}  // namespace
}  // namespace roofsweep
