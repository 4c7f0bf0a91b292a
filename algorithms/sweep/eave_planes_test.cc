#include "algorithms/sweep/eave_planes.h"

#include <gtest/gtest.h>

#include "algorithms/buildings/convex_polygon2.h"
#include "algorithms/buildings/test_planes.h"

namespace roofsweep {
namespace {

RoofPlaneHypothesis Hyp(const Eigen::Vector4d& plane, Ring2 patch, const std::string& id,
                        std::vector<std::array<Eigen::Vector2d, 2>> lines) {
  RoofPlaneHypothesis h;
  h.plane = plane;
  h.patch = ConvexHull(std::move(patch));
  h.id = id;
  h.lines = static_cast<int>(lines.size());
  h.lines_xy = std::move(lines);
  return h;
}

const Eigen::Vector4d kFlat6(0, 0, 1, -6);  // z = 6

// An L-shaped house, eaves at 6 m, 45 deg: the main wing over x 0..8,
// y 0..12 (ridge along y at x = 4), the side wing over x 8..16, y 0..6
// (ridge along x at y = 3). Its east face and the side wing's north face.
std::vector<RoofPlaneHypothesis> LFaces() {
  return {Hyp(SlopedPlane({8, 6, 6}, 45, 0), {{4, 0}, {8, 0}, {8, 12}, {4, 12}}, "east face",
              {{Eigen::Vector2d(8, 0), Eigen::Vector2d(8, 12)}}),
          Hyp(SlopedPlane({12, 6, 6}, 45, 90), {{8, 3}, {16, 3}, {16, 6}, {8, 6}}, "north face",
              {{Eigen::Vector2d(8, 6), Eigen::Vector2d(16, 6)}})};
}

TEST(FlatPlanesBeyondEaves, TheYardInTheInnerCornerOfAnLGoes) {
  std::vector<RoofPlaneHypothesis> planes = LFaces();
  // The two eaves meeting in the inner corner, joined as a pair.
  planes.push_back(Hyp(kFlat6, {{8, 6}, {8, 12}, {16, 6}}, "corner",
                       {{Eigen::Vector2d(8, 6.2), Eigen::Vector2d(8, 12)},
                        {Eigen::Vector2d(8.2, 6), Eigen::Vector2d(16, 6)}}));
  const std::vector<std::string> why = FlatPlanesBeyondEaves(planes);
  ASSERT_EQ(why.size(), 3u);
  EXPECT_TRUE(why[0].empty());
  EXPECT_TRUE(why[1].empty());
  EXPECT_NE(why[2].find("east face"), std::string::npos) << why[2];
  EXPECT_NE(why[2].find("north face"), std::string::npos) << why[2];
}

TEST(FlatPlanesBeyondEaves, AFlatRoofWithAnEdgeOfItsOwnStays) {
  std::vector<RoofPlaneHypothesis> planes = LFaces();
  // One of its lines is its own far edge, which no face continues.
  planes.push_back(Hyp(kFlat6, {{8, 6}, {8, 12}, {16, 12}, {16, 6}}, "annex",
                       {{Eigen::Vector2d(8, 6.2), Eigen::Vector2d(8, 12)},
                        {Eigen::Vector2d(8.5, 12), Eigen::Vector2d(15.5, 12)}}));
  EXPECT_TRUE(FlatPlanesBeyondEaves(planes)[2].empty());
}

TEST(FlatPlanesBeyondEaves, AMansardTopStays) {
  // The flat top at 9 m and a steep face falling away from its edge: the
  // face is lower beyond the line, the top is no eave's continuation.
  const std::vector<RoofPlaneHypothesis> planes = {
      Hyp(Eigen::Vector4d(0, 0, 1, -9), {{2, 2}, {8, 2}, {8, 8}, {2, 8}}, "top",
          {{Eigen::Vector2d(2.5, 2), Eigen::Vector2d(7.5, 2)}}),
      Hyp(SlopedPlane({5, 2, 9}, 70, -90), {{0, 0}, {10, 0}, {8, 2}, {2, 2}}, "south face",
          {{Eigen::Vector2d(2, 2), Eigen::Vector2d(8, 2)}})};
  EXPECT_TRUE(FlatPlanesBeyondEaves(planes)[0].empty());
}

}  // namespace
}  // namespace roofsweep
