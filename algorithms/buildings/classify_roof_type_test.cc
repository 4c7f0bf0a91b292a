#include "algorithms/buildings/classify_roof_type.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace roofsweep {
namespace {

using V3 = Eigen::Vector3d;
constexpr double kDeg = M_PI / 180.0;

Polygon3 Face(std::vector<V3> ring) {
  Polygon3 p;
  p.exterior = std::move(ring);
  return p;
}

// A pyramid roof over a 10 x 10 m square whose faces came out of the
// envelope with extra vertices: the apex split by a few centimetres and a
// vertex halfway along an eave. Still a pavilion; with a 2 m ridge, hipped.
TEST(ClassifyRoofType, TrianglesWithSnappingVerticesAreTriangles) {
  auto roof = [](double half_ridge, double split) {
    const Eigen::Vector3d a(0, 0, 5), b(10, 0, 5), c(10, 10, 5), d(0, 10, 5);
    const Eigen::Vector3d top0(5 - half_ridge, 5, 9), top1(5 + half_ridge, 5, 9);
    const Eigen::Vector3d nudge(split, 0, 0);
    auto face = Face;
    return std::vector<Polygon3>{
        face({a, Eigen::Vector3d(5, 0, 5), b, top1 + nudge, top1, top0}),  // south
        face({b, c, top1}),                                                // east
        face({c, d, top0, top0 - nudge, top1}),                            // north
        face({d, a, top0})};                                               // west
  };
  EXPECT_EQ(ClassifyRoofType(roof(0, 0.03)), roof_type::kPavilion);
  EXPECT_EQ(ClassifyRoofType(roof(1, 0.03)), roof_type::kHipped);
}

// A half-hipped roof over a 12 x 8 m house, eaves at 5 m, ridge at 9 m (as
// the simulator builds it): the verges rise to `fraction` of the roof's
// height, and a hipped triangle takes the gable's top from there. With
// fraction 0 the end faces reach the eaves: a hipped roof.
std::vector<Polygon3> HalfHipRoof(double fraction, bool both_ends = true) {
  const double L = 12, W = 8, he = 5, hr = 9;
  const double hm = he + fraction * (hr - he), ym = -W / 2 + fraction * W / 2;
  const double d = std::min(-ym, 0.3 * L);
  const V3 f0(-L / 2, -W / 2, he), f1(L / 2, -W / 2, he), f2(L / 2, W / 2, he),
      f3(-L / 2, W / 2, he);
  const V3 A(L / 2, ym, hm), A2(L / 2, -ym, hm), B(-L / 2, ym, hm), B2(-L / 2, -ym, hm);
  const V3 R0(-L / 2 + d, 0, hr), R1(L / 2 - d, 0, hr);
  std::vector<Polygon3> faces = {Face({f0, f1, A, R1, R0, B}), Face({f2, f3, B2, R0, R1, A2}),
                                 Face({A, A2, R1})};
  if (both_ends) faces.push_back(Face({B2, B, R0}));
  return faces;
}

TEST(ClassifyRoofType, HalfHipEndsStopAboveTheEaves) {
  // Small ends (3 % of the roof each), found or not, and large ones.
  EXPECT_EQ(ClassifyRoofType(HalfHipRoof(0.6)), roof_type::kHalfHipped);
  EXPECT_EQ(ClassifyRoofType(HalfHipRoof(0.6, false)), roof_type::kHalfHipped);
  EXPECT_EQ(ClassifyRoofType(HalfHipRoof(0.3)), roof_type::kHalfHipped);
  // Ends reaching the eaves, or all but (10 % of the roof's height).
  EXPECT_EQ(ClassifyRoofType(HalfHipRoof(0.0)), roof_type::kHipped);
  EXPECT_EQ(ClassifyRoofType(HalfHipRoof(0.1)), roof_type::kHipped);
  // Without its ends it is a gable.
  std::vector<Polygon3> gable = HalfHipRoof(0.6);
  gable.resize(2);
  EXPECT_EQ(ClassifyRoofType(gable), roof_type::kGabled);
}

// A gable with a small face across it that does not reach the ridge (a
// dormer's cheek, a sliver of the envelope) stays a gable.
TEST(ClassifyRoofType, AFaceAcrossAGableBelowItsRidgeIsNoHalfHip) {
  std::vector<Polygon3> faces = HalfHipRoof(0.6);
  faces.resize(2);
  // A 2 m2 triangle facing east at 6.5-7.5 m on the south face.
  faces.push_back(Face({V3(0, -2, 6.5), V3(0, 0, 6.5), V3(-1, -1, 7.5)}));
  EXPECT_EQ(ClassifyRoofType(faces), roof_type::kGabled);
}

// Steep faces (65 deg) from the eaves at 5 m to a break 1.2 m in, under a
// hipped top at 15 deg: the French mansard. With `hipped_top` false, a
// gambrel: steep and shallow faces on the long sides only, gable walls.
std::vector<Polygon3> MansardRoof(bool hipped_top) {
  const double L = 12, W = 10, a = 1.2, he = 5;
  const double hb = he + std::tan(65 * kDeg) * a;
  const double x = L / 2, y = W / 2;
  std::vector<Polygon3> faces;
  if (hipped_top) {
    const double xi = x - a, yi = y - a, hr = hb + std::tan(15 * kDeg) * yi;
    const V3 r0(-xi + yi, 0, hr), r1(xi - yi, 0, hr);
    const V3 i0(-xi, -yi, hb), i1(xi, -yi, hb), i2(xi, yi, hb), i3(-xi, yi, hb);
    faces = {Face({V3(-x, -y, he), V3(x, -y, he), i1, i0}),
             Face({V3(x, -y, he), V3(x, y, he), i2, i1}),
             Face({V3(x, y, he), V3(-x, y, he), i3, i2}),
             Face({V3(-x, y, he), V3(-x, -y, he), i0, i3}),
             Face({i0, i1, r1, r0}),
             Face({i1, i2, r1}),
             Face({i2, i3, r0, r1}),
             Face({i3, i0, r0})};
  } else {
    const double yi = y - a, hr = hb + std::tan(15 * kDeg) * yi;
    faces = {Face({V3(-x, -y, he), V3(x, -y, he), V3(x, -yi, hb), V3(-x, -yi, hb)}),
             Face({V3(x, y, he), V3(-x, y, he), V3(-x, yi, hb), V3(x, yi, hb)}),
             Face({V3(-x, -yi, hb), V3(x, -yi, hb), V3(x, 0, hr), V3(-x, 0, hr)}),
             Face({V3(x, yi, hb), V3(-x, yi, hb), V3(-x, 0, hr), V3(x, 0, hr)})};
  }
  return faces;
}

TEST(ClassifyRoofType, ASteepFaceUnderAShallowOneOnOppositeSidesIsAMansard) {
  EXPECT_EQ(ClassifyRoofType(MansardRoof(true)), roof_type::kMansard);
  EXPECT_EQ(ClassifyRoofType(MansardRoof(false)), roof_type::kMansard);
  // The break on one side only is no mansard.
  std::vector<Polygon3> one_side = MansardRoof(false);
  one_side.erase(one_side.begin() + 1);
  EXPECT_NE(ClassifyRoofType(one_side), roof_type::kMansard);
}

// Steep faces on all four sides under a flat top, built as two faces
// falling 1 deg east and west: their azimuths are noise, and they make no
// breaks for the east and west faces under them. No mansard.
TEST(ClassifyRoofType, AFlatTopOverSteepFacesMakesNoBreak) {
  std::vector<Polygon3> faces = MansardRoof(true);
  faces.resize(4);
  const double x = 6 - 1.2, y = 5 - 1.2, hb = 5 + std::tan(65 * kDeg) * 1.2;
  const double mid = hb + std::tan(1 * kDeg) * x;
  faces.push_back(Face({V3(0, -y, mid), V3(x, -y, hb), V3(x, y, hb), V3(0, y, mid)}));
  faces.push_back(Face({V3(-x, -y, hb), V3(0, -y, mid), V3(0, y, mid), V3(-x, y, hb)}));
  EXPECT_NE(ClassifyRoofType(faces), roof_type::kMansard);
}

// A steep gable (50 deg, ridge at 9.8 m) beside a taller house with a
// shallow gable (15 deg, eaves at 11 m) facing the same ways: steep under
// shallow on both sides, but the faces share no edge.
TEST(ClassifyRoofType, AShallowRoofOfATallerHouseBesideASteepOneIsNoMansard) {
  const double low_ridge = 5 + std::tan(50 * kDeg) * 4, high_ridge = 11 + std::tan(15 * kDeg) * 4;
  const std::vector<Polygon3> faces = {
      Face({V3(0, 0, 5), V3(10, 0, 5), V3(10, 4, low_ridge), V3(0, 4, low_ridge)}),
      Face({V3(10, 8, 5), V3(0, 8, 5), V3(0, 4, low_ridge), V3(10, 4, low_ridge)}),
      Face({V3(10, 0, 11), V3(20, 0, 11), V3(20, 4, high_ridge), V3(10, 4, high_ridge)}),
      Face({V3(20, 8, 11), V3(10, 8, 11), V3(10, 4, high_ridge), V3(20, 4, high_ridge)})};
  EXPECT_EQ(ClassifyRoofType(faces), roof_type::kCombination);
}

}  // namespace
}  // namespace roofsweep
