#include "algorithms/eval/plan_view.h"

#include <gtest/gtest.h>

#include "algorithms/eval/test_models.h"

namespace roofsweep::eval {
namespace {

using V = Eigen::Vector3d;

double SignedAreaForTest(const Ring2& r) {
  double a = 0;
  for (size_t i = 0; i < r.size(); ++i)
    a += r[i].x() * r[(i + 1) % r.size()].y() - r[(i + 1) % r.size()].x() * r[i].y();
  return a / 2;
}

TEST(PlanGeometry, UnionOfTouchingSquaresIsOneRectangle) {
  const Polygon2 a{{{0, 0}, {5, 0}, {5, 8}, {0, 8}}, {}};
  const Polygon2 b{{{5, 8}, {5, 0}, {10, 0}, {10, 8}}, {}};  // clockwise on purpose
  const MultiPolygon2 r = MakeRegion({a, b});
  ASSERT_EQ(r.size(), 2u);
  EXPECT_GT(SignedAreaForTest(r[1].outer), 0);  // re-oriented counter-clockwise
  EXPECT_NEAR(Area(r), 80.0, 1e-9);
  const MultiPolygon2 u = Outline(r);
  ASSERT_EQ(u.size(), 1u);
  EXPECT_EQ(u[0].outer.size(), 4u);  // collinear (5,0) and (5,8) removed
}

TEST(PlanGeometry, IntersectionAreaAndDistance) {
  const MultiPolygon2 a = MakeRegion({{{{0, 0}, {10, 0}, {10, 8}, {0, 8}}, {}}});
  const MultiPolygon2 b = MakeRegion({{{{2, 0}, {12, 0}, {12, 8}, {2, 8}}, {}}});
  const MultiPolygon2 c = MakeRegion({{{{13, 0}, {14, 0}, {14, 1}}, {}}});
  EXPECT_NEAR(IntersectionArea(a, b), 64.0, 1e-9);
  EXPECT_NEAR(IntersectionArea(a, c), 0.0, 1e-12);
  EXPECT_NEAR(Distance(a, c), 3.0, 1e-12);
  EXPECT_NEAR(Distance(a, b), 0.0, 1e-12);
}

// Two roof planes of Berlin LoD2 tile 3910_5817 (EPSG:25833) that share an
// edge up to 2 mm: Boost.Geometry 1.74 gave all 92.46 m² of the second as
// their intersection. A third ring (tile 3900_5819) that touches itself
// once its pieces are merged must survive a self-intersection.
TEST(PlanGeometry, NearlyTouchingRealRoofsDoNotOverlap) {
  const MultiPolygon2 a = MakeRegion({{{{391801.167777083, 5817731.1340094097},
                                        {391803.637604188, 5817735.9761322401},
                                        {391790.15214216802, 5817742.8134156503},
                                        {391787.68231489899, 5817737.9712927099}},
                                       {}}});
  const MultiPolygon2 b = MakeRegion({{{{391790.15128929098, 5817742.8117432296},
                                        {391792.63663286198, 5817747.6842935197},
                                        {391777.59244582901, 5817755.39196264},
                                        {391775.10710207198, 5817750.5194122298}},
                                       {}}});
  EXPECT_NEAR(Area(a), 82.1852, 1e-4);
  EXPECT_NEAR(Area(b), 92.4598, 1e-4);
  EXPECT_LT(IntersectionArea(a, b), 1e-3);
  EXPECT_NEAR(IntersectionArea(a, a), Area(a), 1e-6);
  EXPECT_NEAR(IntersectionArea(b, b), Area(b), 1e-6);
}

TEST(PlanGeometry, PiecesTouchingAtVerticesKeepTheirArea) {
  // A triangle, a strip and a quad that meet only at corners and along
  // parts of edges (from a Berlin roof face split into three polygons).
  const MultiPolygon2 r = MakeRegion({{{{390884.08613605902, 5818985.9130893704},
                                        {390884.28307401302, 5818983.3073920105},
                                        {390887.703673638, 5818983.4907744797}},
                                       {}},
                                      {{{390885.90721302398, 5819007.2598555898},
                                        {390885.66570591601, 5819010.4552523196},
                                        {390881.98919145903, 5819013.6578962896},
                                        {390882.251360922, 5819010.1891142298},
                                        {390882.49286803202, 5819006.9937174805},
                                        {390883.07717712002, 5818999.2626861297},
                                        {390883.27875126502, 5818996.59564598},
                                        {390883.58397467399, 5818992.55721635},
                                        {390886.69775011198, 5818996.8002085304},
                                        {390886.49617597001, 5818999.4672486596}},
                                       {}},
                                      {{{390883.58397467399, 5818992.55721635},
                                        {390883.88919811998, 5818988.5187867302},
                                        {390884.08613605902, 5818985.9130893704},
                                        {390887.30979774997, 5818988.7021691501}},
                                       {}}});
  ASSERT_EQ(r.size(), 3u);
  const double area = Area(r);
  EXPECT_GT(area, 75);
  EXPECT_NEAR(IntersectionArea(r, r), area, 1e-6);
  EXPECT_NEAR(Area(Outline(r)), area, 1e-3);
}

TEST(PlanGeometry, DegenerateAndSelfIntersectingAreLeftOutAndCounted) {
  UnionStats stats;
  const MultiPolygon2 u = MakeRegion({{{{0, 0}, {1, 0}, {2, 0}}, {}},          // collinear
                                      {{{0, 0}, {4, 4}, {4, 0}, {0, 2}}, {}},  // bow tie
                                      {{{5, 5}, {6, 5}, {6, 6}, {5, 6}}, {}}},
                                     &stats);
  EXPECT_EQ(stats.degenerate, 1);
  EXPECT_EQ(stats.invalid, 1);
  EXPECT_NEAR(Area(u), 1.0, 1e-12);
}

TEST(RoofPlanes, ThreeHousesHaveSevenPlanesWithPlanAreas) {
  const RoofPlaneSet s = ExtractRoofPlanes(eval_test::ThreeHouses(), {});
  ASSERT_EQ(s.planes.size(), 7u);
  EXPECT_EQ(s.roof_polygons, 7);
  EXPECT_NEAR(s.planes[0].plan_area, 80, 1e-9);
  EXPECT_NEAR(s.planes[1].plan_area, 48, 1e-9);
  EXPECT_NEAR(s.planes[3].plan_area, 45, 1e-9);  // hip trapezoid (14 + 4) / 2 * 5
  EXPECT_NEAR(s.planes[4].plan_area, 25, 1e-9);  // hip end triangle 10 * 5 / 2
  // Gable south plane: rise 3 over 4 m.
  EXPECT_NEAR(s.planes[1].normal.y(), -0.6, 1e-12);
  EXPECT_NEAR(s.planes[1].normal.z(), 0.8, 1e-12);
  EXPECT_EQ(s.vertical_polygons + s.degenerate_polygons + s.invalid_polygons, 0);
}

TEST(RoofPlanes, CoplanarTouchingPiecesMergeAcrossSurfaces) {
  CityModel m;
  m.buildings.push_back(eval_test::Box("B", 0, 0, 10, 8, 0, 5));
  Building& b = m.buildings[0];
  b.surfaces.pop_back();  // the one-piece flat roof
  Surface r1{SurfaceType::kRoof, "r1", {{{V(0, 0, 5), V(5, 0, 5), V(5, 8, 5), V(0, 8, 5)}, {}}}};
  Surface r2{SurfaceType::kRoof,
             "r2",
             {{{V(5, 0, 5), V(10, 0, 5), V(10, 4, 5)}, {}},
              {{V(5, 0, 5), V(10, 4, 5), V(10, 8, 5), V(5, 8, 5)}, {}}}};
  b.surfaces.push_back(r1);
  b.surfaces.push_back(r2);
  const RoofPlaneSet s = ExtractRoofPlanes(m, {});
  ASSERT_EQ(s.planes.size(), 1u);
  EXPECT_EQ(s.planes[0].polygons.size(), 3u);
  EXPECT_NEAR(s.planes[0].plan_area, 80, 1e-9);
  ASSERT_EQ(s.planes[0].outline.size(), 1u);
  EXPECT_EQ(s.planes[0].outline[0].outer.size(), 4u);
}

TEST(RoofPlanes, SeparateCoplanarRoofsStayTwoPlanesAndOtherHeightsSplit) {
  CityModel m;
  Building b;
  b.id = "B";
  // Same height, 2 m apart: two planes. Touching but 0.5 m higher: a third.
  b.surfaces.push_back({SurfaceType::kRoof,
                        "",
                        {{{V(0, 0, 5), V(4, 0, 5), V(4, 4, 5), V(0, 4, 5)}, {}},
                         {{V(6, 0, 5), V(10, 0, 5), V(10, 4, 5), V(6, 4, 5)}, {}},
                         {{V(0, 4, 5.5), V(4, 4, 5.5), V(4, 6, 5.5), V(0, 6, 5.5)}, {}}}});
  m.buildings.push_back(b);
  EXPECT_EQ(ExtractRoofPlanes(m, {}).planes.size(), 3u);
}

TEST(RoofPlanes, VerticalDownwardAndHoledPolygons) {
  CityModel m;
  Building b;
  b.id = "B";
  Polygon3 holed{{V(0, 0, 5), V(10, 0, 5), V(10, 8, 5), V(0, 8, 5)},
                 {{V(2, 2, 5), V(2, 6, 5), V(8, 6, 5), V(8, 2, 5)}}};
  Polygon3 vertical{{V(20, 0, 0), V(30, 0, 0), V(30, 0, 5), V(20, 0, 5)}, {}};
  Polygon3 downward{{V(40, 0, 5), V(40, 4, 5), V(44, 4, 5), V(44, 0, 5)}, {}};  // clockwise
  b.surfaces.push_back({SurfaceType::kRoof, "", {holed, vertical, downward}});
  m.buildings.push_back(b);
  const RoofPlaneSet s = ExtractRoofPlanes(m, {});
  ASSERT_EQ(s.planes.size(), 2u);
  EXPECT_EQ(s.vertical_polygons, 1);
  EXPECT_EQ(s.downward_polygons, 1);
  EXPECT_NEAR(s.planes[0].plan_area, 80 - 24, 1e-9);
  EXPECT_NEAR(s.planes[1].plan_area, 16, 1e-9);
  EXPECT_NEAR(s.planes[1].normal.z(), 1, 1e-12);
}

TEST(Footprint, GroundSurfaceElseRoofProjection) {
  const Building g = eval_test::Gable("G", 0, 0, 12, 8, 0, 5, 3);
  EXPECT_NEAR(Area(BuildingFootprint(g, {})), 96, 1e-9);
  Building roof_only = g;
  roof_only.surfaces.erase(roof_only.surfaces.begin());  // drop the ground
  EXPECT_NEAR(Area(BuildingFootprint(roof_only, {})), 96, 1e-9);
}

}  // namespace
}  // namespace roofsweep::eval
