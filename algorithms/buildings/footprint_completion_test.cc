#include "algorithms/buildings/footprint_completion.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "algorithms/buildings/convex_polygon2.h"
#include "algorithms/buildings/test_planes.h"

namespace roofsweep {
namespace {

// A 10 x 8 m house, ridge along x at y = 4: its south face falls at 40°
// towards -y (azimuth 270°).
const Eigen::Vector4d kSouth = SlopedPlane({0, 4, 9}, 40, 270);
const Footprint kHouse = TestFootprint("h", {{0, 0}, {10, 0}, {10, 8}, {0, 8}});

TEST(FootprintsBeyondRidges, TheOtherSideOfAGableWhoseOneFaceWasFound) {
  // The south face seen over most of its half, up to 0.2 m short of the
  // ridge; a dormer-sized plane of another slope on it does not count.
  const std::vector<RoofPlaneHypothesis> planes = {
      TestPlane(kSouth, {{1, 0}, {10, 0}, {10, 3.8}, {1, 3.8}}, "south"),
      TestPlane(SlopedPlane({5, 2, 7}, 20, 270), {{4, 1}, {5, 1}, {5, 2}, {4, 2}}, "dormer")};
  const std::vector<FootprintBeyondRidge> r = FootprintsBeyondRidges(planes, {kHouse});
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].footprint, 0);
  EXPECT_EQ(r[0].plane, 0);
  EXPECT_EQ(r[0].part.id, "h beyond south");
  EXPECT_NEAR(r[0].face_slope_deg, 40, 1e-9);
  // The footprint north of the face's top (y = 3.8).
  EXPECT_NEAR(std::abs(SignedArea(r[0].part.outline)), 10 * 4.2, 1e-6);
  double y_min = 1e9;
  for (const auto& v : r[0].part.outline) y_min = std::min(y_min, v.y());
  EXPECT_NEAR(y_min, 3.8, 1e-9);
}

TEST(FootprintsBeyondRidges, NotWhereTwoFacesAFlatRoofOrLittleIsLeft) {
  const RoofPlaneHypothesis south =
      TestPlane(kSouth, {{0, 0}, {10, 0}, {10, 3.8}, {0, 3.8}}, "south");
  // Both faces found.
  const RoofPlaneHypothesis north =
      TestPlane(SlopedPlane({0, 4, 9}, 40, 90), {{0, 4.2}, {10, 4.2}, {10, 8}, {0, 8}}, "north");
  EXPECT_TRUE(FootprintsBeyondRidges({south, north}, {kHouse}).empty());
  // A flat roof has no ridge.
  EXPECT_TRUE(FootprintsBeyondRidges(
                  {TestPlane({0, 0, 1, -6}, {{0, 0}, {10, 0}, {10, 4}, {0, 4}}, "flat")}, {kHouse})
                  .empty());
  // A shed over almost all of the footprint leaves a strip under a quarter.
  EXPECT_TRUE(FootprintsBeyondRidges(
                  {TestPlane(kSouth, {{0, 0}, {10, 0}, {10, 7}, {0, 7}}, "shed")}, {kHouse})
                  .empty());
}

}  // namespace
}  // namespace roofsweep
