#include "algorithms/sweep/eave_search.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "algorithms/buildings/convex_polygon2.h"
#include "algorithms/buildings/polygon2.h"
#include "algorithms/buildings/test_planes.h"
#include "algorithms/geometry/test_blocks.h"
#include "algorithms/geometry/view.h"

namespace roofsweep {
namespace {

using Line2 = std::array<Eigen::Vector2d, 2>;

// The north face of a gable, ridge along x at y = 0 and z = 10 over
// x -5..5, falling 40 degrees towards +y to its eave at y = 5. The sweep
// found it from its ridge and its west verge, whose lower end stops at
// y = verge_end: the patch is the triangle of their ends. Three nadir
// views 100 m up (10 cm GSD), two of them along x like a strip.
struct EaveScene {
  Block block = NadirTestBlock({{0, 0, 100}, {30, 0, 100}, {0, 30, 100}});
  Eigen::Vector4d plane = SlopedPlane({0, 0, 10}, 40, 90);
  std::vector<RoofPlaneHypothesis> planes;
  std::vector<Segments2D> segments{3};

  explicit EaveScene(double verge_end = 5.0) {
    RoofPlaneHypothesis p = TestPlane(plane, {{-5, 0}, {5, 0}, {-5, verge_end}}, "north face");
    p.lines_xy = {Line2{Eigen::Vector2d(-5, 0), Eigen::Vector2d(5, 0)},
                  Line2{Eigen::Vector2d(-5, 0), Eigen::Vector2d(-5, verge_end)}};
    p.lines = 2;
    planes.push_back(p);
  }
  double Z(double x, double y) const {
    return -(plane[0] * x + plane[1] * y + plane[3]) / plane[2];
  }
  Eigen::Vector3d OnFace(double x, double y) const { return {x, y, Z(x, y)}; }
  // The edge a-b as the given views see it.
  void See(const Eigen::Vector3d& a, const Eigen::Vector3d& b, std::vector<int> views = {0, 1, 2},
           bool texture = false) {
    for (int v : views) {
      const View& view = block.views[v];
      Segment2D s;
      s.p0 = *Project(block.CameraOf(view), view.pose, a);
      s.p1 = *Project(block.CameraOf(view), view.pose, b);
      s.texture = texture;
      segments[v].push_back(s);
    }
  }
};

TEST(FindEaves, TheEaveOfATriangleFromItsRidgeAndVergeIsFoundAndTheFaceGrowsToIt) {
  EaveScene s;
  s.See(s.OnFace(-5, 5), s.OnFace(5, 5));
  const std::vector<FaceEave> eaves = FindEaves(s.block, s.segments, s.planes);
  ASSERT_EQ(eaves.size(), 1u);
  const FaceEave& e = eaves[0];
  EXPECT_EQ(e.plane, 0);
  EXPECT_EQ(e.views, 3);
  EXPECT_NEAR(e.beyond_lines_m, 0.0, 1e-6);
  EXPECT_NEAR(e.held_m, 10.0, 0.11);
  EXPECT_NEAR(std::min(e.a.x(), e.b.x()), -5.0, 0.11);
  EXPECT_NEAR(std::max(e.a.x(), e.b.x()), 5.0, 0.11);
  EXPECT_NEAR(e.a.y(), 5.0, 1e-6);
  EXPECT_NEAR(e.b.y(), 5.0, 1e-6);

  EXPECT_NEAR(std::abs(SignedArea(s.planes[0].patch)), 25.0, 1e-9);
  std::vector<std::string> log;
  EXPECT_EQ(ExtendFacesToEaves(eaves, &s.planes, {}, &log), 1);
  ASSERT_EQ(log.size(), 1u);
  EXPECT_NE(log[0].find("patch grown"), std::string::npos) << log[0];
  EXPECT_NEAR(std::abs(SignedArea(s.planes[0].patch)), 50.0, 1.0);
}

TEST(FindEaves, AnEavePastTheVergesEndIsFoundWithinTheSearchRange) {
  EaveScene s(/*verge_end=*/4.6);
  s.See(s.OnFace(-5, 5), s.OnFace(5, 5));
  const std::vector<FaceEave> eaves = FindEaves(s.block, s.segments, s.planes);
  ASSERT_EQ(eaves.size(), 1u);
  EXPECT_NEAR(eaves[0].beyond_lines_m, 0.4, 1e-6);
  EaveSearchOptions o;
  o.search_to_m = 0.3;  // the same eave, out of reach
  EXPECT_TRUE(FindEaves(s.block, s.segments, s.planes, o).empty());
}

TEST(FindEaves, OneViewAloneHoldsNoEave) {
  EaveScene s;
  s.See(s.OnFace(-5, 5), s.OnFace(5, 5), {0});
  EXPECT_TRUE(FindEaves(s.block, s.segments, s.planes).empty());
  EaveSearchOptions o;
  o.min_views = 1;
  EXPECT_EQ(FindEaves(s.block, s.segments, s.planes, o).size(), 1u);
}

TEST(FindEaves, TextureSegmentsAreLeftOutAndTheOuterOfEqualEdgesWins) {
  EaveScene s;
  // A tile course marked as texture just inside the eave: nothing.
  s.See(s.OnFace(-5, 4.7), s.OnFace(5, 4.7), {0, 1, 2}, /*texture=*/true);
  EXPECT_TRUE(FindEaves(s.block, s.segments, s.planes).empty());
  // An unmarked course and the eave, both held over the whole face: the
  // eave, at the face's edge.
  s.See(s.OnFace(-5, 4.7), s.OnFace(5, 4.7));
  s.See(s.OnFace(-5, 5), s.OnFace(5, 5));
  const std::vector<FaceEave> eaves = FindEaves(s.block, s.segments, s.planes);
  ASSERT_EQ(eaves.size(), 1u);
  EXPECT_NEAR(eaves[0].a.y(), 5.0, 1e-6);
}

TEST(FindEaves, ShortEdgesAndFlatRoofsGiveNoEave) {
  EaveScene s;
  // Held over 1.5 m of the 10 m face.
  s.See(s.OnFace(-5, 5), s.OnFace(-3.5, 5));
  EXPECT_TRUE(FindEaves(s.block, s.segments, s.planes).empty());
  // A flat roof has no fall line to search down.
  EaveScene flat;
  flat.plane = {0, 0, 1, -10};
  flat.planes[0].plane = flat.plane;
  flat.See(flat.OnFace(-5, 5), flat.OnFace(5, 5));
  EXPECT_TRUE(FindEaves(flat.block, flat.segments, flat.planes).empty());
}

TEST(FindEaves, OnlyAFaceWhoseLowestLineRunsDownItIsSearched) {
  // Its ridge, its verge down to y = 4.6 and a level line there, its eave
  // found by the sweep: an edge 0.4 m further out (a gutter's shadow) is
  // no eave of it.
  EaveScene s(/*verge_end=*/4.6);
  s.planes[0].lines_xy.push_back({Eigen::Vector2d(-4, 4.6), Eigen::Vector2d(5, 4.6)});
  s.See(s.OnFace(-5, 5), s.OnFace(5, 5));
  EXPECT_TRUE(FindEaves(s.block, s.segments, s.planes).empty());
  // Shorter than min_length_m, the level line is no eave.
  s.planes[0].lines_xy.back() = {Eigen::Vector2d(-4, 4.6), Eigen::Vector2d(-2.5, 4.6)};
  EXPECT_EQ(FindEaves(s.block, s.segments, s.planes).size(), 1u);
  // Without the verge, the lowest point ends no line down the face: the
  // patch's low edge is wherever the sweep's band stopped.
  s.planes[0].lines_xy.erase(s.planes[0].lines_xy.begin() + 1);
  EXPECT_TRUE(FindEaves(s.block, s.segments, s.planes).empty());
}

TEST(ExtendFacesToEaves, AGrowthOverAnotherPlaneIsLeftOut) {
  EaveScene s;
  s.See(s.OnFace(-5, 5), s.OnFace(5, 5));
  const std::vector<FaceEave> eaves = FindEaves(s.block, s.segments, s.planes);
  ASSERT_EQ(eaves.size(), 1u);
  // A neighbour's face where the triangle would grow.
  s.planes.push_back(TestPlane({0, 0, 1, -8}, {{0, 0.5}, {5, 0.5}, {5, 5}, {0, 5}}, "neighbour"));
  const Ring2 before = s.planes[0].patch;
  std::vector<std::string> log;
  EXPECT_EQ(ExtendFacesToEaves(eaves, &s.planes, {}, &log), 0);
  ASSERT_EQ(log.size(), 1u);
  EXPECT_NE(log[0].find("left out"), std::string::npos) << log[0];
  EXPECT_EQ(s.planes[0].patch, before);
}

TEST(ClipFacesAtBorderLines, APatchRunningPastItsEaveLineEndsThere) {
  EaveScene s;
  // Ridge and eave found; the patch runs 3 m past the eave (a hip's strip
  // reaching over the ground at the hip's foot).
  s.planes[0].lines_xy = {Line2{Eigen::Vector2d(-5, 0), Eigen::Vector2d(5, 0)},
                          Line2{Eigen::Vector2d(-5, 5), Eigen::Vector2d(5, 5)}};
  s.planes[0].patch = {{-5, 0}, {5, 0}, {5, 8}, {-5, 8}};
  std::vector<std::string> log;
  EXPECT_EQ(ClipFacesAtBorderLines(&s.planes, {}, &log), 1);
  ASSERT_EQ(log.size(), 1u);
  EXPECT_NE(log[0].find("north face: patch cut by 27.0 m2"), std::string::npos) << log[0];
  EXPECT_NEAR(std::abs(SignedArea(s.planes[0].patch)), 53.0, 1e-9);
  for (const Eigen::Vector2d& q : s.planes[0].patch) EXPECT_LE(q.y(), 5.3 + 1e-9);
  // Already within the margin: nothing to cut.
  EXPECT_EQ(ClipFacesAtBorderLines(&s.planes), 0);
}

TEST(ClipFacesAtBorderLines, OnlyALevelLineAtTheBottomOfTheLinesIsAnEave) {
  EaveScene s;
  const Ring2 patch = {{-5, 0}, {5, 0}, {5, 8}, {-5, 8}};
  s.planes[0].patch = patch;
  // Ridge and verge: the lowest point ends a line down the face.
  EXPECT_EQ(ClipFacesAtBorderLines(&s.planes), 0);
  // A level line above the lowest point (a course of tiles, a dormer's
  // foot) is no eave.
  s.planes[0].lines_xy.push_back(Line2{Eigen::Vector2d(-4, 3), Eigen::Vector2d(4, 3)});
  EXPECT_EQ(ClipFacesAtBorderLines(&s.planes), 0);
  // Nor is one shorter than min_length_m at the bottom.
  s.planes[0].lines_xy.push_back(Line2{Eigen::Vector2d(-4, 5), Eigen::Vector2d(-2.5, 5)});
  EXPECT_EQ(ClipFacesAtBorderLines(&s.planes), 0);
  // A flat roof has no fall line to cut along: without clip_flat, a line
  // at the end of its lines cuts nothing.
  s.planes[0].lines_xy.push_back(Line2{Eigen::Vector2d(-4, 5), Eigen::Vector2d(4, 5)});
  s.planes[0].plane = Eigen::Vector4d(0, 0, 1, -8);
  EaveSearchOptions no_flat;
  no_flat.clip_flat = false;
  EXPECT_EQ(ClipFacesAtBorderLines(&s.planes, no_flat), 0);
  EXPECT_EQ(s.planes[0].patch, patch);
}

// A flat roof 10 x 6 m at z = 8 whose west edge, south edge and north edge
// were found; its patch runs 2.6 m west past the west edge (a terraced
// row's roof over its lower neighbour's).
RoofPlaneHypothesis FlatRoof() {
  RoofPlaneHypothesis p =
      TestPlane({0, 0, 1, -8}, {{-2.6, 0}, {10, 0}, {10, 6}, {-2.6, 6}}, "flat roof");
  p.lines_xy = {Line2{Eigen::Vector2d(0, 0), Eigen::Vector2d(0, 6)},
                Line2{Eigen::Vector2d(0, 0), Eigen::Vector2d(10, 0)},
                Line2{Eigen::Vector2d(0, 6), Eigen::Vector2d(10, 6)}};
  p.lines = 3;
  return p;
}

TEST(ClipFacesAtBorderLines, AFlatRoofRunningPastTheLineAtTheEndOfItsLinesEndsThere) {
  std::vector<RoofPlaneHypothesis> planes = {FlatRoof()};
  std::vector<std::string> log;
  EXPECT_EQ(ClipFacesAtBorderLines(&planes, {}, &log), 1);
  ASSERT_EQ(log.size(), 1u);
  EXPECT_NE(log[0].find("flat roof: flat patch cut by 13.8 m2"), std::string::npos) << log[0];
  const Eigen::Vector4d bounds = RingBounds(planes[0].patch);  // x0, y0, x1, y1
  EXPECT_NEAR(bounds[0], -0.3, 1e-9);
  // No line ends the roof in the east: the patch keeps its east edge.
  EXPECT_NEAR(bounds[2], 10, 1e-9);
  EXPECT_NEAR(std::abs(SignedArea(planes[0].patch)), 61.8, 1e-9);
  EXPECT_EQ(ClipFacesAtBorderLines(&planes), 0);
}

TEST(ClipFacesAtBorderLines, AFlatRoofEndsWhereItsEavesEndTogether) {
  // The west edge was not matched; the south and north edges both stop at
  // x = 0 (one 0.2 m short of it), and the east edge bounds the depth.
  std::vector<RoofPlaneHypothesis> planes = {FlatRoof()};
  planes[0].lines_xy = {Line2{Eigen::Vector2d(0.2, 0), Eigen::Vector2d(10, 0)},
                        Line2{Eigen::Vector2d(0, 6), Eigen::Vector2d(10, 6)},
                        Line2{Eigen::Vector2d(10, 0), Eigen::Vector2d(10, 6)}};
  const std::vector<RoofPlaneHypothesis> before = planes;
  std::vector<std::string> log;
  EXPECT_EQ(ClipFacesAtBorderLines(&planes, {}, &log), 1);
  ASSERT_EQ(log.size(), 1u);
  EXPECT_NEAR(RingBounds(planes[0].patch)[0], -0.3, 1e-9);
  EXPECT_NEAR(std::abs(SignedArea(planes[0].patch)), 61.8, 1e-9);
  // Off, nothing lies along the west end to cut at.
  EaveSearchOptions off;
  off.clip_min_line_ends = 0;
  planes = before;
  EXPECT_EQ(ClipFacesAtBorderLines(&planes, off), 0);
  // One edge stopping there is not enough: the other ends 3 m further in
  // (a line broken by a tree's shadow).
  planes = before;
  planes[0].lines_xy[1][0] = Eigen::Vector2d(3, 6);
  EXPECT_EQ(ClipFacesAtBorderLines(&planes), 0);
  EXPECT_EQ(planes[0].patch, before[0].patch);
}

TEST(ClipFacesAtBorderLines, AFlatRoofsLinesWithoutDepthCutNothing) {
  // Its west edge alone: the roof may lie on either side of it.
  std::vector<RoofPlaneHypothesis> planes = {FlatRoof()};
  planes[0].lines_xy.resize(1);
  planes[0].patch = {{-3, 0}, {3, 0}, {3, 6}, {-3, 6}};
  const Ring2 patch = planes[0].patch;
  EXPECT_EQ(ClipFacesAtBorderLines(&planes), 0);
  EXPECT_EQ(planes[0].patch, patch);
  // The south edge and a line shorter than min_length_m up from its west
  // end: the lines have depth northwards, but no long line ends them there,
  // and the short line gives no direction to cut across.
  planes[0].lines_xy = {Line2{Eigen::Vector2d(-1.5, 0), Eigen::Vector2d(3, 0)},
                        Line2{Eigen::Vector2d(-1.5, 0), Eigen::Vector2d(-1.5, 1.5)}};
  EXPECT_EQ(ClipFacesAtBorderLines(&planes), 0);
  EXPECT_EQ(planes[0].patch, patch);
}

TEST(ClipFacesAtBorderLines, APatchRunningPastAVergeAtTheEndOfItsLinesEndsThere) {
  EaveScene s;
  // Ridge, eave and west verge found; the patch runs 4 m past the verge (a
  // strip carried beyond the gable end over the ground).
  s.planes[0].lines_xy.push_back(Line2{Eigen::Vector2d(-5, 5), Eigen::Vector2d(5, 5)});
  s.planes[0].patch = {{-9, 0}, {5, 0}, {5, 5}, {-9, 5}};
  std::vector<std::string> log;
  EXPECT_EQ(ClipFacesAtBorderLines(&s.planes, {}, &log), 1);
  ASSERT_EQ(log.size(), 1u);
  EXPECT_NE(log[0].find("north face: patch cut by 18.5 m2"), std::string::npos) << log[0];
  for (const Eigen::Vector2d& q : s.planes[0].patch) EXPECT_GE(q.x(), -5.3 - 1e-9);
  // The east end has no verge (the ridge and the eave just stop there): the
  // lines do not tell where the face ends, and the patch may run on.
  s.planes[0].patch = {{-5, 0}, {9, 0}, {9, 5}, {-5, 5}};
  EXPECT_EQ(ClipFacesAtBorderLines(&s.planes), 0);
}

TEST(ClipFacesAtBorderLines, ARidgeCutsNothingUpTheFace) {
  EaveScene s;
  // The ridge's strip on the far side of the ridge: only eaves and verges
  // end a face (a ridge found alone would cut its own face to a sliver).
  s.planes[0].lines_xy.push_back(Line2{Eigen::Vector2d(-5, 5), Eigen::Vector2d(5, 5)});
  const Ring2 patch = {{-5, -3}, {5, -3}, {5, 5}, {-5, 5}};
  s.planes[0].patch = patch;
  EXPECT_EQ(ClipFacesAtBorderLines(&s.planes), 0);
  EXPECT_EQ(s.planes[0].patch, patch);
}

TEST(ClipFacesAtBorderLines, ALevelLineWithoutDepthAboveItCutsNothing) {
  EaveScene s;
  // Only level lines near the ridge (the ridge and a chimney's edge): the
  // lowest of them may as well be the top of the face as its foot.
  s.planes[0].lines_xy = {Line2{Eigen::Vector2d(-5, 0), Eigen::Vector2d(5, 0)},
                          Line2{Eigen::Vector2d(1, 0.4), Eigen::Vector2d(3.5, 0.4)}};
  const Ring2 patch = {{-5, 0}, {5, 0}, {5, 5}, {-5, 5}};
  s.planes[0].patch = patch;
  EXPECT_EQ(ClipFacesAtBorderLines(&s.planes), 0);
  EXPECT_EQ(s.planes[0].patch, patch);
  // Where less depth is asked for, the lower one ends the face.
  EaveSearchOptions o;
  o.clip_min_depth_m = 0.3;
  EXPECT_EQ(ClipFacesAtBorderLines(&s.planes, o), 1);
  for (const Eigen::Vector2d& q : s.planes[0].patch) EXPECT_LE(q.y(), 0.7 + 1e-9);
}

// The north-east corner of a hipped roof: the north face (40 degrees,
// ridge along x at y = 0 and z = 10) found from its hip alone, (5, 0) up
// at the ridge's end to (10, 5) at the eaves' corner, its patch the
// sweep's strip past the corner; the east face found with its eave along
// x = 10, ending at the corner.
struct HipCorner {
  std::vector<RoofPlaneHypothesis> planes;
  HipCorner() {
    RoofPlaneHypothesis north = TestPlane(SlopedPlane({0, 0, 10}, 40, 90),
                                          {{-5, 0}, {5, 0}, {10, 5}, {9, 7}, {-5, 7}}, "north");
    north.lines_xy = {Line2{Eigen::Vector2d(5, 0), Eigen::Vector2d(10, 5)}};
    north.lines = 1;
    RoofPlaneHypothesis east =
        TestPlane(SlopedPlane({5, 0, 10}, 40, 0), {{5, 0}, {10, 5}, {10, -5}}, "east");
    east.lines_xy = {Line2{Eigen::Vector2d(10, -5), Eigen::Vector2d(10, 5)},
                     Line2{Eigen::Vector2d(5, 0), Eigen::Vector2d(10, 5)}};
    east.lines = 2;
    planes = {north, east};
  }
  double MaxY() const {
    double y = -1e300;
    for (const Eigen::Vector2d& q : planes[0].patch) y = std::max(y, q.y());
    return y;
  }
};

TEST(CutFacesAtHipFeet, AFaceEndsAtTheFootOfItsHipWhereTheNextFacesEaveEnds) {
  HipCorner s;
  std::vector<std::string> log;
  EXPECT_EQ(CutFacesAtHipFeet(&s.planes, {}, &log), 1);
  ASSERT_EQ(log.size(), 1u);
  EXPECT_NE(log[0].find("north: patch cut by 24.5 m2 at the foot of its hip"), std::string::npos)
      << log[0];
  EXPECT_NEAR(s.MaxY(), 5.3, 1e-9);
  // The east face has its eave: nothing past it to cut.
  EXPECT_EQ(s.planes[1].patch, HipCorner().planes[1].patch);
  // Off: the strip stays.
  HipCorner off;
  EaveSearchOptions o;
  o.hip_corner_m = 0;
  EXPECT_EQ(CutFacesAtHipFeet(&off.planes, o), 0);
  EXPECT_NEAR(off.MaxY(), 7, 1e-9);
}

TEST(CutFacesAtHipFeet, OnlyAnEaveEndingAtTheHipsFootAtItsHeightBackUpTheFaceCuts) {
  const auto cuts = [](const std::function<void(HipCorner*)>& change) {
    HipCorner s;
    change(&s);
    return CutFacesAtHipFeet(&s.planes) > 0 && s.MaxY() < 6;
  };
  EXPECT_TRUE(cuts([](HipCorner*) {}));
  // The eave stops 1 m short of the corner.
  EXPECT_FALSE(cuts([](HipCorner* s) { s->planes[1].lines_xy[0][1] = {10, 4}; }));
  // The other face lies 0.5 m higher there (a step, no hip).
  EXPECT_FALSE(cuts([](HipCorner* s) { s->planes[1].plane[3] -= 0.5 * s->planes[1].plane[2]; }));
  // The eave runs on down this face's slope from the foot: a valley's
  // foot in a concave corner, which this face may pass.
  EXPECT_FALSE(cuts([](HipCorner* s) { s->planes[1].lines_xy[0] = {{{10, 15}, {10, 5}}}; }));
  // A level line above the other face's lowest (a course of tiles) is no eave.
  EXPECT_FALSE(cuts([](HipCorner* s) {
    s->planes[1].lines_xy.push_back(Line2{Eigen::Vector2d(11, -5), Eigen::Vector2d(11, 0)});
  }));
  // This face's lowest line runs along its fall line: a verge, whose foot
  // is no corner of the eaves.
  EXPECT_FALSE(cuts([](HipCorner* s) { s->planes[0].lines_xy[0] = {{{10, 0}, {10, 5}}}; }));
}

}  // namespace
}  // namespace roofsweep
