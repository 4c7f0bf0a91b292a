#include "algorithms/sweep/merge_coplanar_neighbours.h"

#include <gtest/gtest.h>

#include <cmath>

#include "algorithms/buildings/convex_polygon2.h"
#include "algorithms/buildings/test_planes.h"

namespace roofsweep {
namespace {

RoofPlaneHypothesis Hyp(const Eigen::Vector4d& plane, Ring2 patch, const std::string& id,
                        double score = 10) {
  RoofPlaneHypothesis h;
  h.plane = plane;
  h.patch = ConvexHull(std::move(patch));
  h.id = id;
  h.score = score;
  h.lines = 2;
  return h;
}

double AngleDeg(const Eigen::Vector4d& a, const Eigen::Vector4d& b) {
  return std::acos(std::min(1.0, a.head<3>().dot(b.head<3>()))) * 180 / M_PI;
}

TEST(NearCoplanarMerges, OneFaceFittedTwiceBecomesOnePlane) {
  // The south face of a 10 x 8 m gable (ridge at y = 4, 30 deg), fitted as
  // two planes 30 +- 2 deg through the middle of the face: they meet there
  // at the same height and creased at x = 5.
  const Eigen::Vector3d mid(5, 2, 6 + 2 * std::tan(30 * M_PI / 180));
  const std::vector<RoofPlaneHypothesis> planes = {
      Hyp(SlopedPlane(mid, 28, -90), {{0, 0}, {5, 0}, {5, 4}, {0, 4}}, "west"),
      Hyp(SlopedPlane(mid, 32, -90), {{5.2, 0}, {10, 0}, {10, 4}, {5.2, 4}}, "east", 12)};
  const std::vector<PlaneMerge> m = NearCoplanarMerges(planes);
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].a, 0);
  EXPECT_EQ(m[0].b, 1);
  EXPECT_FALSE(m[0].concave);  // side by side on one face: no crease to check
  const RoofPlaneHypothesis& h = m[0].merged;
  EXPECT_EQ(h.lines, 4);
  EXPECT_NE(h.id.find("west merged with east"), std::string::npos) << h.id;
  EXPECT_LT(AngleDeg(h.plane, SlopedPlane(mid, 30, -90)), 0.3);
  EXPECT_NEAR(SignedArea(h.patch), 40, 1e-9);
}

TEST(NearCoplanarMerges, GableFacesAndStepsStayApart) {
  const double ridge_z = 6 + 4 * std::tan(30 * M_PI / 180);
  const std::vector<RoofPlaneHypothesis> gable = {
      Hyp(SlopedPlane({0, 4, ridge_z}, 30, -90), {{0, 0}, {10, 0}, {10, 4}, {0, 4}}, "south"),
      Hyp(SlopedPlane({0, 4, ridge_z}, 30, 90), {{0, 4}, {10, 4}, {10, 8}, {0, 8}}, "north")};
  EXPECT_TRUE(NearCoplanarMerges(gable).empty());
  // Two flat roofs side by side, 0.5 m apart in height: a step between two
  // roofs.
  const std::vector<RoofPlaneHypothesis> step = {
      Hyp({0, 0, 1, -6}, {{0, 0}, {6, 0}, {6, 8}, {0, 8}}, "low"),
      Hyp({0, 0, 1, -6.5}, {{6.1, 0}, {12, 0}, {12, 8}, {6.1, 8}}, "high")};
  EXPECT_TRUE(NearCoplanarMerges(step).empty());
  // The same 0.2 m apart merges (within max_step_m).
  const std::vector<RoofPlaneHypothesis> near = {
      Hyp({0, 0, 1, -6}, {{0, 0}, {6, 0}, {6, 8}, {0, 8}}, "low"),
      Hyp({0, 0, 1, -6.2}, {{6.1, 0}, {12, 0}, {12, 8}, {6.1, 8}}, "high")};
  EXPECT_EQ(NearCoplanarMerges(near).size(), 1u);
  // Far apart in plan: no merge.
  const std::vector<RoofPlaneHypothesis> apart = {
      Hyp({0, 0, 1, -6}, {{0, 0}, {6, 0}, {6, 8}, {0, 8}}, "here"),
      Hyp({0, 0, 1, -6}, {{8, 0}, {12, 0}, {12, 8}, {8, 8}}, "there")};
  EXPECT_TRUE(NearCoplanarMerges(apart).empty());
}

