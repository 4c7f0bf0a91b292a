#include "algorithms/simulate/prop_edges.h"

#include <gtest/gtest.h>

namespace roofsweep {
namespace sim {
namespace {

using V3 = Eigen::Vector3d;

Prop Box(PropKind kind, const V3& center, const V3& half) {
  Prop p;
  p.kind = kind;
  p.center = center;
  p.half = half;
  return p;
}

double Length(const std::vector<TrueEdge>& edges) {
  double l = 0;
  for (const TrueEdge& e : edges) l += (e.b - e.a).norm();
  return l;
}

// A flat roof at 5 m over [-5, 5]²: a chimney from 4 m to 6 m through it,
// a box standing on the ground beside the house.
struct Fixture {
  Scene scene;
  std::vector<RoofPlane> roofs;
  Fixture() {
    RoofPlane r;
    r.plane = Eigen::Vector4d(0, 0, 1, -5);
    r.polygon.exterior = {V3(-5, -5, 5), V3(5, -5, 5), V3(5, 5, 5), V3(-5, 5, 5)};
    roofs.push_back(r);
  }
};

TEST(PropEdges, ABoxOnTheGroundKeepsAllTwelveEdges) {
  Fixture f;
  f.scene.props.push_back(Box(PropKind::kHedge, V3(20, 0, 0.5), V3(2, 0.5, 0.5)));
  const auto edges = PropEdges(f.scene, f.roofs);
  EXPECT_EQ(edges.size(), 12u);
  EXPECT_NEAR(Length(edges), 4 * (4 + 1 + 1), 1e-9);
  for (const TrueEdge& e : edges) EXPECT_EQ(e.kind, EdgeKind::kProp);
}

TEST(PropEdges, AChimneyKeepsOnlyWhatRisesAboveTheRoof) {
  Fixture f;
  f.scene.props.push_back(Box(PropKind::kChimney, V3(0, 0, 5), V3(0.3, 0.3, 1)));
  const auto edges = PropEdges(f.scene, f.roofs);
  // Four top edges of 0.6 m, four verticals from the roof (5 m, less the
  // 2 cm taken as contact) up to 6 m; the foot's edges at 4 m are buried.
  EXPECT_EQ(edges.size(), 8u);
  EXPECT_NEAR(Length(edges), 4 * 0.6 + 4 * 1.01, 4 * 0.011);
  for (const TrueEdge& e : edges) {
    EXPECT_GE(std::min(e.a.z(), e.b.z()), 5 - 0.02);
  }
}

TEST(PropEdges, AHoleInTheRoofIsOpenAir) {
  Fixture f;
  f.roofs[0].polygon.holes.push_back({V3(-1, -1, 5), V3(1, -1, 5), V3(1, 1, 5), V3(-1, 1, 5)});
  f.scene.props.push_back(Box(PropKind::kRoofBox, V3(0, 0, 2), V3(0.5, 0.5, 0.5)));
  // Below the roof's plane but under its hole, over the ground: all edges.
  EXPECT_EQ(PropEdges(f.scene, f.roofs).size(), 12u);
}

TEST(EdgeKindFromName, EveryKindRoundTrips) {
  for (int k = 0; k <= static_cast<int>(EdgeKind::kProp); ++k) {
    const auto kind = static_cast<EdgeKind>(k);
    EXPECT_EQ(EdgeKindFromName(EdgeKindName(kind)), kind);
  }
  EXPECT_FALSE(EdgeKindFromName("chimney").has_value());
  // No kind beyond the last one the walk knows of.
  EXPECT_STREQ(EdgeKindName(static_cast<EdgeKind>(static_cast<int>(EdgeKind::kProp) + 1)), "?");
}

}  // namespace
}  // namespace sim
}  // namespace roofsweep
