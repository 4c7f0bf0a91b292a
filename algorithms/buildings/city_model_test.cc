#include "algorithms/buildings/city_model.h"

#include <gtest/gtest.h>

namespace roofsweep {
namespace {

TEST(Polygon3, NormalAndAreaOfCounterClockwiseSquare) {
  Polygon3 p;
  p.exterior = {{0, 0, 5}, {4, 0, 5}, {4, 3, 5}, {0, 3, 5}};
  EXPECT_NEAR(p.Normal().z(), 1.0, 1e-12);
  EXPECT_NEAR(p.Area(), 12.0, 1e-12);
  p.holes.push_back({{1, 1, 5}, {1, 2, 5}, {2, 2, 5}, {2, 1, 5}});
  EXPECT_NEAR(p.Area(), 11.0, 1e-12);
}

TEST(Building, GroundAndRoofHeights) {
  Building b;
  Surface g{SurfaceType::kGround, "", {}};
  g.polygons.push_back({{{0, 0, 2}, {0, 1, 2}, {1, 1, 2}}, {}});
  Surface r{SurfaceType::kRoof, "", {}};
  r.polygons.push_back({{{0, 0, 9}, {1, 0, 9}, {1, 1, 11}}, {}});
  b.surfaces = {g, r};
  EXPECT_DOUBLE_EQ(b.GroundZ(), 2);
  EXPECT_DOUBLE_EQ(b.RoofTopZ(), 11);
  EXPECT_STREQ(RoofTypeName(roof_type::kGabled), "gabled");
}

}  // namespace
}  // namespace roofsweep
