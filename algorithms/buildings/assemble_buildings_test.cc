#include "algorithms/buildings/assemble_buildings.h"

#include <gtest/gtest.h>

#include <cmath>

#include "algorithms/buildings/convex_polygon2.h"
#include "algorithms/buildings/solid_check.h"

namespace roofsweep {
namespace {

// Plane through point p with the given slope (deg) falling towards azimuth
// (deg, from +x counter-clockwise).
Eigen::Vector4d SlopedPlane(const Eigen::Vector3d& p, double slope_deg, double azimuth_deg) {
  const double s = slope_deg * M_PI / 180, a = azimuth_deg * M_PI / 180;
  const Eigen::Vector3d n(std::sin(s) * std::cos(a), std::sin(s) * std::sin(a), std::cos(s));
  return {n.x(), n.y(), n.z(), -n.dot(p)};
}

RoofPlaneHypothesis Hyp(const Eigen::Vector4d& plane, Ring2 patch, double score = 1) {
  RoofPlaneHypothesis h;
  h.plane = plane;
  h.patch = ConvexHull(std::move(patch));
  h.score = score;
  h.lines = 2;
  h.longest_line_m = 10;
  h.similarity = 0.5;
  return h;
}

GroundModel Flat(double z) {
  GroundModel g;
  g.height = z;
  return g;
}

// A 10 x 8 m gable roof, ridge along x at y = 4, eaves at z = 6, pitch 30 deg.
std::vector<RoofPlaneHypothesis> Gable(double x0 = 0) {
  const double ridge_z = 6 + 4 * std::tan(30 * M_PI / 180);
  return {
      Hyp(SlopedPlane({x0, 4, ridge_z}, 30, -90), {{x0, 0}, {x0 + 10, 0}, {x0 + 10, 4}, {x0, 4}}),
      Hyp(SlopedPlane({x0, 4, ridge_z}, 30, 90), {{x0, 4}, {x0 + 10, 4}, {x0 + 10, 8}, {x0, 8}})};
}

void ExpectAllValid(const AssemblyResult& r) {
  for (const Building& b : r.model.buildings) {
    const SolidCheckResult c = CheckBuildingSolid(b);
    EXPECT_TRUE(c.Valid()) << b.id << ": " << c.Summary();
    EXPECT_GT(c.signed_volume, 0) << b.id;
  }
}

TEST(AssembleBuildings, GableBecomesClosedGabledSolid) {
  const AssemblyResult r = AssembleBuildings(Gable(), Flat(0.5));
  ASSERT_EQ(r.model.buildings.size(), 1u);
  const Building& b = r.model.buildings[0];
  EXPECT_EQ(b.roof_type, roof_type::kGabled);
  EXPECT_NEAR(b.measured_height, 6 + 4 * std::tan(30 * M_PI / 180) - 0.5, 1e-6);
  int roofs = 0, walls = 0, grounds = 0;
  for (const Surface& s : b.surfaces) {
    roofs += s.type == SurfaceType::kRoof;
    walls += s.type == SurfaceType::kWall;
    grounds += s.type == SurfaceType::kGround;
  }
  EXPECT_EQ(roofs, 2);
  EXPECT_EQ(walls, 4);
  EXPECT_EQ(grounds, 1);
  ExpectAllValid(r);
  // Volume: footprint 80 m2 x 5.5 m walls + the prism 0.5 x 8 x 2.309 x 10.
  const double prism = 0.5 * 8 * 4 * std::tan(30 * M_PI / 180) * 10;
  EXPECT_NEAR(CheckBuildingSolid(b).signed_volume, 80 * 5.5 + prism, 1e-6);
}

TEST(AssembleBuildings, HipAndPyramid) {
  // Hip roof over 12 x 8 m: four planes at 35 deg from the eaves at z = 5.
  const double t = std::tan(35 * M_PI / 180);
  std::vector<RoofPlaneHypothesis> hip = {
      Hyp(SlopedPlane({0, 0, 5}, 35, -90), {{0, 0}, {12, 0}, {8, 4}, {4, 4}}),
      Hyp(SlopedPlane({0, 8, 5}, 35, 90), {{0, 8}, {12, 8}, {8, 4}, {4, 4}}),
      Hyp(SlopedPlane({0, 0, 5}, 35, 180), {{0, 0}, {0, 8}, {4, 4}}),
      Hyp(SlopedPlane({12, 0, 5}, 35, 0), {{12, 0}, {12, 8}, {8, 4}})};
  AssemblyResult r = AssembleBuildings(hip, Flat(0));
  ASSERT_EQ(r.model.buildings.size(), 1u);
  EXPECT_EQ(r.model.buildings[0].roof_type, roof_type::kHipped);
  EXPECT_NEAR(r.model.buildings[0].measured_height, 5 + 4 * t, 1e-6);
  ExpectAllValid(r);

  std::vector<RoofPlaneHypothesis> pyr = {
      Hyp(SlopedPlane({0, 0, 5}, 35, -90), {{0, 0}, {8, 0}, {4, 4}}),
      Hyp(SlopedPlane({0, 8, 5}, 35, 90), {{0, 8}, {8, 8}, {4, 4}}),
      Hyp(SlopedPlane({0, 0, 5}, 35, 180), {{0, 0}, {0, 8}, {4, 4}}),
      Hyp(SlopedPlane({8, 0, 5}, 35, 0), {{8, 0}, {8, 8}, {4, 4}})};
  r = AssembleBuildings(pyr, Flat(0));
  ASSERT_EQ(r.model.buildings.size(), 1u);
  EXPECT_EQ(r.model.buildings[0].roof_type, roof_type::kPavilion);
  ExpectAllValid(r);
}

TEST(AssembleBuildings, PartialPatchesStillCloseAndTwoBuildingsStayApart) {
  // The ridge's half-planes reached only 3 m of the 4 m faces; a second
  // gable 20 m away; a flat roof 3 m lower touching the first gable's
  // gable end is a separate building (a step, not a ridge).
  std::vector<RoofPlaneHypothesis> in = Gable();
  in[0].patch = ConvexHull({{0, 1}, {10, 1}, {10, 4}, {0, 4}});
  for (const auto& h : Gable(30)) in.push_back(h);
  in.push_back(Hyp(Eigen::Vector4d(0, 0, 1, -3.5), {{10.2, 0}, {16, 0}, {16, 8}, {10.2, 8}}));
  const AssemblyResult r = AssembleBuildings(in, Flat(0));
  ASSERT_EQ(r.model.buildings.size(), 3u);
  int gabled = 0, flat = 0;
  for (const Building& b : r.model.buildings) {
    gabled += b.roof_type == roof_type::kGabled;
    flat += b.roof_type == roof_type::kFlat;
  }
  EXPECT_EQ(gabled, 2);
  EXPECT_EQ(flat, 1);
  ExpectAllValid(r);
}

TEST(AssembleBuildings, EveryRejectionHasAReason) {
  std::vector<RoofPlaneHypothesis> in;
  in.push_back(
      Hyp(Eigen::Vector4d(0, 0, 1, -0.8), {{0, 0}, {10, 0}, {10, 10}, {0, 10}}));         // ground
  in.push_back(Hyp(SlopedPlane({40, 0, 6}, 85, 0), {{40, 0}, {41, 0}, {41, 10}}));        // wall
  in.push_back(Hyp(Eigen::Vector4d(0, 0, 1, -6), {{60, 0}, {62, 0}, {62, 2}, {60, 2}}));  // tiny
  RoofPlaneHypothesis bad = Hyp(Eigen::Vector4d(0, 0, 1, -6), {{80, 0}, {82, 0}, {82, 2}});
  bad.plane[2] = std::nan("");
  in.push_back(bad);
  RoofPlaneHypothesis crown = Hyp(Eigen::Vector4d(0, 0, 1, -6), {{90, 0}, {95, 0}, {95, 5}});
  crown.longest_line_m = 1.2;  // a tree crown's short lines
  in.push_back(crown);
  const AssemblyResult r = AssembleBuildings(in, Flat(0));
  EXPECT_TRUE(r.model.buildings.empty());
  ASSERT_EQ(r.rejected.size(), 5u);
  EXPECT_NE(r.rejected[3].find("longest supporting line"), std::string::npos) << r.rejected[3];
  EXPECT_NE(r.rejected[0].find("above the ground"), std::string::npos) << r.rejected[0];
  EXPECT_NE(r.rejected[1].find("slope"), std::string::npos) << r.rejected[1];
  EXPECT_NE(r.rejected[2].find("degenerate"), std::string::npos) << r.rejected[2];
  EXPECT_NE(r.rejected[4].find("footprint"), std::string::npos) << r.rejected[4];
}

TEST(AssembleBuildings, UnsupportedPlaneIsDroppedNotAllowedToCutTheRoof) {
  // A false steep plane seen only over a small patch at the gable's corner
  // would, in a plain lower envelope, slice off most of the roof.
  std::vector<RoofPlaneHypothesis> in = Gable();
  in.push_back(
      Hyp(SlopedPlane({9, 7, 7}, 60, 0), {{8.5, 6.5}, {9.5, 6.5}, {9.5, 7.5}, {8.5, 7.5}}, 0.1));
  const AssemblyResult r = AssembleBuildings(in, Flat(0));
  ASSERT_EQ(r.model.buildings.size(), 1u);
  EXPECT_EQ(r.model.buildings[0].roof_type, roof_type::kGabled);
  ASSERT_EQ(r.rejected.size(), 1u);
  EXPECT_NE(r.rejected[0].find("plane 2"), std::string::npos) << r.rejected[0];
  ExpectAllValid(r);
}

TEST(AssembleBuildings, ValleySplitsIntoConvexPartsOfOneBuilding) {
  // A butterfly roof: two planes falling towards a valley at y = 4. One
  // lower envelope would turn the V upside down; two parts keep it.
  std::vector<RoofPlaneHypothesis> in = {
      Hyp(SlopedPlane({0, 4, 6}, std::atan(0.5) * 180 / M_PI, 90),
          {{0, 0}, {10, 0}, {10, 4}, {0, 4}}),
      Hyp(SlopedPlane({0, 4, 6}, std::atan(0.5) * 180 / M_PI, -90),
          {{0, 4}, {10, 4}, {10, 8}, {0, 8}})};
  const AssemblyResult r = AssembleBuildings(in, Flat(0));
  ASSERT_EQ(r.model.buildings.size(), 2u);
  for (const Building& b : r.model.buildings) {
    EXPECT_EQ(b.roof_type, roof_type::kMonopitch) << b.id;
    EXPECT_NEAR(b.measured_height, 8.0, 1e-6) << b.id;
  }
  EXPECT_EQ(r.model.buildings[0].double_attributes.at("building_group"),
            r.model.buildings[1].double_attributes.at("building_group"));
  ExpectAllValid(r);
  // The gable (a ridge) stays one part.
  EXPECT_EQ(AssembleBuildings(Gable(), Flat(0)).model.buildings.size(), 1u);
}

TEST(ConvexPolygon2, ClipIntersectDistance) {
  const Ring2 sq = ConvexHull({{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 1}});
  ASSERT_EQ(sq.size(), 4u);
  EXPECT_NEAR(SignedArea(sq), 4, 1e-12);
  EXPECT_NEAR(SignedArea(ClipHalfPlane(sq, 1, 0, -0.5)), 1, 1e-12);  // x <= 0.5
  const Ring2 other = ConvexHull({{1, 1}, {3, 1}, {3, 3}, {1, 3}});
  EXPECT_NEAR(SignedArea(IntersectConvex(sq, other)), 1, 1e-12);
  const Ring2 far = ConvexHull({{5, 0}, {6, 0}, {6, 1}});
  EXPECT_NEAR(ConvexDistance(sq, far), 3, 1e-12);
  EXPECT_EQ(ConvexDistance(sq, other), 0);
}

}  // namespace
}  // namespace roofsweep
