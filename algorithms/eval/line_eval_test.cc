#include "algorithms/eval/line_eval.h"

#include <gtest/gtest.h>

#include "algorithms/eval/test_models.h"

namespace roofsweep::eval {
namespace {

using V = Eigen::Vector3d;

double TotalLength(const std::vector<Segment3>& s) {
  double l = 0;
  for (const auto& x : s) l += x.Length();
  return l;
}

TEST(Segment3, DistanceAndDirection) {
  const Segment3 s{V(0, 0, 0), V(10, 0, 0)};
  EXPECT_DOUBLE_EQ(s.Length(), 10);
  EXPECT_DOUBLE_EQ(s.Distance(V(5, 3, 4)), 5);
  EXPECT_DOUBLE_EQ(s.Distance(V(13, 4, 0)), 5);  // beyond the end
  EXPECT_DOUBLE_EQ(s.Direction().x(), 1);
}

TEST(RoofEdges, SharedRidgeOnceAndCoplanarSeamDropped) {
  CityModel m;
  m.buildings.push_back(eval_test::Gable("G", 0, 0, 12, 8, 0, 5, 3));
  const auto edges = RoofEdges(m, {});
  EXPECT_EQ(edges.size(), 7u);  // 2 eaves, ridge, 4 slope edges
  EXPECT_NEAR(TotalLength(edges), 12 * 3 + 4 * 5, 1e-9);

  CityModel split;
  Building b;
  b.id = "S";
  b.surfaces.push_back({SurfaceType::kRoof,
                        "",
                        {{{V(0, 0, 5), V(5, 0, 5), V(5, 8, 5), V(0, 8, 5)}, {}},
                         {{V(5, 0, 5), V(10, 0, 5), V(10, 8, 5), V(5, 8, 5)}, {}}}});
  split.buildings.push_back(b);
  EXPECT_NEAR(TotalLength(RoofEdges(split, {})), 36, 1e-9);  // seam x=5 not an edge
}

TEST(EvaluateLines, ExactEdgesArePerfect) {
  const CityModel m = eval_test::ThreeHouses();
  const auto edges = RoofEdges(m, {});
  const LineScores s = EvaluateLines(eval_test::UniqueRoofEdges(m), edges, {}, {});
  EXPECT_NEAR(s.result_on_reference_m / s.result_length_m, 1.0, 1e-12);
  EXPECT_NEAR(s.reference_covered_m / s.reference_length_m, 1.0, 1e-12);
  EXPECT_NEAR(s.roof_edge_covered_m / s.roof_edge_length_m, 1.0, 1e-12);
}

TEST(EvaluateLines, TwentyCentimetresOffGivesNothing) {
  const CityModel m = eval_test::ThreeHouses();
  std::vector<Segment3> lines = eval_test::UniqueRoofEdges(m);
  for (auto& l : lines) {
    l.a.z() += 0.2;
    l.b.z() += 0.2;
  }
  const LineScores s = EvaluateLines(lines, RoofEdges(m, {}), {}, {});
  EXPECT_EQ(s.result_on_reference_m, 0);
  EXPECT_EQ(s.reference_covered_m, 0);
  // Within tolerance (8 cm outward, perpendicular to the box edges) they count.
  CityModel box;
  box.buildings.push_back(eval_test::Box("B", 0, 0, 10, 8, 0, 5));
  std::vector<Segment3> near = eval_test::UniqueRoofEdges(box);
  for (auto& l : near) {
    const V d = l.Direction();
    const V outward(d.y(), -d.x(), 0);  // right of a counter-clockwise ring
    l.a += 0.08 * outward;
    l.b += 0.08 * outward;
  }
  const LineScores t = EvaluateLines(near, RoofEdges(box, {}), {}, {});
  EXPECT_NEAR(t.result_on_reference_m / t.result_length_m, 1.0, 1e-12);
}

TEST(EvaluateLines, HalfTheEdgesGiveHalfCompleteness) {
  CityModel box;
  box.buildings.push_back(eval_test::Box("B", 0, 0, 10, 8, 0, 5));
  const auto edges = RoofEdges(box, {});
  ASSERT_EQ(edges.size(), 4u);
  const std::vector<Segment3> half = {edges[0], edges[1]};  // 10 m + 8 m of 36 m
  const LineScores s = EvaluateLines(half, edges, {}, {});
  EXPECT_NEAR(s.reference_covered_m / s.reference_length_m, 0.5, 1e-12);
  EXPECT_NEAR(s.result_on_reference_m / s.result_length_m, 1.0, 1e-12);
  // Edge by edge: the two given whole, the other two not at all.
  ASSERT_EQ(s.reference_covered_each_m.size(), 4u);
  for (size_t k = 0; k < 4; ++k)
    EXPECT_NEAR(s.reference_covered_each_m[k], k < 2 ? edges[k].Length() : 0.0, 1e-12) << k;
  // Half of each edge (up to its midpoint): the reference is covered up to
  // 10 cm beyond each half's end, so 0.5 + 4 * 0.1 / 36, to the 2 cm sampling.
  std::vector<Segment3> halves;
  for (const auto& e : edges) halves.push_back({e.a, e.At(0.5)});
  const LineScores h = EvaluateLines(halves, edges, {}, {});
  EXPECT_NEAR(h.reference_covered_m / h.reference_length_m, 0.5 + 0.4 / 36, 4 * 0.02 / 36);
}

TEST(EvaluateLines, DirectionToleranceRejectsCrossingSegments) {
  const std::vector<Segment3> ref = {{V(0, 0, 0), V(10, 0, 0)}};
  const std::vector<Segment3> crossing = {{V(5, -1, 0), V(5, 1, 0)}};
  const LineScores s = EvaluateLines(crossing, ref, {}, {});
  EXPECT_EQ(s.result_on_reference_m, 0);
  EXPECT_EQ(s.reference_covered_m, 0);
  const std::vector<Segment3> tilted = {{V(0, 0, 0), V(10, 0.1, 0)}};  // 0.57°, within 10 cm
  const LineScores t = EvaluateLines(tilted, ref, {}, {});
  EXPECT_NEAR(t.reference_covered_m, 10, 0.05);
}

// A tile course in the middle of a roof face and a shadow border on the
// terrain lie on true surfaces; the same lines a metre above do not.
TEST(EvaluateLines, LinesOnASurfaceButNoEdgeAreCountedApart) {
  const Polygon3 roof{{V(0, 0, 5), V(10, 0, 5), V(10, 8, 9), V(0, 8, 9)}, {}};
  const std::vector<Polygon3> surfaces = {roof};
  LineEvalOptions o;
  o.ground.height = 0;
  const Segment3 course{V(2, 4, 7), V(8, 4, 7)};          // inside the face, 6 m
  const Segment3 shadow{V(20, 0, 0.02), V(20, 4, 0.02)};  // on the terrain, 4 m
  const Segment3 above{V(2, 4, 8), V(8, 4, 8)};           // 1 m over the face, 6 m
  const Segment3 eave{V(0, 0, 5), V(10, 0, 5)};           // a reference edge, 10 m
  const auto s = EvaluateLines({course, shadow, above, eave}, {eave}, {}, o, &surfaces);
  EXPECT_NEAR(s.result_length_m, 26, 1e-9);
  EXPECT_NEAR(s.result_on_reference_m, 10, 0.05);
  EXPECT_NEAR(s.result_on_surface_m, 10, 0.05);  // the course and the shadow, not the eave

  // Without surfaces or terrain nothing is on a surface.
  const auto none = EvaluateLines({course, shadow}, {eave}, {}, LineEvalOptions{});
  EXPECT_EQ(none.result_on_surface_m, 0);

  // A hole in the face (a courtyard, a skylight) is no surface.
  const Polygon3 holed{roof.exterior, {{V(1, 3, 6.5), V(9, 3, 6.5), V(9, 5, 7.5), V(1, 5, 7.5)}}};
  const std::vector<Polygon3> with_hole = {holed};
  const auto h = EvaluateLines({course}, {eave}, {}, LineEvalOptions{}, &with_hole);
  EXPECT_EQ(h.result_on_surface_m, 0);
}

TEST(EvaluateLines, ExtraReferenceSegmentsCountInCompletenessOnly) {
  CityModel box;
  box.buildings.push_back(eval_test::Box("B", 0, 0, 10, 8, 0, 5));
  const auto edges = RoofEdges(box, {});
  const std::vector<Segment3> marking = {{V(0, -5, 0), V(12, -5, 0)}};
  const LineScores s = EvaluateLines(edges, edges, marking, {});
  EXPECT_NEAR(s.reference_length_m, 48, 1e-9);
  ASSERT_EQ(s.reference_covered_each_m.size(), edges.size() + 1);  // the marking comes last
  EXPECT_EQ(s.reference_covered_each_m.back(), 0.0);
  EXPECT_NEAR(s.reference_covered_m / s.reference_length_m, 36.0 / 48.0, 1e-12);
  EXPECT_NEAR(s.roof_edge_covered_m / s.roof_edge_length_m, 1.0, 1e-12);
  std::vector<Segment3> with_marking = edges;
  with_marking.push_back(marking[0]);
  const LineScores t = EvaluateLines(with_marking, edges, marking, {});
  EXPECT_NEAR(t.result_on_reference_m / t.result_length_m, 1.0, 1e-12);
  EXPECT_NEAR(t.reference_covered_m / t.reference_length_m, 1.0, 1e-12);
}

TEST(EvaluateLines, ClutterCountsInPrecisionOnly) {
  CityModel box;
  box.buildings.push_back(eval_test::Box("B", 0, 0, 10, 8, 0, 5));
  const auto edges = RoofEdges(box, {});
  // A car's roof edge beside the house, and a line 1 m above it.
  const std::vector<Segment3> car = {{V(14, 0, 1.5), V(18, 0, 1.5)}};
  std::vector<Segment3> lines = edges;
  lines.push_back(car[0]);
  lines.push_back({V(14, 0, 2.5), V(18, 0, 2.5)});
  const LineScores without = EvaluateLines(lines, edges, {}, {});
  const LineScores with = EvaluateLines(lines, edges, {}, {}, nullptr, &car);
  EXPECT_NEAR(without.result_on_reference_m, 36, 1e-9);
  EXPECT_NEAR(with.result_on_reference_m, 40, 1e-9);
  EXPECT_NEAR(with.result_on_clutter_m, 4, 1e-9);
  EXPECT_NEAR(with.result_length_m, 44, 1e-9);
  // The car's edge is not there to be completed.
  EXPECT_NEAR(with.reference_length_m, without.reference_length_m, 1e-12);
  EXPECT_NEAR(with.reference_covered_m, without.reference_covered_m, 1e-12);
}

}  // namespace
}  // namespace roofsweep::eval
