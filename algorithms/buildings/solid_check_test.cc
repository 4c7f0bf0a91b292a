#include "algorithms/buildings/solid_check.h"

#include <gtest/gtest.h>

namespace roofsweep {
namespace {

using V = Eigen::Vector3d;

Surface Face(SurfaceType t, std::vector<V> ring) {
  Surface s;
  s.type = t;
  s.polygons.push_back(Polygon3{std::move(ring), {}});
  return s;
}

// Unit-ish box 4 x 3 x 2 with outward rings.
Building Box() {
  const V a(0, 0, 0), b(4, 0, 0), c(4, 3, 0), d(0, 3, 0);
  const V A(0, 0, 2), B(4, 0, 2), C(4, 3, 2), D(0, 3, 2);
  Building bl;
  bl.id = "box";
  bl.surfaces = {Face(SurfaceType::kGround, {a, d, c, b}), Face(SurfaceType::kWall, {a, b, B, A}),
                 Face(SurfaceType::kWall, {b, c, C, B}),   Face(SurfaceType::kWall, {c, d, D, C}),
                 Face(SurfaceType::kWall, {d, a, A, D}),   Face(SurfaceType::kRoof, {A, B, C, D})};
  return bl;
}

bool Has(const SolidCheckResult& r, SolidError e) {
  for (const auto& v : r.violations)
    if (v.code == e) return true;
  return false;
}

TEST(SolidCheck, CorrectBoxIsValidWithItsVolume) {
  const auto r = CheckBuildingSolid(Box());
  EXPECT_TRUE(r.Valid()) << r.Summary();
  EXPECT_EQ(r.Summary(), "valid");
  EXPECT_NEAR(r.signed_volume, 24.0, 1e-9);
}

TEST(SolidCheck, OneFlippedWallIsBlamedAlone) {
  Building b = Box();
  auto& ring = b.surfaces[2].polygons[0].exterior;
  std::reverse(ring.begin(), ring.end());
  const auto r = CheckBuildingSolid(b);
  ASSERT_FALSE(r.Valid());
  ASSERT_EQ(r.violations.size(), 1u) << r.Summary();
  EXPECT_EQ(r.violations[0].code, SolidError::kPolygonWrongOrientation);
  EXPECT_EQ(r.violations[0].surface, 2);
}

TEST(SolidCheck, AllFlippedIsNegativeVolume) {
  Building b = Box();
  for (auto& s : b.surfaces)
    std::reverse(s.polygons[0].exterior.begin(), s.polygons[0].exterior.end());
  const auto r = CheckBuildingSolid(b);
  EXPECT_TRUE(Has(r, SolidError::kAllPolygonsWronglyOriented)) << r.Summary();
  EXPECT_NEAR(r.signed_volume, -24.0, 1e-9);
}

TEST(SolidCheck, MissingRoofIsOpen) {
  Building b = Box();
  b.surfaces.pop_back();
  const auto r = CheckBuildingSolid(b);
  EXPECT_TRUE(Has(r, SolidError::kShellNotClosed)) << r.Summary();
  EXPECT_FALSE(Has(r, SolidError::kAllPolygonsWronglyOriented));
}

TEST(SolidCheck, GapBelowWeldToleranceIsClosedAboveIsNot) {
  Building b = Box();
  b.surfaces[5].polygons[0].exterior[0] += V(0.0004, 0, 0);  // 0.4 mm: welded
  EXPECT_TRUE(CheckBuildingSolid(b).Valid()) << CheckBuildingSolid(b).Summary();
  b.surfaces[5].polygons[0].exterior[0] += V(0.005, 0, 0);  // 5.4 mm: a gap
  EXPECT_TRUE(Has(CheckBuildingSolid(b), SolidError::kShellNotClosed));
}

TEST(SolidCheck, NonPlanarRoofFailsAtTolerance) {
  Building b = Box();
  // Lift one roof corner (and the wall tops meeting it) by 5 cm: still closed,
  // but the roof and two walls are no longer planar within 1 cm.
  const V corner(4, 3, 2), lifted(4, 3, 2.05);
  for (auto& s : b.surfaces)
    for (auto& v : s.polygons[0].exterior)
      if ((v - corner).norm() < 1e-9) v = lifted;
  const auto r = CheckBuildingSolid(b);
  EXPECT_TRUE(Has(r, SolidError::kNonPlanar)) << r.Summary();
  EXPECT_FALSE(Has(r, SolidError::kShellNotClosed));
  SolidCheckOptions loose;
  loose.planarity_tolerance = 0.02;  // deviation is 0.0125 m for this quad
  EXPECT_TRUE(CheckBuildingSolid(b, loose).Valid()) << CheckBuildingSolid(b, loose).Summary();
}

TEST(SolidCheck, BowtieRingSelfIntersects) {
  Building b;
  b.surfaces.push_back(Face(SurfaceType::kRoof, {V(0, 0, 0), V(2, 2, 0), V(2, 0, 0), V(0, 2, 0)}));
  EXPECT_TRUE(Has(CheckBuildingSolid(b), SolidError::kRingSelfIntersection));
}

TEST(SolidCheck, DegenerateRingsAndEmptyBuilding) {
  Building b;
  b.surfaces.push_back(Face(SurfaceType::kRoof, {V(0, 0, 0), V(1, 0, 0), V(1, 0, 0)}));
  const auto r = CheckBuildingSolid(b);
  EXPECT_TRUE(Has(r, SolidError::kTooFewPoints));
  EXPECT_TRUE(Has(r, SolidError::kConsecutivePointsSame));
  EXPECT_TRUE(Has(CheckBuildingSolid(Building{}), SolidError::kEmpty));
}

TEST(SolidCheck, SummaryListsCodesWithCounts) {
  Building b = Box();
  b.surfaces.pop_back();
  const std::string s = CheckBuildingSolid(b).Summary();
  EXPECT_NE(s.find("302 SHELL_NOT_CLOSED x4"), std::string::npos) << s;
}

}  // namespace
}  // namespace roofsweep
