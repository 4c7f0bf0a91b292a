#include "algorithms/buildings/assemble_buildings.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "algorithms/buildings/convex_polygon2.h"
#include "algorithms/buildings/footprint_completion.h"
#include "algorithms/buildings/footprint_roofs.h"
#include "algorithms/buildings/polygon2.h"
#include "algorithms/buildings/solid_check.h"
#include "algorithms/buildings/test_planes.h"

namespace roofsweep {
namespace {

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

bool Mentions(const std::vector<std::string>& lines, const std::string& a, const std::string& b) {
  for (const std::string& l : lines)
    if (l.find(a) != std::string::npos && l.find(b) != std::string::npos) return true;
  return false;
}

// Every solid of the result: the buildings without parts and the parts.
std::vector<Building> Solids(const AssemblyResult& r) {
  std::vector<Building> out;
  for (const Building& b : r.model.buildings)
    for (const Building* solid : b.Solids()) out.push_back(*solid);
  return out;
}

void ExpectAllValid(const AssemblyResult& r) {
  for (const Building& building : r.model.buildings) {
    ASSERT_FALSE(building.Solids().empty()) << building.id;
    for (const Building* b : building.Solids()) {
      const SolidCheckResult c = CheckBuildingSolid(*b);
      EXPECT_TRUE(c.Valid()) << b->id << ": " << c.Summary();
      EXPECT_GT(c.signed_volume, 0) << b->id;
    }
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
  EXPECT_EQ(b.double_attributes.at("supporting_lines"), 4);
  EXPECT_NEAR(b.double_attributes.at("photometric_score"), 0.5, 1e-12);
  // The planes' lines carried no reprojection residual: none is claimed.
  EXPECT_EQ(b.double_attributes.count("reprojection_rms_px"), 0u);
}

TEST(AssembleBuildings, TheBuildingsResidualIsTheRmsOverTheLinesOfItsFaces) {
  std::vector<RoofPlaneHypothesis> in = Gable();
  in[0].reprojection_rms_px = 0.5, in[0].reprojection_lines = 2;
  in[1].reprojection_rms_px = 1.0, in[1].reprojection_lines = 1;
  const AssemblyResult r = AssembleBuildings(in, Flat(0.5));
  ASSERT_EQ(r.model.buildings.size(), 1u);
  EXPECT_NEAR(r.model.buildings[0].double_attributes.at("reprojection_rms_px"),
              std::sqrt((2 * 0.25 + 1 * 1.0) / 3), 1e-12);
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
  // Each plane names the building it roofs: the first gable's two planes
  // one, the second gable's another.
  ASSERT_EQ(r.plane_building.size(), in.size());
  std::set<std::string> ids;
  for (const Building& b : r.model.buildings) ids.insert(b.id);
  for (size_t i = 0; i < in.size(); ++i) EXPECT_EQ(ids.count(r.plane_building[i]), 1u) << i;
  EXPECT_EQ(r.plane_building[0], r.plane_building[1]);
  EXPECT_EQ(r.plane_building[2], r.plane_building[3]);
  EXPECT_NE(r.plane_building[0], r.plane_building[2]);
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
  // Only the tiny roof's plane failed with its building hypothesis; the
  // others were dropped on their own.
  ASSERT_EQ(r.plane_reason.size(), in.size());
  for (size_t i = 0; i < in.size(); ++i) {
    EXPECT_TRUE(r.plane_building[i].empty()) << i;
    EXPECT_EQ(r.plane_reason[i].empty(), i != 2) << i << ": " << r.plane_reason[i];
  }
  EXPECT_EQ(r.plane_reason[2], r.rejected[4]);
}

TEST(AssembleBuildings, PlanesThatCannotBeRoofsAreDroppedWithTheirReasons) {
  // The gable's faces, a plane 1.85 m above the ground (on `realistic` s1
  // such a false plane won the sweep's conflict against the 2.1 m high
  // garage roof under it) and a wall.
  std::vector<RoofPlaneHypothesis> in = Gable();
  in.insert(in.begin() + 1,
            Hyp(Eigen::Vector4d(0, 0, 1, -1.85), {{20, 0}, {23, 0}, {23, 3}, {20, 3}}));
  in.push_back(Hyp(SlopedPlane({40, 0, 6}, 85, 0), {{40, 0}, {41, 0}, {41, 10}}));
  for (size_t i = 0; i < in.size(); ++i) in[i].id = "plane " + std::to_string(i);

  std::vector<RoofPlaneHypothesis> planes = in;
  const std::vector<std::string> reasons = DropRefusedRoofs(&planes, Flat(0), AssemblyOptions{});
  ASSERT_EQ(planes.size(), 2u);
  EXPECT_EQ(planes[0].id, "plane 0");
  EXPECT_EQ(planes[1].id, "plane 2");
  ASSERT_EQ(reasons.size(), 2u);
  EXPECT_EQ(reasons[0], "plane 1: 1.85 m above the ground < 2.00 m");
  EXPECT_TRUE(Mentions(reasons, "plane 3: ", "slope"));

  // The assembly refuses the same planes for the same reasons.
  const AssemblyResult r = AssembleBuildings(in, Flat(0));
  EXPECT_TRUE(Mentions(r.rejected, "plane 1: ", "above the ground"));
  EXPECT_TRUE(Mentions(r.rejected, "plane 3: ", "slope"));

  // With footprints a roof may be 1.5 m high.
  planes = in;
  EXPECT_EQ(DropRefusedRoofs(&planes, Flat(0), AssemblyOptionsFor(AssemblyOptions{}, true)).size(),
            1u);
  EXPECT_EQ(planes.size(), 3u);
}

TEST(AssembleBuildings, ShortLinesRefuseAPlaneUnlessSpared) {
  // A flat garage roof found as two planes of short lines (1.3 m and
  // 1.4 m): each alone is refused, but where it may still merge with its
  // neighbour only its other properties count.
  std::vector<RoofPlaneHypothesis> in = {
      Hyp(Eigen::Vector4d(0, 0, 1, -2.5), {{0, 0}, {3, 0}, {3, 6}, {0, 6}}),
      Hyp(Eigen::Vector4d(0, 0, 1, -2.5), {{3, 0}, {6, 0}, {6, 6}, {3, 6}}),
      Hyp(Eigen::Vector4d(0, 0, 1, -1.2), {{20, 0}, {23, 0}, {23, 3}, {20, 3}})};
  in[0].longest_line_m = 1.3;
  in[1].longest_line_m = 1.4;
  for (size_t i = 0; i < in.size(); ++i) in[i].id = "plane " + std::to_string(i);

  std::vector<RoofPlaneHypothesis> planes = in;
  std::vector<std::string> reasons = DropRefusedRoofs(&planes, Flat(0), AssemblyOptions{});
  EXPECT_TRUE(planes.empty());
  ASSERT_EQ(reasons.size(), 3u);
  EXPECT_EQ(reasons[0], "plane 0: longest supporting line 1.30 m < 3.00 m");

  planes = in;
  const std::vector<char> spare = {1, 0, 1};
  reasons = DropRefusedRoofs(&planes, Flat(0), AssemblyOptions{}, &spare);
  ASSERT_EQ(planes.size(), 1u);
  EXPECT_EQ(planes[0].id, "plane 0");
  ASSERT_EQ(reasons.size(), 2u);
  EXPECT_TRUE(Mentions(reasons, "plane 1: ", "longest supporting line"));
  // Spared from the line rule only: too low is too low.
  EXPECT_TRUE(Mentions(reasons, "plane 2: ", "above the ground"));
}

TEST(AssembleBuildings, AShortLinedPlaneIsKeptWhereItJoinsARoof) {
  // A porch roof (3 x 2 m, flat at the eave height, lines of 2.5 m) at the
  // gable's south eave: too short-lined alone, a roof part beside it.
  std::vector<RoofPlaneHypothesis> in = Gable();
  RoofPlaneHypothesis porch = Hyp(Eigen::Vector4d(0, 0, 1, -6), {{3, -2}, {6, -2}, {6, 0}, {3, 0}});
  porch.longest_line_m = 2.5;
  in.push_back(porch);
  AssemblyResult r = AssembleBuildings(in, Flat(0));
  EXPECT_TRUE(r.rejected.empty()) << r.rejected.front();
  double porch_area = 0;
  for (const Building& b : Solids(r))
    if (std::abs(b.measured_height - 6) < 1e-9) porch_area = b.double_attributes.at("footprint_m2");
  EXPECT_NEAR(porch_area, 6, 1e-6);
  ExpectAllValid(r);
  // The same roof 5 m away from the house is a hedge or a car.
  in.back().patch = ConvexHull({{3, -7}, {6, -7}, {6, -5}, {3, -5}});
  r = AssembleBuildings(in, Flat(0));
  ASSERT_EQ(r.rejected.size(), 1u);
  EXPECT_NE(r.rejected[0].find("joins no roof plane"), std::string::npos) << r.rejected[0];
  ASSERT_EQ(Solids(r).size(), 1u);
  EXPECT_EQ(Solids(r)[0].roof_type, roof_type::kGabled);
}

TEST(AssembleBuildings, AShortLinedPlaneGoesWithThePlaneItWasKeptFor) {
  // A short-lined facet at 3 m (a tree crown's) kept for meeting a plane
  // at 3.5 m over most of it, which lies above it everywhere in their
  // envelope and is dropped there (a second fit where the facet was seen,
  // not a roof of its own): the facet no longer joins any roof.
  RoofPlaneHypothesis facet = Hyp(Eigen::Vector4d(0, 0, 1, -3), {{0, 0}, {4, 0}, {4, 4}, {0, 4}});
  facet.longest_line_m = 2.5;
  const RoofPlaneHypothesis above =
      Hyp(Eigen::Vector4d(0, 0, 1, -3.5), {{1, 0}, {5, 0}, {5, 4}, {1, 4}});
  AssemblyResult r = AssembleBuildings({facet, above}, Flat(0));
  EXPECT_TRUE(r.model.buildings.empty());
  ASSERT_EQ(r.rejected.size(), 2u);
  EXPECT_TRUE(Mentions(r.rejected, "plane 1", "above the roof everywhere"));
  EXPECT_NE(r.plane_reason[0].find("kept for meeting roof planes that were dropped"),
            std::string::npos)
      << r.plane_reason[0];
  AssemblyOptions off;
  off.drop_lone_companions = false;
  r = AssembleBuildings({facet, above}, Flat(0), off);
  ASSERT_EQ(r.model.buildings.size(), 1u);
  EXPECT_EQ(r.plane_building[0], r.model.buildings[0].id);
  // A plane that stands on its own is not dropped with the plane beside it.
  RoofPlaneHypothesis roof = facet;
  roof.longest_line_m = 4;
  r = AssembleBuildings({roof, above}, Flat(0));
  ASSERT_EQ(r.model.buildings.size(), 1u);
  EXPECT_EQ(r.plane_building[0], r.model.buildings[0].id);
  // Nor is one whose companion still stands: the porch of
  // AShortLinedPlaneIsKeptWhereItJoinsARoof is a convex part of its own.
}

TEST(AssembleBuildings, AShortLinedPlaneStandsAloneWhenItsLinesMakeASquareCorner) {
  // A lone garage, 2.6 x 2.6 m, flat roof at 2.3 m, its outline seen as
  // lines of 2.5 m: no roof to join, but two lines meet at a right angle.
  RoofPlaneHypothesis garage =
      Hyp(Eigen::Vector4d(0, 0, 1, -2.3), {{0, 0}, {2.6, 0}, {2.6, 2.6}, {0, 2.6}});
  garage.longest_line_m = 2.5;
  garage.lines_xy = {{Eigen::Vector2d(0.05, 0), Eigen::Vector2d(2.55, 0)},
                     {Eigen::Vector2d(2.6, 0.1), Eigen::Vector2d(2.6, 2.5)}};
  AssemblyResult r = AssembleBuildings({garage}, Flat(0));
  EXPECT_TRUE(r.rejected.empty()) << r.rejected.front();
  ASSERT_EQ(r.model.buildings.size(), 1u);
  EXPECT_NEAR(r.model.buildings[0].measured_height, 2.3, 1e-9);
  ExpectAllValid(r);
  // Lines that cross at 45 deg, or at a right angle 3 m away from both
  // (two edges of a tree crown's shadow), make no corner.
  for (const auto& second :
       {std::array<Eigen::Vector2d, 2>{Eigen::Vector2d(0.5, 0.5), Eigen::Vector2d(2.2, 2.2)},
        std::array<Eigen::Vector2d, 2>{Eigen::Vector2d(5.6, 3), Eigen::Vector2d(5.6, 5)}}) {
    garage.lines_xy[1] = second;
    r = AssembleBuildings({garage}, Flat(0));
    ASSERT_EQ(r.rejected.size(), 1u);
    EXPECT_NE(r.rejected[0].find("no right-angled corner"), std::string::npos) << r.rejected[0];
    EXPECT_TRUE(r.model.buildings.empty());
  }
  // Arms shorter than corner_min_arm_m do not count either.
  garage.lines_xy[1] = {Eigen::Vector2d(2.6, 0.1), Eigen::Vector2d(2.6, 0.9)};
  EXPECT_TRUE(AssembleBuildings({garage}, Flat(0)).model.buildings.empty());
  AssemblyOptions off;
  off.keep_right_corners = false;
  garage.lines_xy[1] = {Eigen::Vector2d(2.6, 0.1), Eigen::Vector2d(2.6, 2.5)};
  EXPECT_TRUE(AssembleBuildings({garage}, Flat(0), off).model.buildings.empty());
}

TEST(AssembleBuildings, AFaceJoinsAShortLinedRoofKeptForItsSquareCorner) {
  // A garden shed, 2.6 x 2.4 m, gable along x at 34 deg, eaves at 2.2 m.
  // The south face holds its eave and a verge (a square corner); the north
  // face, mirrored from it, only the ridge. Both lines are under 3 m.
  const double ridge_z = 2.2 + 1.2 * std::tan(34 * M_PI / 180);
  RoofPlaneHypothesis south =
      Hyp(SlopedPlane({0, 1.2, ridge_z}, 34, -90), {{0, 0}, {2.6, 0}, {2.6, 1.2}, {0, 1.2}});
  south.longest_line_m = 2.5;
  south.lines_xy = {{Eigen::Vector2d(0.05, 0), Eigen::Vector2d(2.55, 0)},
                    {Eigen::Vector2d(2.6, 0.05), Eigen::Vector2d(2.6, 1.15)}};
  RoofPlaneHypothesis north =
      Hyp(SlopedPlane({0, 1.2, ridge_z}, 34, 90), {{0, 1.2}, {2.6, 1.2}, {2.6, 2.4}, {0, 2.4}});
  north.longest_line_m = 2.5;
  north.lines_xy = {{Eigen::Vector2d(0.05, 1.2), Eigen::Vector2d(2.55, 1.2)}};
  AssemblyResult r = AssembleBuildings({south, north}, Flat(0));
  EXPECT_TRUE(r.rejected.empty()) << r.rejected.front();
  ASSERT_EQ(Solids(r).size(), 1u);
  EXPECT_EQ(Solids(r)[0].roof_type, roof_type::kGabled);
  EXPECT_NEAR(Solids(r)[0].double_attributes.at("footprint_m2"), 2.6 * 2.4, 1e-6);
  ExpectAllValid(r);
  AssemblyOptions off;
  off.join_gable_to_corners = false;
  EXPECT_EQ(AssembleBuildings({south, north}, Flat(0), off).rejected.size(), 2u);
  // A facet beside it that is not the gable's other face (a tree crown's)
  // does not join it.
  RoofPlaneHypothesis facet = north;
  facet.plane = SlopedPlane({2.6, 1.8, 2.6}, 34, 0);
  facet.patch = ConvexHull({{2.6, 0}, {3.8, 0}, {3.8, 2.4}, {2.6, 2.4}});
  r = AssembleBuildings({south, facet}, Flat(0));
  EXPECT_EQ(r.rejected.size(), 2u);
  // Without the square corner neither face has a roof to join.
  south.lines_xy.pop_back();
  r = AssembleBuildings({south, north}, Flat(0));
  EXPECT_EQ(r.rejected.size(), 2u);
  EXPECT_TRUE(r.model.buildings.empty());
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

TEST(AssembleBuildings, ARoofHiddenByALowerNeighbourGoesOnAsABuildingOfItsOwn) {
  // Two flat garages 7 m apart, 0.3 m different in height, joined through
  // a carport roof between them at a height in between. Over the hull of
  // all three the lowest garage's plane lies below the others, which were
  // seen where it is only extrapolated: each goes on as a building of its
  // own.
  std::vector<RoofPlaneHypothesis> in = {
      Hyp(Eigen::Vector4d(0, 0, 1, -3.0), {{0, 0}, {6, 0}, {6, 8}, {0, 8}}, 2),
      Hyp(Eigen::Vector4d(0, 0, 1, -3.3), {{13, 0}, {19, 0}, {19, 8}, {13, 8}}, 2),
      Hyp(Eigen::Vector4d(0, 0, 1, -3.15), {{6.5, 3}, {12.5, 3}, {12.5, 5}, {6.5, 5}}, 0.5)};
  AssemblyResult r = AssembleBuildings(in, Flat(0));
  EXPECT_TRUE(r.rejected.empty()) << r.rejected.front();
  std::vector<std::pair<double, double>> got;  // height, footprint
  for (const Building& b : Solids(r))
    got.emplace_back(b.measured_height, b.double_attributes.at("footprint_m2"));
  std::sort(got.begin(), got.end());
  ASSERT_EQ(got.size(), 3u);
  const double want[3][2] = {{3.0, 48}, {3.15, 12}, {3.3, 48}};
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(got[k].first, want[k][0], 1e-9);
    EXPECT_NEAR(got[k].second, want[k][1], 1e-6);
  }
  ExpectAllValid(r);

  // Without the split the hidden planes are dropped like slivers, the
  // weakest first: the carport roof. The hypothesis then falls apart and is
  // built piece by piece; one envelope over both garages would let the
  // lower roof cover the higher garage and the gap.
  AssemblyOptions o;
  o.split_hidden = false;
  r = AssembleBuildings(in, Flat(0), o);
  ASSERT_EQ(Solids(r).size(), 2u);
  ASSERT_EQ(r.rejected.size(), 1u);
  EXPECT_NE(r.rejected[0].find("plane 2"), std::string::npos) << r.rejected[0];
  std::vector<double> heights;
  for (const Building& b : Solids(r)) {
    heights.push_back(b.measured_height);
    EXPECT_NEAR(b.double_attributes.at("footprint_m2"), 48, 1e-6) << b.id;
  }
  std::sort(heights.begin(), heights.end());
  EXPECT_NEAR(heights[0], 3.0, 1e-9);
  EXPECT_NEAR(heights[1], 3.3, 1e-9);
  ExpectAllValid(r);
}

TEST(AssembleBuildings, ASecondFitOfAFaceHiddenWhereTheFaceWasSeenIsDropped) {
  // A gable and a second plane fitted to its south face's lines, 3 deg
  // shallower and 5 cm higher at the ridge: above the face everywhere, so
  // hidden, and seen over the same ground. It is no roof at another height.
  std::vector<RoofPlaneHypothesis> in = Gable();
  const double ridge_z = 6 + 4 * std::tan(30 * M_PI / 180);
  in.push_back(Hyp(SlopedPlane({0, 4, ridge_z + 0.05}, 27, -90),
                   {{0, 0.5}, {6, 0.5}, {6, 3.8}, {0, 3.8}}, 0.8));
  in.back().id = "second fit";
  AssemblyResult r = AssembleBuildings(in, Flat(0));
  ASSERT_EQ(Solids(r).size(), 1u);
  EXPECT_EQ(Solids(r)[0].roof_type, roof_type::kGabled);
  EXPECT_TRUE(Mentions(r.rejected, "second fit", "")) << r.rejected.size();
  ExpectAllValid(r);
  // Treated as a neighbour, it became a shed roof inside the gable.
  AssemblyOptions o;
  o.hidden_duplicate_overlap = 1;
  r = AssembleBuildings(in, Flat(0), o);
  ASSERT_EQ(Solids(r).size(), 2u);
  EXPECT_EQ(Solids(r)[1].roof_type, roof_type::kMonopitch);
}

TEST(AssembleBuildings, AHigherTerraceRowHiddenByTheHouseBesideItIsKept) {
  // A terrace: a 5 m house and a 20 m row joined at a party wall, the
  // row's roof 0.3 m higher. Over the hull of both, the house's planes lie
  // below the row's everywhere: the row's gable, seen but hidden, goes on
  // as a building of its own, and the house keeps its faces.
  std::vector<RoofPlaneHypothesis> in;
  const double ridge_z = 6 + 4 * std::tan(30 * M_PI / 180);
  for (double az : {-90.0, 90.0}) {
    const double y0 = az < 0 ? 0 : 4, y1 = az < 0 ? 4 : 8;
    in.push_back(Hyp(SlopedPlane({0, 4, ridge_z}, 30, az), {{0, y0}, {5, y0}, {5, y1}, {0, y1}}));
    in.push_back(Hyp(SlopedPlane({5.5, 4, ridge_z + 0.3}, 30, az),
                     {{5.5, y0}, {25, y0}, {25, y1}, {5.5, y1}}));
  }
  AssemblyResult r = AssembleBuildings(in, Flat(0));
  EXPECT_TRUE(r.rejected.empty()) << r.rejected.front();
  ASSERT_EQ(Solids(r).size(), 2u);
  std::vector<std::pair<double, double>> got;  // height, footprint
  for (const Building& b : Solids(r)) {
    EXPECT_EQ(b.roof_type, roof_type::kGabled) << b.id;
    got.emplace_back(b.measured_height, b.double_attributes.at("footprint_m2"));
  }
  std::sort(got.begin(), got.end());
  EXPECT_NEAR(got[0].first, ridge_z, 1e-9);
  EXPECT_NEAR(got[0].second, 40, 1e-6);
  EXPECT_NEAR(got[1].first, ridge_z + 0.3, 1e-9);
  EXPECT_NEAR(got[1].second, 156, 1e-6);
  ExpectAllValid(r);

  // Without the split, the house's planes, seen over less than a third of
  // their faces, go first, and the row keeps its faces instead of losing
  // them for being hidden (which would then leave no roof at all).
  AssemblyOptions o;
  o.split_hidden = false;
  r = AssembleBuildings(in, Flat(0), o);
  ASSERT_EQ(Solids(r).size(), 1u);
  EXPECT_EQ(Solids(r)[0].roof_type, roof_type::kGabled);
  EXPECT_NEAR(Solids(r)[0].measured_height, ridge_z + 0.3, 1e-9);
  ASSERT_EQ(r.rejected.size(), 2u);
  for (const std::string& why : r.rejected)
    EXPECT_NE(why.find("where the images saw the plane"), std::string::npos) << why;
  ExpectAllValid(r);
}

TEST(AssembleBuildings, OneHousesHullDoesNotRunOverItsLowerNeighbour) {
  // Two terraced houses of 7 x 8 m, gables along x, the east one 1.2 m
  // lower: buildings of their own. The west house's south face was found
  // along an eave line that runs on over the east house's eave (collinear
  // in every view), so its patch reaches x = 14 there; the hull of its
  // patches then lays a triangle of 28 m² over the east house, which its
  // own faces cover whole. The west house is built again without it.
  const double ridge_z = 6 + 4 * std::tan(30 * M_PI / 180);
  std::vector<RoofPlaneHypothesis> in = {
      Hyp(SlopedPlane({0, 4, ridge_z}, 30, -90), {{0, 0}, {14, 0}, {7, 4}, {0, 4}}),
      Hyp(SlopedPlane({0, 4, ridge_z}, 30, 90), {{0, 4}, {7, 4}, {7, 8}, {0, 8}}),
      Hyp(SlopedPlane({7, 4, ridge_z - 1.2}, 30, -90), {{7, 0}, {14, 0}, {14, 4}, {7, 4}}),
      Hyp(SlopedPlane({7, 4, ridge_z - 1.2}, 30, 90), {{7, 4}, {14, 4}, {14, 8}, {7, 8}})};
  AssemblyResult r = AssembleBuildings(in, Flat(0));
  std::vector<std::pair<double, double>> got;  // height, footprint
  for (const Building& b : Solids(r)) {
    EXPECT_EQ(b.roof_type, roof_type::kGabled) << b.id;
    got.emplace_back(b.measured_height, b.double_attributes.at("footprint_m2"));
  }
  std::sort(got.begin(), got.end());
  ASSERT_EQ(got.size(), 2u);
  EXPECT_NEAR(got[0].first, ridge_z - 1.2, 1e-9);
  EXPECT_NEAR(got[0].second, 56, 1e-4);  // Boost's overlay, to a tenth of a mm2
  EXPECT_NEAR(got[1].first, ridge_z, 1e-9);
  EXPECT_NEAR(got[1].second, 56, 1e-4);
  EXPECT_TRUE(Mentions(r.rejected, "overlaps", "built again without it")) << r.rejected.size();
  ExpectAllValid(r);
  auto total_footprint = [](const AssemblyResult& r) {
    double total = 0;
    for (const Building& b : Solids(r)) total += b.double_attributes.at("footprint_m2");
    return total;
  };
  // Left overlapping, the west house covers 28 m² of the east one's roof.
  AssemblyOptions o;
  o.max_building_overlap_m2 = 0;
  EXPECT_NEAR(total_footprint(AssembleBuildings(in, Flat(0), o)), 112 + 28, 1e-6);
  // Both west faces seen over the whole row as well: the images saw both
  // roofs over the east house alike, and the overlap stays.
  in[0].patch = ConvexHull({{0, 0}, {14, 0}, {14, 4}, {0, 4}});
  in[1].patch = ConvexHull({{0, 4}, {14, 4}, {14, 8}, {0, 8}});
  r = AssembleBuildings(in, Flat(0));
  EXPECT_FALSE(Mentions(r.rejected, "overlaps", "built again")) << r.rejected.size();
  EXPECT_NEAR(total_footprint(r), 112 + 56, 1e-6);
}

TEST(AssembleBuildings, TheOutlineFollowsTheBorderLines) {
  // The south face's patch stops 0.4 m short of its eave, the north face's
  // runs 0.6 m past it (into the garden); both eaves were matched as lines.
  std::vector<RoofPlaneHypothesis> in = Gable();
  in[0].patch = ConvexHull({{0, 0.4}, {10, 0.4}, {10, 4}, {0, 4}});
  in[1].patch = ConvexHull({{0, 4}, {10, 4}, {10, 8.6}, {0, 8.6}});
  in[0].lines_xy = {{Eigen::Vector2d(0.5, 0), Eigen::Vector2d(9.5, 0)}};
  in[1].lines_xy = {{Eigen::Vector2d(9, 8), Eigen::Vector2d(1, 8)}};
  // A ridge line inside the outline and a verge at 30 degrees to every
  // edge move nothing.
  in[0].lines_xy.push_back({Eigen::Vector2d(0, 4), Eigen::Vector2d(10, 4)});
  in[1].lines_xy.push_back({Eigen::Vector2d(10, 4), Eigen::Vector2d(10 - 4 * std::sqrt(3.0), 8)});
  AssemblyResult r = AssembleBuildings(in, Flat(0));
  ASSERT_EQ(r.model.buildings.size(), 1u);
  EXPECT_NEAR(r.model.buildings[0].double_attributes.at("footprint_m2"), 80, 1e-6);
  EXPECT_EQ(r.model.buildings[0].roof_type, roof_type::kGabled);
  ExpectAllValid(r);
  AssemblyOptions o;
  o.border_lines = false;  // the patches' own extent: 10 x 8.2 m
  r = AssembleBuildings(in, Flat(0), o);
  ASSERT_EQ(r.model.buildings.size(), 1u);
  EXPECT_NEAR(r.model.buildings[0].double_attributes.at("footprint_m2"), 82, 1e-6);
  // A line farther than border_max_offset_m from the outline is not a border.
  in[0].lines_xy[0] = {Eigen::Vector2d(0.5, -1.5), Eigen::Vector2d(9.5, -1.5)};
  r = AssembleBuildings(in, Flat(0));
  ASSERT_EQ(r.model.buildings.size(), 1u);
  EXPECT_NEAR(r.model.buildings[0].double_attributes.at("footprint_m2"), 76, 1e-6);
}

TEST(AssembleBuildings, RoundedOrCutCornersOfTheOutlineAreSquared) {
  // The patches keep off two corners of the house: the south-west one cut
  // by 1 m legs, the north-east one by 0.8 m legs in two steps.
  std::vector<RoofPlaneHypothesis> in = Gable();
  in[0].patch = ConvexHull({{0, 1}, {1, 0}, {10, 0}, {10, 4}, {0, 4}});
  in[1].patch = ConvexHull({{0, 4}, {10, 4}, {10, 7.2}, {9.8, 7.8}, {9.2, 8}, {0, 8}});
  auto area = [&](const AssemblyOptions& o) {
    const AssemblyResult r = AssembleBuildings(in, Flat(0), o);
    EXPECT_EQ(r.model.buildings.size(), 1u);
    ExpectAllValid(r);
    return r.model.buildings.empty() ? 0.0
                                     : r.model.buildings[0].double_attributes.at("footprint_m2");
  };
  EXPECT_NEAR(area({}), 80, 1e-6);
  AssemblyOptions off;
  off.square_corners = false;
  const double cut = 0.5 + 0.16;  // the triangle, and the quadrilateral by the shoelace formula
  EXPECT_NEAR(area(off), 80 - cut, 1e-6);
  // A cut corner with a line along it is the building's own.
  in[0].lines_xy = {{Eigen::Vector2d(0, 1), Eigen::Vector2d(1, 0)}};
  EXPECT_NEAR(area({}), 79.5, 1e-6);
  // A corner whose filling would reach out 2.1 m is not a rounded corner.
  in[0].lines_xy.clear();
  in[0].patch = ConvexHull({{0, 3}, {3, 0}, {10, 0}, {10, 4}, {0, 4}});
  EXPECT_NEAR(area({}), 80 - 4.5, 1e-6);
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
  ASSERT_EQ(Solids(r).size(), 2u);
  for (const Building& b : Solids(r)) {
    EXPECT_EQ(b.roof_type, roof_type::kMonopitch) << b.id;
    EXPECT_NEAR(b.measured_height, 8.0, 1e-6) << b.id;
  }
  EXPECT_EQ(Solids(r)[0].double_attributes.at("building_group"),
            Solids(r)[1].double_attributes.at("building_group"));
  // ... the parts of one building.
  ASSERT_EQ(r.model.buildings.size(), 1u);
  EXPECT_EQ(r.model.buildings[0].parts.size(), 2u);
  EXPECT_EQ(r.model.buildings[0].double_attributes.at("building_parts"), 2);
  EXPECT_EQ(r.plane_building[0], "rs_b0001_p1");
  ExpectAllValid(r);
  AssemblyOptions apart;
  apart.join_parts_per_group = false;
  EXPECT_EQ(AssembleBuildings(in, Flat(0), apart).model.buildings.size(), 2u);
  // The gable (a ridge) stays one part.
  EXPECT_EQ(AssembleBuildings(Gable(), Flat(0)).model.buildings.size(), 1u);
}

TEST(AssembleBuildings, AShedRoofBesideAGableIsAPartOfItsOwn) {
  // A terraced row: the gable of Gable() and, beyond the party wall at
  // x = 10, a shed roof rising north at 15 deg from an eave 1 m higher (as
  // on `realistic` s1). The shed crosses both gable faces along lines
  // parallel to the ridge, across the strip where the patches meet, not
  // along it: one lower envelope over the three planes lays a strip of the
  // shed plane between the gable's faces along the whole row.
  std::vector<RoofPlaneHypothesis> in = Gable();
  in.push_back(Hyp(SlopedPlane({10, 0, 7}, 15, -90), {{10, 0}, {16, 0}, {16, 8}, {10, 8}}));
  const AssemblyResult r = AssembleBuildings(in, Flat(0));
  ASSERT_EQ(Solids(r).size(), 2u);
  std::multiset<int> types;
  for (const Building& b : Solids(r)) types.insert(b.roof_type);
  EXPECT_EQ(types, (std::multiset<int>{roof_type::kGabled, roof_type::kMonopitch}));
  for (const Building& b : Solids(r)) {
    if (b.roof_type == roof_type::kMonopitch) {
      EXPECT_NEAR(b.measured_height, 7 + 8 * std::tan(15 * M_PI / 180), 1e-6);
    }
  }
  EXPECT_EQ(Solids(r)[0].double_attributes.at("building_group"),
            Solids(r)[1].double_attributes.at("building_group"));
  ExpectAllValid(r);

  // Without the test the three planes make one roof of three faces.
  AssemblyOptions o;
  o.split_across_edges = false;
  const AssemblyResult one = AssembleBuildings(in, Flat(0), o);
  ASSERT_EQ(Solids(one).size(), 1u);
  int roofs = 0;
  const Building first = Solids(one)[0];
  for (const Surface& f : first.surfaces) roofs += f.type == SurfaceType::kRoof;
  EXPECT_EQ(roofs, 3);
}

TEST(AssembleBuildings, APlaneTheEnvelopeDropsIsNotRescuedAsAPartOfItsOwn) {
  // A flat plane 1 m wide beside the gable at 7.2 m (a false plane in the
  // gap to the next house): it crosses the gable's faces across the strip
  // where they meet, but in their envelope its face lies mostly outside
  // its patch, so it is dropped before any part is split off.
  std::vector<RoofPlaneHypothesis> in = Gable();
  in.push_back(Hyp({0, 0, 1, -7.2}, {{10, 0}, {11, 0}, {11, 8}, {10, 8}}));
  const AssemblyResult r = AssembleBuildings(in, Flat(0));
  ASSERT_EQ(r.model.buildings.size(), 1u);
  EXPECT_EQ(r.model.buildings[0].roof_type, roof_type::kGabled);
  EXPECT_TRUE(r.plane_building[2].empty());
  EXPECT_TRUE(std::any_of(r.rejected.begin(), r.rejected.end(), [](const std::string& why) {
    return why.find("where the images saw the plane") != std::string::npos;
  }));
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

TEST(ConvexPolygon2, SlabAndChord) {
  // A triangle with its right angle at the origin, legs 4 along x and 2
  // along y; slabs and chords across x.
  const Ring2 tri = ConvexHull({{0, 0}, {4, 0}, {0, 2}});
  const Eigen::Vector2d x(1, 0), y(0, 1);
  EXPECT_NEAR(SignedArea(ConvexSlab(tri, x, 0, 2)), 3, 1e-12);  // 4 minus the tip's 1
  EXPECT_NEAR(SignedArea(ConvexSlab(tri, x, 2, 9)), 1, 1e-12);
  EXPECT_LT(ConvexSlab(tri, x, 5, 9).size(), 3u);
  const auto [lo, hi] = ConvexChord(tri, x, y, 2);
  EXPECT_NEAR(lo, 0, 1e-12);
  EXPECT_NEAR(hi, 1, 1e-12);
  const auto [none_lo, none_hi] = ConvexChord(tri, x, y, 5);
  EXPECT_GT(none_lo, none_hi);
}

Footprint Fp(const std::string& id, Ring2 outline) {
  Footprint f;
  f.id = id;
  f.outline = std::move(outline);
  return f;
}

TEST(AssembleBuildings, PlanesMostlyOutsideTheFootprintsAreDroppedWithTheirReasons) {
  // The gable's faces over its footprint, a plane with a third of its patch
  // over it (a neighbour's face run over the eave) and one with five
  // sixths.
  std::vector<RoofPlaneHypothesis> in = Gable();
  in.push_back(Hyp(SlopedPlane({8, 4, 6}, 30, -90), {{8, 0}, {14, 0}, {14, 4}, {8, 4}}));
  in.push_back(Hyp(SlopedPlane({5, 4, 6}, 30, 90), {{5, 4}, {11, 4}, {11, 8}, {5, 8}}));
  for (size_t i = 0; i < in.size(); ++i) in[i].id = "plane " + std::to_string(i);
  const std::vector<Footprint> footprints = {Fp("house", {{0, 0}, {10, 0}, {10, 8}, {0, 8}})};

  std::vector<RoofPlaneHypothesis> planes = in;
  const std::vector<std::string> reasons =
      DropOutsideFootprints(&planes, footprints, AssemblyOptions{});
  ASSERT_EQ(planes.size(), 3u);
  EXPECT_EQ(planes[2].id, "plane 3");
  ASSERT_EQ(reasons.size(), 1u);
  EXPECT_EQ(reasons[0], "plane 2: 33 % of its patch over a footprint < 50 %");

  // The assembly refuses it for the same reason.
  const AssemblyResult r = AssembleBuildings(in, Flat(0), AssemblyOptions{}, footprints);
  EXPECT_TRUE(Mentions(r.rejected, reasons[0], ""));

  // Without footprints nothing is dropped.
  planes = in;
  EXPECT_TRUE(DropOutsideFootprints(&planes, {}, AssemblyOptions{}).empty());
  EXPECT_EQ(planes.size(), 4u);
}

int Count(const Building& b, SurfaceType t) {
  int n = 0;
  for (const Surface& s : b.surfaces) n += s.type == t;
  return n;
}

TEST(AssembleBuildingsFootprints, WallsStandOnTheFootprint) {
  // Patches seen over the middle of each face only; the footprint is the
  // true 10 x 8 m outline.
  const double ridge_z = 6 + 4 * std::tan(30 * M_PI / 180);
  const std::vector<RoofPlaneHypothesis> planes = {
      Hyp(SlopedPlane({0, 4, ridge_z}, 30, -90), {{1, 0.5}, {9, 0.5}, {9, 3.8}, {1, 3.8}}),
      Hyp(SlopedPlane({0, 4, ridge_z}, 30, 90), {{1.5, 4.2}, {8.5, 4.2}, {8.5, 7}, {1.5, 7}})};
  const AssemblyResult without = AssembleBuildings(planes, Flat(0));
  ASSERT_EQ(without.model.buildings.size(), 1u);
  EXPECT_LT(without.model.buildings[0].double_attributes.at("footprint_m2"), 60);

  const AssemblyResult r =
      AssembleBuildings(planes, Flat(0), {}, {Fp("DEBE123", {{0, 0}, {10, 0}, {10, 8}, {0, 8}})});
  ASSERT_EQ(r.model.buildings.size(), 1u);
  const Building& b = r.model.buildings[0];
  EXPECT_NEAR(b.double_attributes.at("footprint_m2"), 80, 1e-9);
  EXPECT_EQ(b.string_attributes.at("footprint_id"), "DEBE123");
  EXPECT_EQ(b.string_attributes.at("outline"), "footprint");
  EXPECT_EQ(b.roof_type, roof_type::kGabled);
  EXPECT_EQ(Count(b, SurfaceType::kRoof), 2);
  EXPECT_NEAR(b.measured_height, ridge_z, 1e-9);
  ExpectAllValid(r);
}

TEST(AssembleBuildingsFootprints, OnePlaneOverATerraceBecomesOneBuildingPerHouse) {
  // A flat roof plane found across three terraced houses of equal height.
  const std::vector<RoofPlaneHypothesis> planes = {
      Hyp({0, 0, 1, -7}, {{0.5, 0.5}, {29.5, 0.5}, {29.5, 7.5}, {0.5, 7.5}})};
  EXPECT_EQ(AssembleBuildings(planes, Flat(0)).model.buildings.size(), 1u);
  const std::vector<Footprint> houses = {Fp("a", {{0, 0}, {10, 0}, {10, 8}, {0, 8}}),
                                         Fp("b", {{10, 0}, {20, 0}, {20, 8}, {10, 8}}),
                                         Fp("c", {{20, 0}, {30, 0}, {30, 8}, {20, 8}})};
  const AssemblyResult r = AssembleBuildings(planes, Flat(0), {}, houses);
  ASSERT_EQ(r.model.buildings.size(), 3u);
  for (size_t k = 0; k < 3; ++k) {
    const Building& b = r.model.buildings[k];
    EXPECT_EQ(b.string_attributes.at("footprint_id"), houses[k].id);
    EXPECT_NEAR(b.double_attributes.at("footprint_m2"), 80, 1e-9) << b.id;
    EXPECT_EQ(b.roof_type, roof_type::kFlat);
  }
  ExpectAllValid(r);
}

TEST(AssembleBuildingsFootprints, NonConvexFootprint) {
  // An L-shaped footprint under one flat roof: the solid follows the L.
  const Ring2 l = {{0, 0}, {12, 0}, {12, 5}, {5, 5}, {5, 12}, {0, 12}};
  const std::vector<RoofPlaneHypothesis> planes = {
      Hyp({0, 0, 1, -6}, {{0.5, 0.5}, {11, 0.5}, {11, 4.5}, {4.5, 11}, {0.5, 11}})};
  const AssemblyResult r = AssembleBuildings(planes, Flat(0), {}, {Fp("L", l)});
  ASSERT_EQ(r.model.buildings.size(), 1u);
  const Building& b = r.model.buildings[0];
  EXPECT_NEAR(b.double_attributes.at("footprint_m2"), 12 * 5 + 5 * 7, 1e-9);
  EXPECT_EQ(b.string_attributes.at("outline"), "footprint");
  EXPECT_EQ(Count(b, SurfaceType::kWall), 6);
  ExpectAllValid(r);
  EXPECT_NEAR(CheckBuildingSolid(b).signed_volume, 95 * 6, 1e-6);
}

TEST(AssembleBuildingsFootprints, NonConvexFootprintUnderAGable) {
  // The gable's two faces each cut at the reflex corner of an L-shaped
  // footprint (a notch in one corner): roof faces may be non-convex.
  const double ridge_z = 6 + 4 * std::tan(30 * M_PI / 180);
  const std::vector<RoofPlaneHypothesis> planes = {
      Hyp(SlopedPlane({0, 4, ridge_z}, 30, -90), {{1, 0.5}, {9, 0.5}, {9, 3.8}, {1, 3.8}}),
      Hyp(SlopedPlane({0, 4, ridge_z}, 30, 90), {{1, 4.2}, {7, 4.2}, {7, 7.5}, {1, 7.5}})};
  const Ring2 notched = {{0, 0}, {10, 0}, {10, 6}, {8, 6}, {8, 8}, {0, 8}};
  const AssemblyResult r = AssembleBuildings(planes, Flat(0), {}, {Fp("n", notched)});
  ASSERT_EQ(r.model.buildings.size(), 1u);
  const Building& b = r.model.buildings[0];
  EXPECT_EQ(b.string_attributes.at("outline"), "footprint");
  EXPECT_NEAR(b.double_attributes.at("footprint_m2"), 76, 1e-9);
  ExpectAllValid(r);
}

TEST(AssembleBuildingsFootprints, OneSideOfAGableIsNotAShedOverTheWholeFootprint) {
  const double ridge_z = 6 + 4 * std::tan(30 * M_PI / 180);
  const std::vector<RoofPlaneHypothesis> planes = {
      Hyp(SlopedPlane({0, 4, ridge_z}, 30, -90), {{1, 0.5}, {9, 0.5}, {9, 3.8}, {1, 3.8}})};
  const AssemblyResult r =
      AssembleBuildings(planes, Flat(0), {}, {Fp("g", {{0, 0}, {10, 0}, {10, 8}, {0, 8}})});
  ASSERT_EQ(r.model.buildings.size(), 1u);
  const Building& b = r.model.buildings[0];
  EXPECT_EQ(b.string_attributes.at("outline"), "roof planes cut at the footprint");
  EXPECT_LT(b.double_attributes.at("footprint_m2"), 40);
  ExpectAllValid(r);
}

TEST(AssembleBuildingsFootprints, AFlatRoofSeenOverPartOfItsFootprintCoversItWhole) {
  // A green roof seen where its structures are: 4 of its 10 m depth.
  const Ring2 seen = {{0.5, 0.5}, {9.5, 0.5}, {9.5, 4}, {0.5, 4}};
  const Ring2 outline = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  const AssemblyResult flat =
      AssembleBuildings({Hyp({0, 0, 1, -6}, seen)}, Flat(0), {}, {Fp("f", outline)});
  ASSERT_EQ(flat.model.buildings.size(), 1u);
  EXPECT_EQ(flat.model.buildings[0].string_attributes.at("outline"), "footprint");
  EXPECT_NEAR(flat.model.buildings[0].double_attributes.at("footprint_m2"), 100, 1e-9);
  ExpectAllValid(flat);
  // The same patch of a 20 deg shed is not carried over the rest.
  const AssemblyResult shed = AssembleBuildings({Hyp(SlopedPlane({0, 0, 6}, 20, 90), seen)},
                                                Flat(0), {}, {Fp("s", outline)});
  ASSERT_EQ(shed.model.buildings.size(), 1u);
  EXPECT_EQ(shed.model.buildings[0].string_attributes.at("outline"),
            "roof planes cut at the footprint");
  EXPECT_LT(shed.model.buildings[0].double_attributes.at("footprint_m2"), 50);
  // Nor is a flat plane seen over less than footprint_flat_min_support.
  const AssemblyResult small =
      AssembleBuildings({Hyp({0, 0, 1, -6}, {{0.5, 0.5}, {9.5, 0.5}, {9.5, 1.5}, {0.5, 1.5}})},
                        Flat(0), {}, {Fp("t", outline)});
  ASSERT_EQ(small.model.buildings.size(), 1u);
  EXPECT_LT(small.model.buildings[0].double_attributes.at("footprint_m2"), 50);
}

TEST(AssembleBuildingsFootprints, EveryPlaneAndFootprintEndsSomewhere) {
  std::vector<RoofPlaneHypothesis> planes = Gable();
  planes.push_back(Hyp({0, 0, 1, -6}, {{50, 50}, {60, 50}, {60, 60}, {50, 60}}));
  planes.back().id = "plane in the park";
  const std::vector<Footprint> fps = {Fp("house", {{0, 0}, {10, 0}, {10, 8}, {0, 8}}),
                                      Fp("shed", {{30, 0}, {34, 0}, {34, 3}, {30, 3}})};
  const AssemblyResult r = AssembleBuildings(planes, Flat(0), {}, fps);
  ASSERT_EQ(r.model.buildings.size(), 1u);
  EXPECT_EQ(r.model.buildings[0].string_attributes.at("footprint_id"), "house");
  EXPECT_TRUE(Mentions(r.rejected, "plane in the park", "over a footprint")) << r.rejected.size();
  EXPECT_TRUE(Mentions(r.rejected, "footprint shed", "no roof plane"));
  // The footprint's reason is also kept by id, with its line.
  ASSERT_EQ(r.footprint_rejection.size(), 1u);
  const auto& shed = r.footprint_rejection.at("shed");
  EXPECT_EQ(shed.why, "no roof plane found over it");
  ASSERT_LT(shed.line, r.rejected.size());
  EXPECT_EQ(r.rejected[shed.line], "footprint shed: " + shed.why);
  ExpectAllValid(r);
}

TEST(AssembleBuildingsFootprints, SolidsOverOneFootprintArePartsOfOneBuilding) {
  // A house with a wing 3 m higher under one cadastral footprint: the two
  // flat roofs cannot share one envelope, so two solids are built, and
  // they are the two parts of the footprint's one building.
  const std::vector<RoofPlaneHypothesis> planes = {
      Hyp({0, 0, 1, -6}, {{0.5, 0.5}, {5.8, 0.5}, {5.8, 5.5}, {0.5, 5.5}}, 2),
      Hyp({0, 0, 1, -9}, {{6.2, 0.5}, {11.5, 0.5}, {11.5, 5.5}, {6.2, 5.5}}, 3)};
  const std::vector<Footprint> fps = {Fp("DEBE7", {{0, 0}, {12, 0}, {12, 6}, {0, 6}}),
                                      Fp("DEBE8", {{20, 0}, {30, 0}, {30, 8}, {20, 8}})};
  std::vector<RoofPlaneHypothesis> with_gable = planes;
  for (RoofPlaneHypothesis& h : Gable(20)) with_gable.push_back(h);
  const AssemblyResult r = AssembleBuildings(with_gable, Flat(0), {}, fps);
  ASSERT_EQ(r.model.buildings.size(), 2u);
  ExpectAllValid(r);
  const Building& b = r.model.buildings[0];
  EXPECT_EQ(b.id, "rs_b0001");
  EXPECT_EQ(b.string_attributes.at("footprint_id"), "DEBE7");
  EXPECT_TRUE(b.surfaces.empty());
  ASSERT_EQ(b.parts.size(), 2u);
  EXPECT_EQ(b.parts[0].id, "rs_b0001_p1");
  EXPECT_EQ(b.parts[1].id, "rs_b0001_p2");
  EXPECT_EQ(b.parts[0].string_attributes.at("footprint_id"), "DEBE7");
  EXPECT_NEAR(b.measured_height, 9, 1e-9);
  EXPECT_EQ(b.roof_type, roof_type::kFlat);
  EXPECT_EQ(b.double_attributes.at("building_parts"), 2);
  EXPECT_EQ(b.double_attributes.at("roof_planes"), 2);
  EXPECT_NEAR(b.double_attributes.at("reliability"), 5, 1e-9);
  EXPECT_NEAR(b.double_attributes.at("footprint_m2"),
              b.parts[0].double_attributes.at("footprint_m2") +
                  b.parts[1].double_attributes.at("footprint_m2"),
              1e-9);
  std::set<std::string> roofed(r.plane_building.begin(), r.plane_building.begin() + 2);
  EXPECT_EQ(roofed, (std::set<std::string>{"rs_b0001_p1", "rs_b0001_p2"}));
  // A footprint roofed by one solid stays a plain building.
  const Building& gable = r.model.buildings[1];
  EXPECT_EQ(gable.id, "rs_b0002");
  EXPECT_TRUE(gable.parts.empty());
  EXPECT_EQ(gable.roof_type, roof_type::kGabled);
  EXPECT_EQ(r.plane_building[2], "rs_b0002");

  AssemblyOptions apart;
  apart.join_parts_per_footprint = false;
  const AssemblyResult s = AssembleBuildings(with_gable, Flat(0), apart, fps);
  ASSERT_EQ(s.model.buildings.size(), 3u);
  for (const Building& x : s.model.buildings) EXPECT_TRUE(x.parts.empty());

  // A multipolygon footprint (the wings as two polygons of one id, as
  // cadastres and the Berlin ground surfaces have them) is one building too,
  // and a piece left bare is no footprint "without a building".
  const std::vector<Footprint> pieces = {Fp("DEBE7", {{0, 0}, {6, 0}, {6, 6}, {0, 6}}),
                                         Fp("DEBE7", {{6, 0}, {12, 0}, {12, 6}, {6, 6}}),
                                         Fp("DEBE7", {{40, 0}, {44, 0}, {44, 3}, {40, 3}})};
  const AssemblyResult m = AssembleBuildings(planes, Flat(0), {}, pieces);
  ASSERT_EQ(m.model.buildings.size(), 1u);
  EXPECT_EQ(m.model.buildings[0].parts.size(), 2u);
  EXPECT_EQ(m.model.buildings[0].string_attributes.at("footprint_id"), "DEBE7");
  EXPECT_FALSE(Mentions(m.rejected, "footprint DEBE7", "")) << m.rejected.size();
  ExpectAllValid(m);
  // Bare, it gets one reason, not one per piece.
  const AssemblyResult bare = AssembleBuildings({}, Flat(0), {}, pieces);
  EXPECT_EQ(std::count_if(bare.rejected.begin(), bare.rejected.end(),
                          [](const std::string& x) { return x.find("DEBE7") != x.npos; }),
            1);
}

TEST(AssembleBuildingsFootprints, AFootprintLetsAGardenShedIn) {
  // A 3 x 2.5 m flat shed roof 2.1 m above the ground, its longest line 2.5 m.
  std::vector<RoofPlaneHypothesis> planes = {
      Hyp({0, 0, 1, -2.1}, {{0.2, 0.2}, {2.8, 0.2}, {2.8, 2.3}, {0.2, 2.3}})};
  planes[0].longest_line_m = 2.5;
  const AssemblyResult without = AssembleBuildings(planes, Flat(0));
  EXPECT_TRUE(without.model.buildings.empty());
  const AssemblyResult with =
      AssembleBuildings(planes, Flat(0), {}, {Fp("shed", {{0, 0}, {3, 0}, {3, 2.5}, {0, 2.5}})});
  ASSERT_EQ(with.model.buildings.size(), 1u);
  EXPECT_NEAR(with.model.buildings[0].measured_height, 2.1, 1e-9);
  ExpectAllValid(with);
  // Still not a car or a hedge: 1.2 m is below footprint_min_height_m.
  planes[0].plane = {0, 0, 1, -1.2};
  EXPECT_TRUE(
      AssembleBuildings(planes, Flat(0), {}, {Fp("shed", {{0, 0}, {3, 0}, {3, 2.5}, {0, 2.5}})})
          .model.buildings.empty());
}

TEST(FootprintCompletion, TerraceNeighboursShareTheirRoofPlanes) {
  // A row of three 6 x 10 m houses under one gable roof (ridge along x at
  // y = 5); the sweep found the front slope over the first house only and
  // both slopes over the third.
  const double ridge_z = 6 + 5 * std::tan(35 * M_PI / 180);
  const Eigen::Vector4d front = SlopedPlane({0, 5, ridge_z}, 35, -90);
  const Eigen::Vector4d back = SlopedPlane({0, 5, ridge_z}, 35, 90);
  std::vector<RoofPlaneHypothesis> planes = {Hyp(front, {{0, 0}, {6, 0}, {6, 5}, {0, 5}}),
                                             Hyp(front, {{12, 0}, {18, 0}, {18, 5}, {12, 5}}),
                                             Hyp(back, {{12, 5}, {18, 5}, {18, 10}, {12, 10}})};
  planes[0].id = "a";
  planes[1].id = "b";
  planes[2].id = "c";
  const std::vector<Footprint> row = {Fp("h1", {{0, 0}, {6, 0}, {6, 10}, {0, 10}}),
                                      Fp("h2", {{6, 0}, {12, 0}, {12, 10}, {6, 10}}),
                                      Fp("h3", {{12, 0}, {18, 0}, {18, 10}, {12, 10}}),
                                      Fp("far", {{40, 0}, {46, 0}, {46, 10}, {40, 10}})};
  const std::vector<RoofPlaneHypothesis> proposed = PlanesFromNeighbourFootprints(planes, row);
  // Only h2 gets proposals: the front slope (once, though both neighbours
  // have it) and the back slope; h1 and h3 have no neighbour with planes
  // they lack, the far house has no neighbour.
  int front_h2 = 0, back_h2 = 0;
  for (const RoofPlaneHypothesis& q : proposed) {
    ASSERT_NE(q.id.find("extended over footprint h2"), std::string::npos) << q.id;
    const bool is_front = q.plane.head<3>().dot(front.head<3>()) > 0.999;
    (is_front ? front_h2 : back_h2) += 1;
    // The patch is the band of the slope over h2: y within the source band.
    for (const auto& v : q.patch) {
      EXPECT_GE(v.x(), 6 - 1e-9);
      EXPECT_LE(v.x(), 12 + 1e-9);
      if (is_front) {
        EXPECT_LE(v.y(), 5 + 1e-9);
      } else {
        EXPECT_GE(v.y(), 5 - 1e-9);
      }
    }
  }
  EXPECT_EQ(front_h2, 1);
  EXPECT_EQ(back_h2, 1);
  // Once h2 has its planes, h1 is offered the back slope, named after the
  // plane found over h3; h3 has both already.
  std::vector<RoofPlaneHypothesis> more = planes;
  for (const RoofPlaneHypothesis& q : proposed) more.push_back(q);
  const std::vector<RoofPlaneHypothesis> next = PlanesFromNeighbourFootprints(more, row);
  ASSERT_EQ(next.size(), 1u);
  EXPECT_EQ(next[0].id, "c extended over footprint h1");
  EXPECT_GT(next[0].plane.head<3>().dot(back.head<3>()), 0.999);
}

TEST(FootprintCompletion, BareFootprintsGetAFlatRoofHypothesis) {
  // A house covered by its gable, and a garage (L-shaped shed) that only a
  // sliver of a neighbouring plane reaches.
  const std::vector<Footprint> fps = {
      Fp("house", {{0, 0}, {10, 0}, {10, 8}, {0, 8}}),
      Fp("garage", {{12, 0}, {15, 0}, {15, 3}, {13.5, 3}, {13.5, 5}, {12, 5}})};
  std::vector<RoofPlaneHypothesis> planes = Gable();
  planes.push_back(Hyp(Eigen::Vector4d(0, 0, 1, -3), {{9, 0}, {12.5, 0}, {12.5, 8}, {9, 8}}));
  EXPECT_EQ(BareFootprints(planes, fps), std::vector<int>({1}));
  EXPECT_EQ(BareFootprints({}, fps), std::vector<int>({0, 1}));
  // More of the garage covered (0.5 x 5 of its 12 m2 is less than a
  // quarter; 1.5 x 5 is more).
  planes.back().patch = ConvexHull({{9, 0}, {13.5, 0}, {13.5, 8}, {9, 8}});
  EXPECT_TRUE(BareFootprints(planes, fps).empty());

  const RoofPlaneHypothesis flat = RoofModelFaceAt(fps[1], RoofModelsOver(fps[1]).front(), 0, 2.4);
  EXPECT_EQ(flat.plane, Eigen::Vector4d(0, 0, 1, -2.4));
  EXPECT_TRUE(flat.derived);
  EXPECT_NEAR(std::abs(SignedArea(flat.patch)), 15 - 0.5 * 1.5 * 2, 1e-9);  // the hull
  EXPECT_NEAR(flat.longest_line_m, 5, 1e-9);
  EXPECT_NE(flat.id.find("garage"), std::string::npos);
  // Over its footprint the flat roof makes a building on its own.
  const AssemblyResult r = AssembleBuildings({flat}, Flat(0), AssemblyOptions(), {fps[1]});
  ASSERT_EQ(r.model.buildings.size(), 1u);
  EXPECT_NEAR(r.model.buildings[0].measured_height, 2.4, 1e-9);
  ExpectAllValid(r);
}

TEST(Polygon2, IntersectNonConvex) {
  const Ring2 l = {{0, 0}, {12, 0}, {12, 5}, {5, 5}, {5, 12}, {0, 12}};
  EXPECT_FALSE(IsConvexRing(l));
  EXPECT_TRUE(IsConvexRing({{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}}));
  const Ring2 sq = {{4, 4}, {13, 4}, {13, 13}, {4, 13}};
  EXPECT_EQ(IntersectPolygons(sq, l).size(), 1u);
  EXPECT_NEAR(IntersectionArea(sq, l), 8 * 1 + 1 * 7, 1e-9);
  // A triangle across the two arms, clear of the corner: two pieces.
  const Ring2 tri = {{11, 4}, {13, 13}, {4, 11}};
  const std::vector<Ring2> pieces = IntersectPolygons(tri, l);
  ASSERT_EQ(pieces.size(), 2u);
  EXPECT_GT(SignedArea(pieces[0]), 0);
  EXPECT_NEAR(SignedArea(pieces[0]) + SignedArea(pieces[1]), IntersectionArea(tri, l), 1e-12);
  // Clockwise input is accepted.
  Ring2 cw(l.rbegin(), l.rend());
  EXPECT_NEAR(IntersectionArea(sq, cw), 15, 1e-9);
  EXPECT_FALSE(RingSelfIntersects(l));
  EXPECT_TRUE(RingSelfIntersects({{0, 0}, {2, 2}, {2, 0}, {0, 2}}));
}

TEST(Polygon2, DifferenceWithoutSlivers) {
  // b covers a's east half, its south edge 3 cm above a's: the difference
  // keeps a strip 3 cm wide along a's south edge under b.
  const Ring2 a = {{0, 0}, {10, 0}, {10, 6}, {0, 6}};
  const Ring2 b = {{5, 0.03}, {12, 0.03}, {12, 7}, {5, 7}};
  auto max_x = [](const std::vector<Ring2>& pieces) {
    double m = -1e9;
    for (const Ring2& r : pieces)
      for (const auto& q : r) m = std::max(m, q.x());
    return m;
  };
  const std::vector<Ring2> raw = DifferencePolygons(a, b);
  ASSERT_EQ(raw.size(), 1u);
  // Boost's overlay rounds to a tenth of a mm2.
  EXPECT_NEAR(SignedArea(raw[0]), 30 + 5 * 0.03, 1e-4);
  EXPECT_NEAR(max_x(raw), 10, 1e-6);
  const std::vector<Ring2> opened = DifferencePolygons(a, b, 0.3);
  ASSERT_EQ(opened.size(), 1u);
  EXPECT_NEAR(SignedArea(opened[0]), 30, 1e-4);
  EXPECT_NEAR(max_x(opened), 5, 1e-6);
  // No overlap: a itself (counter-clockwise); a inside b: nothing.
  EXPECT_NEAR(
      SignedArea(DifferencePolygons(Ring2(a.rbegin(), a.rend()), {{20, 0}, {21, 0}, {21, 1}})[0]),
      60, 1e-9);
  bool holed = true;
  EXPECT_TRUE(DifferencePolygons(a, {{-1, -1}, {11, -1}, {11, 7}, {-1, 7}}, 0, &holed).empty());
  EXPECT_FALSE(holed);
  // b inside a: a with a hole, which no piece is.
  EXPECT_TRUE(DifferencePolygons(a, {{2, 2}, {4, 2}, {4, 4}, {2, 4}}, 0, &holed).empty());
  EXPECT_TRUE(holed);
}

}  // namespace

// Two terraced houses of 6 m under one 12 x 8 m gable: lines down both
// faces at x = 6 (a party wall seen as a change of roof) cut them apart; a
// line down one face only (the facing face spans both units, as real city
// models have it), a verge at the face's edge, a dormer's 2 m side and a
// line across the slope do not.
TEST(AssembleBuildings, PartyLineDownTheSlopeCutsTerracedHouses) {
  using Lines = std::vector<std::array<Eigen::Vector2d, 2>>;
  auto row = [](Lines front_lines, Lines back_lines) {
    const double ridge_z = 6 + 4 * std::tan(35 * M_PI / 180);
    std::vector<RoofPlaneHypothesis> p = {
        Hyp(SlopedPlane({0, 4, ridge_z}, 35, -90), {{0, 0}, {12, 0}, {12, 4}, {0, 4}}),
        Hyp(SlopedPlane({0, 4, ridge_z}, 35, 90), {{0, 4}, {12, 4}, {12, 8}, {0, 8}})};
    p[0].lines_xy = std::move(front_lines);
    p[1].lines_xy = std::move(back_lines);
    p[0].id = "front", p[1].id = "back";
    return p;
  };
  const Lines front = {{{{6, 0.2}, {6, 3.8}}}}, back = {{{{6.2, 4.5}, {6.2, 7.5}}}};
  const AssemblyResult cut = AssembleBuildings(row(front, back), Flat(0));
  ASSERT_EQ(cut.model.buildings.size(), 2u);
  EXPECT_EQ(cut.party_cuts, 1);
  ExpectAllValid(cut);
  std::set<double> groups;
  for (const Building& b : cut.model.buildings) {
    EXPECT_EQ(b.roof_type, roof_type::kGabled) << b.id;
    double xmin = 1e9, xmax = -1e9;
    for (const Surface& s : b.surfaces)
      for (const Polygon3& poly : s.polygons)
        for (const auto& v : poly.exterior)
          xmin = std::min(xmin, v.x()), xmax = std::max(xmax, v.x());
    // The cut runs through one of the two lines.
    EXPECT_NEAR(xmax - xmin, 6.1, 0.1 + 1e-6) << b.id;
    groups.insert(b.double_attributes.at("building_group"));
  }
  EXPECT_EQ(groups.size(), 2u);
  // Both input planes roof a building: counted once each.
  EXPECT_EQ(cut.planes_used, 2);
  for (const Lines& lines : {Lines{{{{0.1, 0.2}, {0.1, 3.8}}}},  // verge
                             Lines{{{{6, 1.0}, {6, 3.0}}}},      // dormer side
                             Lines{{{{1, 2}, {11, 2}}}}}) {      // across
    const AssemblyResult whole = AssembleBuildings(row(lines, {}), Flat(0));
    EXPECT_EQ(whole.model.buildings.size(), 1u);
    EXPECT_EQ(whole.party_cuts, 0);
  }
  EXPECT_EQ(AssembleBuildings(row(front, {}), Flat(0)).model.buildings.size(), 1u);
  AssemblyOptions off;
  off.split_at_party_lines = false;
  EXPECT_EQ(AssembleBuildings(row(front, back), Flat(0), off).model.buildings.size(), 1u);
}

// The same row roofed apart: a colour break down both faces at x = 6 cuts
// it as lines there do, and a break and a line confirm each other. A break
// on one face only does not cut, nor does a break on a face that no other
// face confirms: alone it may be the end of a patch that reaches past its
// roof.
TEST(AssembleBuildings, ColourBreaksDownBothFacesCutTerracedHouses) {
  using Lines = std::vector<std::array<Eigen::Vector2d, 2>>;
  const double ridge_z = 6 + 4 * std::tan(35 * M_PI / 180);
  auto row = [&](Lines front_breaks, Lines back_breaks, Lines back_lines = {}) {
    std::vector<RoofPlaneHypothesis> p = {
        Hyp(SlopedPlane({0, 4, ridge_z}, 35, -90), {{0, 0}, {12, 0}, {12, 4}, {0, 4}}),
        Hyp(SlopedPlane({0, 4, ridge_z}, 35, 90), {{0, 4}, {12, 4}, {12, 8}, {0, 8}})};
    p[0].colour_breaks = std::move(front_breaks);
    p[1].colour_breaks = std::move(back_breaks);
    p[1].lines_xy = std::move(back_lines);
    return p;
  };
  const Lines front = {{{{6, 0.3}, {6, 3.7}}}}, back = {{{{6.1, 4.3}, {6.1, 7.7}}}};
  const AssemblyResult cut = AssembleBuildings(row(front, back), Flat(0));
  EXPECT_EQ(cut.model.buildings.size(), 2u);
  EXPECT_EQ(cut.party_cuts, 1);
  ExpectAllValid(cut);
  EXPECT_EQ(AssembleBuildings(row(front, {}, back), Flat(0)).party_cuts, 1);
  EXPECT_EQ(AssembleBuildings(row(front, {}), Flat(0)).model.buildings.size(), 1u);
  // A shed roof: no other face to confirm the break.
  std::vector<RoofPlaneHypothesis> shed = {
      Hyp(SlopedPlane({0, 0, 8}, 15, -90), {{0, 0}, {12, 0}, {12, 6}, {0, 6}})};
  shed[0].colour_breaks = {{{{6, 0.3}, {6, 5.7}}}};
  EXPECT_EQ(AssembleBuildings(shed, Flat(0)).party_cuts, 0);
}

// A row of one eave height: a shed roof rising 15 deg beside a 35 deg gable.
// The shed's plane runs below the gable's faces, so the lower envelope of
// the row hides the gable; the two faces must still end in one gabled
// building.
TEST(AssembleBuildings, AGableBesideAShedRoofStaysOneGabledBuilding) {
  const double ridge_z = 6 + 5 * std::tan(35 * M_PI / 180);
  const std::vector<RoofPlaneHypothesis> row = {
      Hyp(SlopedPlane({0, 0, 6}, 15, -90), {{0, 0}, {6, 0}, {6, 10}, {0, 10}}),
      Hyp(SlopedPlane({6, 5, ridge_z}, 35, -90), {{6, 0}, {16, 0}, {16, 5}, {6, 5}}),
      Hyp(SlopedPlane({6, 5, ridge_z}, 35, 90), {{6, 5}, {16, 5}, {16, 10}, {6, 10}})};
  const AssemblyResult r = AssembleBuildings(row, Flat(0));
  ASSERT_EQ(r.model.buildings.size(), 2u);
  ExpectAllValid(r);
  const Building& shed = r.model.buildings[0];
  const Building& gable = r.model.buildings[1];
  EXPECT_EQ(shed.roof_type, roof_type::kMonopitch);
  EXPECT_EQ(gable.roof_type, roof_type::kGabled);
  ASSERT_EQ(gable.parts.size(), 2u);
  for (const Building& part : gable.parts) EXPECT_EQ(part.roof_type, roof_type::kMonopitch);
  EXPECT_NEAR(gable.measured_height, ridge_z, 1e-6);
  // Without the join the envelope's split leaves three shed roofs.
  AssemblyOptions apart;
  apart.join_gable_halves = false;
  const AssemblyResult a = AssembleBuildings(row, Flat(0), apart);
  ASSERT_EQ(a.model.buildings.size(), 3u);
  for (const Building& b : a.model.buildings) EXPECT_EQ(b.roof_type, roof_type::kMonopitch);
}

}  // namespace roofsweep
