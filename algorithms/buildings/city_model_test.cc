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

TEST(Polygon3, ContainsXYLeavesOutHolesAndIgnoresHeight) {
  Polygon3 p;
  p.exterior = {{0, 0, 5}, {4, 0, 7}, {4, 3, 7}, {0, 3, 5}};  // a sloped face
  p.holes.push_back({{1, 1, 6}, {1, 2, 6}, {2, 2, 6}, {2, 1, 6}});
  EXPECT_TRUE(p.ContainsXY({0.5, 0.5}));
  EXPECT_TRUE(p.ContainsXY({3, 2.5}));
  EXPECT_FALSE(p.ContainsXY({1.5, 1.5}));  // in the hole
  EXPECT_FALSE(p.ContainsXY({5, 1}));
  EXPECT_FALSE(Polygon3{}.ContainsXY({0, 0}));
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

TEST(Building, PlanCentroidOfTheGroundSurfacesOverAllParts) {
  // Two parts: a 4 x 2 ground at x 0..4 and a 2 x 2 one at x 4..6 with a
  // 1 x 1 courtyard; their rings face down (clockwise in plan), as the
  // assembly writes them.
  Building a, b;
  Surface ga{SurfaceType::kGround, "", {}};
  ga.polygons.push_back({{{0, 0, 0}, {0, 2, 0}, {4, 2, 0}, {4, 0, 0}}, {}});
  a.surfaces = {ga};
  Surface gb{SurfaceType::kGround, "", {}};
  gb.polygons.push_back({{{4, 0, 0}, {4, 2, 0}, {6, 2, 0}, {6, 0, 0}},
                         {{{5, 0.5, 0}, {5.5, 0.5, 0}, {5.5, 1.5, 0}, {5, 1.5, 0}}}});
  b.surfaces = {gb};
  Building whole;
  whole.parts = {a, b};
  const auto c = whole.PlanCentroid();
  ASSERT_TRUE(c.has_value());
  // Areas 8 (centre x 2), 4 (x 5) less 0.5 (x 5.25): x = (16 + 20 - 2.625) / 11.5.
  EXPECT_NEAR(c->x(), (16 + 20 - 2.625) / 11.5, 1e-12);
  EXPECT_NEAR(c->y(), 1.0, 1e-12);
  EXPECT_FALSE(Building().PlanCentroid().has_value());
}

}  // namespace
}  // namespace roofsweep
