#include "algorithms/sweep/coplanar_lines.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "algorithms/buildings/convex_polygon2.h"

namespace roofsweep {
namespace {

constexpr double kDeg = M_PI / 180.0;

SweepLine L(Eigen::Vector3d a, Eigen::Vector3d b) { return {{a, b}, {}}; }

double AngleDeg(const Eigen::Vector4d& plane, const Eigen::Vector3d& n) {
  return std::acos(std::min(1.0, std::abs(plane.head<3>().dot(n.normalized())))) / kDeg;
}

// Gable 10 x 8 m, ridge along x at y = 4, z = 8, eaves at z = 6, verges
// at x = 0 and x = 10.
std::vector<SweepLine> Gable(double x0 = 0) {
  return {L({x0, 4, 8}, {x0 + 10, 4, 8}),  // ridge
          L({x0, 0, 6}, {x0 + 10, 0, 6}),  // south eave
          L({x0, 8, 6}, {x0 + 10, 8, 6}),  // north eave
          L({x0, 0, 6}, {x0, 4, 8}),       // verges
          L({x0, 4, 8}, {x0, 8, 6}),          L({x0 + 10, 0, 6}, {x0 + 10, 4, 8}),
          L({x0 + 10, 4, 8}, {x0 + 10, 8, 6})};
}

// The gable's south face as the sweep found it from the ridge alone, with
// a 2.5 m strip.
PlaneGroup SweptSouthFace() {
  PlaneGroup g;
  const Eigen::Vector3d n = Eigen::Vector3d(0, -2, 4).normalized();
  g.plane << n, -n.dot(Eigen::Vector3d(0, 4, 8));
  g.lines = {0};
  g.half_planes = {0};
  g.patch = ConvexHull({{0, 4}, {10, 4}, {10, 1.5}, {0, 1.5}});
  g.longest_line_m = 10;
  return g;
}

TEST(CoplanarLines, GableGivesItsTwoFacesAndNotThePlaneThroughTheEaves) {
  const std::vector<SweepLine> lines = Gable();
  std::vector<PlaneGroup> none;
  const std::vector<PlaneGroup> planes = PlanesFromLinePairs(lines, &none);
  ASSERT_EQ(planes.size(), 2u);
  const Eigen::Vector3d south(0, -2, 4), north(0, 2, 4);
  int found_south = 0, found_north = 0;
  for (const PlaneGroup& p : planes) {
    found_south += AngleDeg(p.plane, south) < 0.01;
    found_north += AngleDeg(p.plane, north) < 0.01;
    // Ridge, eave and both verges of the face.
    EXPECT_EQ(p.lines.size(), 4u);
    EXPECT_NEAR(std::abs(SignedArea(p.patch)), 40.0, 1e-6);
    EXPECT_TRUE(p.half_planes.empty());
  }
  EXPECT_EQ(found_south, 1);
  EXPECT_EQ(found_north, 1);
}

TEST(CoplanarLines, AFaceIsNotContinuedPastTheEaveWhereItsSweepStops) {
  // The south face (z = 6 + y / 2, 26.6 deg) continued 6 m past its eave
  // meets the near edge of a garage roof, on the extension (z = 3) or a
  // little below it (z = 2.25: the pair is 5.4 deg steeper), as on the
  // simulated blocks, where such a pair grew into the house's face and
  // roofed the gap.
  for (const double garage_z : {3.0, 2.25}) {
    SCOPED_TRACE(garage_z);
    std::vector<SweepLine> lines = Gable();
    lines.push_back(L({5, -6, garage_z}, {9, -6, garage_z}));
    const int garage = static_cast<int>(lines.size()) - 1;
    const auto holding_garage = [&](const std::vector<PlaneGroup>& planes) {
      return std::count_if(planes.begin(), planes.end(), [&](const PlaneGroup& p) {
        return std::find(p.lines.begin(), p.lines.end(), garage) != p.lines.end();
      });
    };
    std::vector<PlaneGroup> none;
    EXPECT_GE(holding_garage(PlanesFromLinePairs(lines, &none)), 1);

    // The sweep found the face on the eave's north side and nothing on its
    // south side (the wall below it).
    HalfPlane face;
    face.line = 1;  // south eave, a -> b along +x: side +1 is north
    face.side = +1;
    face.plane = Eigen::Vector4d(0, -0.5, 1, -6) / std::sqrt(1.25);
    face.candidate = face.accepted = true;
    HalfPlane wall = face;
    wall.side = -1;
    wall.plane = Eigen::Vector4d(0, 0, 1, -3);
    wall.candidate = wall.accepted = false;
    const std::vector<HalfPlane> half_planes = {face, wall};
    std::vector<PlaneGroup> none2;
    const std::vector<PlaneGroup> planes = PlanesFromLinePairs(lines, &none2, {}, &half_planes);
    EXPECT_EQ(holding_garage(planes), 0);
    // The roof's own faces are still proposed.
    ASSERT_EQ(planes.size(), 2u);
    for (const PlaneGroup& p : planes) EXPECT_NEAR(std::abs(SignedArea(p.patch)), 40.0, 1e-6);
  }
}

TEST(CoplanarLines, ARidgeIsNotAFaceContinued) {
  // Only the north face was found by the sweep (on the ridge's north side):
  // the pair of ridge and south eave still proposes the south face, 53 deg
  // from the north one.
  const std::vector<SweepLine> lines = Gable();
  HalfPlane north;
  north.line = 0;  // ridge, a -> b along +x: side +1 is north
  north.side = +1;
  north.plane = Eigen::Vector4d(0, 0.5, 1, -10) / std::sqrt(1.25);
  north.candidate = north.accepted = true;
  const std::vector<HalfPlane> half_planes = {north};
  std::vector<PlaneGroup> none;
  const std::vector<PlaneGroup> planes = PlanesFromLinePairs(lines, &none, {}, &half_planes);
  int south = 0;
  for (const PlaneGroup& p : planes) south += AngleDeg(p.plane, {0, -2, 4}) < 0.01;
  EXPECT_EQ(south, 1);
}

TEST(CoplanarLines, HipRoofGivesFourFaces) {
  // 12 x 8 m hip roof, eaves at z = 5, ridge from (4, 4) to (8, 4) at z = 7.
  const Eigen::Vector3d c00(0, 0, 5), c10(12, 0, 5), c11(12, 8, 5), c01(0, 8, 5);
  const Eigen::Vector3d r0(4, 4, 7), r1(8, 4, 7);
  const std::vector<SweepLine> lines = {L(c00, c10), L(c10, c11), L(c11, c01),
                                        L(c01, c00), L(r0, r1),   L(c00, r0),
                                        L(c01, r0),  L(c10, r1),  L(c11, r1)};
  std::vector<PlaneGroup> none;
  const std::vector<PlaneGroup> planes = PlanesFromLinePairs(lines, &none);
  const std::vector<Eigen::Vector3d> normals = {{0, -2, 4}, {0, 2, 4}, {-2, 0, 4}, {2, 0, 4}};
  ASSERT_EQ(planes.size(), 4u);
  for (const Eigen::Vector3d& n : normals) {
    int found = 0;
    for (const PlaneGroup& p : planes) found += AngleDeg(p.plane, n) < 0.01;
    EXPECT_EQ(found, 1) << n.transpose();
  }
}

TEST(CoplanarLines, LinesOfNeighbouringBuildingsDoNotPair) {
  // Two equal gables 3 m apart: their faces are coplanar, but no plane
  // may span both houses. The gaps between their verges are hypotheses of
  // their own (3 m wide) for the photometric verification to refute.
  std::vector<SweepLine> lines = Gable(0);
  for (const SweepLine& l : Gable(13)) lines.push_back(l);
  std::vector<PlaneGroup> none;
  const std::vector<PlaneGroup> planes = PlanesFromLinePairs(lines, &none);
  int faces = 0;
  for (const PlaneGroup& p : planes) faces += std::abs(std::abs(SignedArea(p.patch)) - 40) < 1e-6;
  EXPECT_EQ(faces, 4);
  EXPECT_LE(planes.size(), 6u);
  for (const PlaneGroup& p : planes) {
    double xmin = 1e9, xmax = -1e9;
    for (const Eigen::Vector2d& v : p.patch)
      xmin = std::min(xmin, v.x()), xmax = std::max(xmax, v.x());
    EXPECT_LE(xmax - xmin, 10.0 + 1e-6);
  }
}

TEST(CoplanarLines, SweptPlaneTakesItsCoplanarLinesAndKeepsOthersOut) {
  const std::vector<SweepLine> lines = Gable();
  const PlaneGroup g = SweptSouthFace();
  const Eigen::Vector3d n = Eigen::Vector3d(0, -2, 4).normalized();
  std::vector<PlaneGroup> planes = {g};
  const int attached = AttachCoplanarLines(lines, &planes);
  EXPECT_EQ(attached, 3);  // south eave and the two south verges
  std::vector<int> got = planes[0].lines;
  std::sort(got.begin(), got.end());
  EXPECT_EQ(got, (std::vector<int>{0, 1, 3, 5}));
  EXPECT_NEAR(std::abs(SignedArea(planes[0].patch)), 40.0, 1e-6);
  EXPECT_LT(AngleDeg(planes[0].plane, n), 0.01);

  // A pair hypothesis of the same face joins the swept plane instead of
  // becoming a second one.
  const std::vector<PlaneGroup> pairs = PlanesFromLinePairs(lines, &planes);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_GT(AngleDeg(pairs[0].plane, n), 10.0);
}

// Level lines (SweepLevelLines) join planes through their half-planes
// only: two eaves at one height are coplanar with a flat roof there, and
// the south eave would join the swept face as a line.
TEST(CoplanarLines, LevelLinesNeitherPairNorJoin) {
  std::vector<SweepLine> lines = Gable();
  for (int i : {1, 2}) lines[i].level = true;  // both eaves
  const PlaneGroup g = SweptSouthFace();
  std::vector<PlaneGroup> planes = {g};
  EXPECT_EQ(AttachCoplanarLines(lines, &planes), 2);  // the two south verges
  EXPECT_EQ(std::count(planes[0].lines.begin(), planes[0].lines.end(), 1), 0);
  // The eaves alone, level: no pair, though they lie in the plane z = 6.
  std::vector<PlaneGroup> none;
  EXPECT_TRUE(PlanesFromLinePairs({lines[1], lines[2]}, &none).empty());
  lines[1].level = lines[2].level = false;
  EXPECT_EQ(PlanesFromLinePairs({lines[1], lines[2]}, &none).size(), 1u);
}

TEST(CoplanarLines, ALineThatBoundsAnotherFaceIsNotAttached) {
  // A terraced row: the gable's south eave (y = 0, z = 6, x 0..10) runs on
  // as the edge of a flat roof at eave height (x -8..0), which lies on the
  // same side of it as the gable's south face. The edge lies on the face's
  // plane.
  std::vector<SweepLine> lines = Gable();
  lines.push_back(L({-8, 0, 6}, {0, 0, 6}));
  const int flat_edge = static_cast<int>(lines.size()) - 1;
  PlaneGroup g;
  const Eigen::Vector3d n = Eigen::Vector3d(0, -2, 4).normalized();
  g.plane << n, -n.dot(Eigen::Vector3d(0, 4, 8));
  g.lines = {0, 1, 3, 5};
  g.patch = ConvexHull({{0, 4}, {10, 4}, {10, 0}, {0, 0}});
  g.longest_line_m = 10;
  // The sweep saw the flat roof on the face's side of the edge (+1 is
  // left of a -> b: north, where the face's centre lies) and nothing
  // beyond it.
  HalfPlane flat;
  flat.line = flat_edge;
  flat.side = 1;
  flat.plane << 0, 0, 1, -6;
  flat.candidate = flat.accepted = true;
  std::vector<HalfPlane> sides = {flat};

  // Without the half-planes the edge joins the face and grows its patch
  // over the flat roof.
  std::vector<PlaneGroup> planes = {g};
  EXPECT_EQ(AttachCoplanarLines(lines, &planes), 1);
  EXPECT_NEAR(std::abs(SignedArea(planes[0].patch)), 40.0 + 16.0, 1e-6);

  planes = {g};
  EXPECT_EQ(AttachCoplanarLines(lines, &planes, CoplanarOptions{}, &sides), 0);
  EXPECT_NEAR(std::abs(SignedArea(planes[0].patch)), 40.0, 1e-6);

  // Where the sweep saw the face's own plane beside the edge (a terraced
  // neighbour's coplanar face), the edge joins; so it does with the rule
  // off.
  sides[0].plane = g.plane;
  planes = {g};
  EXPECT_EQ(AttachCoplanarLines(lines, &planes, CoplanarOptions{}, &sides), 1);
  sides[0].plane << 0, 0, 1, -6;
  CoplanarOptions off;
  off.refuse_other_face = false;
  planes = {g};
  EXPECT_EQ(AttachCoplanarLines(lines, &planes, off, &sides), 1);
}

TEST(CoplanarLines, NonCoplanarJunctionsAndSteepPlanesAreRefused) {
  // A wall corner (vertical) meeting an eave: the plane is a wall.
  const std::vector<SweepLine> wall = {L({0, 0, 0}, {0, 0, 6}), L({0, 0, 6}, {10, 0, 6})};
  std::vector<PlaneGroup> none;
  EXPECT_TRUE(PlanesFromLinePairs(wall, &none).empty());
  // Two lines that pass 1 m apart in height do not meet.
  const std::vector<SweepLine> skew = {L({0, 0, 6}, {10, 0, 6}), L({0, -1, 7}, {0, 8, 7})};
  EXPECT_TRUE(PlanesFromLinePairs(skew, &none).empty());
}

}  // namespace
}  // namespace roofsweep