TEST(NearCoplanarMerges, NeighboursAreEveryCandidateNotOnlyThePairsChosen) {
  // a, b and c in a row: the merges pair only b with c, but a is a
  // candidate of b; d is a step above c, e far away.
  const std::vector<RoofPlaneHypothesis> planes = {
      Hyp({0, 0, 1, -6}, {{0, 0}, {4, 0}, {4, 8}, {0, 8}}, "a", 1),
      Hyp({0, 0, 1, -6.05}, {{4.1, 0}, {8, 0}, {8, 8}, {4.1, 8}}, "b", 5),
      Hyp({0, 0, 1, -6.1}, {{8.1, 0}, {12, 0}, {12, 8}, {8.1, 8}}, "c", 5),
      Hyp({0, 0, 1, -7}, {{12.1, 0}, {16, 0}, {16, 8}, {12.1, 8}}, "d"),
      Hyp({0, 0, 1, -6}, {{30, 0}, {34, 0}, {34, 8}, {30, 8}}, "e")};
  EXPECT_EQ(NearCoplanarMerges(planes).size(), 1u);
  EXPECT_EQ(NearCoplanarNeighbours(planes), std::vector<char>({1, 1, 1, 0, 0}));
}

TEST(NearCoplanarMerges, EachPlaneJoinsOnePairTheStrongestFirst) {
  // Three flat pieces in a row: the stronger pair (b, c) is proposed, a is
  // left alone.
  const std::vector<RoofPlaneHypothesis> planes = {
      Hyp({0, 0, 1, -6}, {{0, 0}, {4, 0}, {4, 8}, {0, 8}}, "a", 1),
      Hyp({0, 0, 1, -6.05}, {{4.1, 0}, {8, 0}, {8, 8}, {4.1, 8}}, "b", 5),
      Hyp({0, 0, 1, -6.1}, {{8.1, 0}, {12, 0}, {12, 8}, {8.1, 8}}, "c", 5)};
  const std::vector<PlaneMerge> m = NearCoplanarMerges(planes);
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].a, 1);
  EXPECT_EQ(m[0].b, 2);
}

TEST(ConcaveCrease, OnlyAShallowerPlaneBelowASteeperOne) {
  // A 45 deg face falling north to an eave at y = 5, z = 10.
  const Eigen::Vector3d eave(0, 5, 10);
  const RoofPlaneHypothesis face =
      Hyp(SlopedPlane(eave, 45, 90), {{0, 0}, {10, 0}, {10, 5}, {0, 5}}, "face");
  // Beyond the eave, falling the same way at 40 deg (a false plane over the
  // lawn): concave, each is the lower one over the other's patch.
  const RoofPlaneHypothesis lawn =
      Hyp(SlopedPlane(eave, 40, 90), {{0, 5}, {10, 5}, {10, 14}, {0, 14}}, "lawn");
  EXPECT_TRUE(ConcaveCrease(face, lawn));
  EXPECT_TRUE(ConcaveCrease(lawn, face));
  // They meet without a step and 5 deg apart: a proposed merge, marked.
  const std::vector<PlaneMerge> m = NearCoplanarMerges({face, lawn});
  ASSERT_EQ(m.size(), 1u);
  EXPECT_TRUE(m[0].concave);
  // A mansard's steep lower face below the break (70 deg): convex.
  const RoofPlaneHypothesis mansard =
      Hyp(SlopedPlane(eave, 70, 90), {{0, 5}, {10, 5}, {10, 7}, {0, 7}}, "mansard");
  EXPECT_FALSE(ConcaveCrease(face, mansard));
  // The other face of a gable whose ridge is at y = 0: convex too.
  const Eigen::Vector3d ridge(0, 0, 15);
  const RoofPlaneHypothesis other =
      Hyp(SlopedPlane(ridge, 45, -90), {{0, -5}, {10, -5}, {10, 0}, {0, 0}}, "other");
  EXPECT_FALSE(ConcaveCrease(face, other));
  // A plane with no patch is never in a crease.
  RoofPlaneHypothesis empty = lawn;
  empty.patch.clear();
  EXPECT_FALSE(ConcaveCrease(face, empty));
}

}  // namespace
}  // namespace roofsweep
