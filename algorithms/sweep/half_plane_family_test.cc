#include "algorithms/sweep/half_plane_family.h"

#include <gtest/gtest.h>

#include <cmath>

namespace roofsweep {
namespace {

constexpr double kDeg = M_PI / 180.0;

TEST(HalfPlaneFamily, HorizontalLineSidesAndAngles) {
  const Segment3 line{{-5, 0, 10}, {5, 0, 10}};
  const auto left = HalfPlaneFamily::Make(line, 1);
  const auto right = HalfPlaneFamily::Make(line, -1);
  ASSERT_TRUE(left && right);
  // Left of +x seen from above is +y.
  EXPECT_NEAR((left->Direction(0) - Eigen::Vector3d(0, 1, 0)).norm(), 0, 1e-12);
  EXPECT_NEAR((right->Direction(0) - Eigen::Vector3d(0, -1, 0)).norm(), 0, 1e-12);
  // theta < 0 falls away from the line (a ridge's faces).
  const Eigen::Vector3d w = left->Direction(-30 * kDeg);
  EXPECT_NEAR(w.y(), std::cos(30 * kDeg), 1e-12);
  EXPECT_NEAR(w.z(), -std::sin(30 * kDeg), 1e-12);
  EXPECT_NEAR((left->Normal(0) - Eigen::Vector3d::UnitZ()).norm(), 0, 1e-12);
}

TEST(HalfPlaneFamily, PlaneContainsLineAndAngleRoundTrips) {
  // An inclined (hip-like) line: the family is still defined.
  const Segment3 line{{1, 2, 8}, {6, 5, 11}};
  for (int side : {1, -1}) {
    const auto f = HalfPlaneFamily::Make(line, side);
    ASSERT_TRUE(f);
    for (double deg = -75; deg <= 75; deg += 7.5) {
      const Eigen::Vector4d p = f->Plane(deg * kDeg);
      EXPECT_NEAR(p.head<3>().norm(), 1.0, 1e-12);
      EXPECT_GE(p.z(), 0.0);
      EXPECT_NEAR(p.head<3>().dot(line.a) + p(3), 0, 1e-9);
      EXPECT_NEAR(p.head<3>().dot(line.b) + p(3), 0, 1e-9);
      // The half-plane leaves the line on its side.
      EXPECT_GT(f->Direction(deg * kDeg).dot(f->e()), 0);
      EXPECT_NEAR(f->AngleOfNormal(p.head<3>()), deg * kDeg, 1e-9);
    }
  }
}

TEST(HalfPlaneFamily, VerticalOrDegenerateLinesHaveNoFamily) {
  EXPECT_FALSE(HalfPlaneFamily::Make(Segment3{{0, 0, 0}, {0, 0, 5}}, 1));
  EXPECT_FALSE(HalfPlaneFamily::Make(Segment3{{0, 0, 0}, {0.1, 0, 5}}, 1));
  EXPECT_FALSE(HalfPlaneFamily::Make(Segment3{{1, 1, 1}, {1, 1, 1}}, 1));
  EXPECT_FALSE(HalfPlaneFamily::Make(Segment3{{0, 0, 0}, {1, 0, 0}}, 0));
}

}  // namespace
}  // namespace roofsweep
