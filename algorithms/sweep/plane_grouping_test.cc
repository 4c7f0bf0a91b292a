#include "algorithms/sweep/plane_grouping.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

#include "algorithms/buildings/convex_polygon2.h"
#include "algorithms/sweep/half_plane_family.h"

namespace roofsweep {
namespace {

constexpr double kDeg = M_PI / 180.0;

// The accepted half-plane on `side` of `line` that contains the plane with
// unit normal `n` (as the sweep would report it).
HalfPlane Accepted(const std::vector<SweepLine>& lines, int line, int side,
                   const Eigen::Vector3d& n, double extent, double sim = 0.6) {
  const auto f = HalfPlaneFamily::Make(lines[line].segment, side);
  HalfPlane h;
  h.line = line;
  h.side = side;
  h.theta_deg = f->AngleOfNormal(n) / kDeg;
  h.plane = f->Plane(h.theta_deg * kDeg);
  h.similarity = sim;
  h.curvature = -10;
  h.extent_m = extent;
  h.accepted = true;
  h.candidate = true;
  return h;
}

// Gable 10 x 8 m, ridge along x at y = 4, z = 8, eaves at z = 6.
struct Gable {
  std::vector<SweepLine> lines = {{{{0, 4, 8}, {10, 4, 8}}, {}},   // ridge
                                  {{{0, 0, 6}, {10, 0, 6}}, {}},   // south eave
                                  {{{0, 8, 6}, {10, 8, 6}}, {}}};  // north eave
  Eigen::Vector3d south = Eigen::Vector3d(0, -2, 4).normalized();
  Eigen::Vector3d north = Eigen::Vector3d(0, 2, 4).normalized();
};

TEST(PlaneGrouping, RidgeAndEavesBecomeTwoPlanes) {
  Gable g;
  // Side +1 is left of a -> b seen from above: +y for lines along +x.
  std::vector<HalfPlane> hps = {
      Accepted(g.lines, 0, -1, g.south, 3.0), Accepted(g.lines, 0, +1, g.north, 3.5),
      Accepted(g.lines, 1, +1, g.south, 3.0), Accepted(g.lines, 2, -1, g.north, 2.0)};
  HalfPlane rejected = hps[0];
  rejected.accepted = false;
  rejected.candidate = false;
  rejected.line = 1;
  hps.push_back(rejected);
  const GroupingResult r = GroupHalfPlanes(g.lines, hps);
  ASSERT_EQ(r.planes.size(), 2u);
  for (const PlaneGroup& p : r.planes) {
    EXPECT_EQ(p.lines.size(), 2u);
    const Eigen::Vector3d n = p.plane.head<3>();
    EXPECT_GT(std::max(n.dot(g.south), n.dot(g.north)), std::cos(0.01 * kDeg));
    // The two strips cover the 10 x 4 m face.
    EXPECT_NEAR(std::abs(SignedArea(p.patch)), 40.0, 1e-6);
  }
  const std::vector<RoofPlaneHypothesis> roofs = ToRoofPlanes(r.planes);
  ASSERT_EQ(roofs.size(), 2u);
  EXPECT_EQ(roofs[0].lines, 2);
  // Without lines (or lines without residuals) the residual is unknown.
  EXPECT_EQ(roofs[0].reprojection_lines, 0);
}

TEST(PlaneGrouping, APlaneCarriesTheReprojectionResidualOfItsLines) {
  Gable g;
  g.lines[0].rms_px = 0.5;  // ridge
  g.lines[1].rms_px = 1.0;  // south eave
  // The north eave has none (read from a file without the field).
  std::vector<HalfPlane> hps = {
      Accepted(g.lines, 0, -1, g.south, 3.0), Accepted(g.lines, 0, +1, g.north, 3.5),
      Accepted(g.lines, 1, +1, g.south, 3.0), Accepted(g.lines, 2, -1, g.north, 2.0)};
  const GroupingResult r = GroupHalfPlanes(g.lines, hps);
  const std::vector<RoofPlaneHypothesis> roofs = ToRoofPlanes(r.planes, &g.lines);
  ASSERT_EQ(roofs.size(), 2u);
  for (const RoofPlaneHypothesis& h : roofs) {
    const Eigen::Vector3d n = h.plane.head<3>();
    if (n.dot(g.south) > 0.999) {  // ridge and south eave
      EXPECT_EQ(h.reprojection_lines, 2);
      EXPECT_NEAR(h.reprojection_rms_px, std::sqrt((0.25 + 1.0) / 2), 1e-12);
    } else {  // ridge only
      EXPECT_EQ(h.reprojection_lines, 1);
      EXPECT_NEAR(h.reprojection_rms_px, 0.5, 1e-12);
    }
  }
}

TEST(PlaneGrouping, FarApartCoplanarFacesStaySeparateAndConflictsResolve) {
  Gable g;
  std::vector<SweepLine> lines = g.lines;
  // The same south face 30 m further east: coplanar but another building.
  lines.push_back({{{40, 4, 8}, {50, 4, 8}}, {}});
  // A false, steep half-plane on the south eave's inner side overlapping
  // the south face, weaker than it.
  std::vector<HalfPlane> hps = {
      Accepted(lines, 0, -1, g.south, 4.0), Accepted(lines, 3, -1, g.south, 4.0),
      Accepted(lines, 1, +1, Eigen::Vector3d(0, -1, 1).normalized(), 3.5, 0.45)};
  const GroupingResult r = GroupHalfPlanes(lines, hps);
  ASSERT_EQ(r.planes.size(), 3u);
  std::vector<RoofPlaneHypothesis> planes = ToRoofPlanes(r.planes);
  const std::vector<std::string> rejected = ResolveConflicts(&planes, GroupingOptions{});
  ASSERT_EQ(planes.size(), 2u);
  EXPECT_EQ(planes[0].lines, 1);
  EXPECT_EQ(r.planes[0].lines, std::vector<int>{0});
  EXPECT_EQ(r.planes[1].lines, std::vector<int>{3});
  ASSERT_EQ(rejected.size(), 1u);
  EXPECT_NE(rejected[0].find("overlaps"), std::string::npos) << rejected[0];
  EXPECT_NE(rejected[0].find("line 1"), std::string::npos) << rejected[0];
}

// Two flat roofs of a row, 8 m deep, side by side along x; the eastern one
// `step` m higher. Each roof's front and back eaves carry a half-plane into
// the roof.
GroupingResult TwoFlatRoofs(double step) {
  const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  const std::vector<SweepLine> lines = {{{{0, 0, 6}, {10, 0, 6}}, {}},
                                        {{{0, 8, 6}, {10, 8, 6}}, {}},
                                        {{{10.5, 0, 6 + step}, {20, 0, 6 + step}}, {}},
                                        {{{10.5, 8, 6 + step}, {20, 8, 6 + step}}, {}}};
  const std::vector<HalfPlane> hps = {
      Accepted(lines, 0, +1, up, 4.0), Accepted(lines, 1, -1, up, 4.0),
      Accepted(lines, 2, +1, up, 4.0, 0.55), Accepted(lines, 3, -1, up, 4.0, 0.55)};
  return GroupHalfPlanes(lines, hps);
}

TEST(PlaneGrouping, FlatRoofsAStepApartStaySeparate) {
  // A 0.2 m step is four times the height error of a matched line: two roofs.
  GroupingResult r = TwoFlatRoofs(0.2);
  ASSERT_EQ(r.planes.size(), 2u);
  EXPECT_NEAR(-r.planes[0].plane.w() / r.planes[0].plane.z(), 6.0, 1e-6);
  EXPECT_NEAR(-r.planes[1].plane.w() / r.planes[1].plane.z(), 6.2, 1e-6);
  // Lines 0.08 m apart are one roof measured twice.
  r = TwoFlatRoofs(0.08);
  ASSERT_EQ(r.planes.size(), 1u);
  EXPECT_EQ(r.planes[0].lines.size(), 4u);
}

TEST(PlaneGrouping, DerivedPlanesYieldToFoundOnesInConflicts) {
  RoofPlaneHypothesis found, derived;
  found.id = "found";
  found.patch = {{0, 0}, {10, 0}, {10, 5}, {0, 5}};
  found.score = 1;
  derived.id = "derived";
  derived.patch = {{0, 0}, {10, 0}, {10, 6}, {0, 6}};
  derived.score = 100;  // larger and better scored, but only proposed
  derived.derived = true;
  std::vector<RoofPlaneHypothesis> planes = {derived, found};
  const std::vector<std::string> rejected = ResolveConflicts(&planes, GroupingOptions{});
  ASSERT_EQ(planes.size(), 1u);
  EXPECT_EQ(planes[0].id, "found");
  ASSERT_EQ(rejected.size(), 1u);
  EXPECT_EQ(rejected[0].rfind("derived: overlaps the stronger found", 0), 0u) << rejected[0];
}

// A derived face over a footprint against a found plane of a fifth of its
// area inside it: the derived face takes its place; against one of half its
// area it yields.
TEST(PlaneGrouping, ADerivedFaceDisplacesMuchSmallerFoundPlanes) {
  RoofPlaneHypothesis derived, small, elsewhere;
  derived.id = "derived";
  derived.patch = {{0, 0}, {10, 0}, {10, 6}, {0, 6}};
  derived.score = 30;
  derived.derived = true;
  small.id = "small";
  small.patch = {{2, 1}, {5, 1}, {5, 5}, {2, 5}};  // 12 m² of 60
  small.score = 50;
  elsewhere.id = "elsewhere";
  elsewhere.patch = {{20, 0}, {22, 0}, {22, 2}, {20, 2}};
  elsewhere.score = 1;
  std::vector<RoofPlaneHypothesis> planes = {small, derived, elsewhere};
  std::vector<std::string> rejected = ResolveConflicts(&planes, GroupingOptions{});
  ASSERT_EQ(planes.size(), 2u);
  EXPECT_EQ(planes[0].id, "derived");
  EXPECT_EQ(planes[1].id, "elsewhere");
  ASSERT_EQ(rejected.size(), 1u);
  EXPECT_EQ(rejected[0].rfind("small: lies in the derived derived, more than 4 times its area", 0),
            0u)
      << rejected[0];

  // Without the rule, or against a found plane of half its area, the
  // derived face yields.
  GroupingOptions off;
  off.derived_displaces_fraction = 0;
  planes = {small, derived, elsewhere};
  ResolveConflicts(&planes, off);
  ASSERT_EQ(planes.size(), 2u);
  EXPECT_EQ(planes[0].id, "small");
  RoofPlaneHypothesis half = small;
  half.patch = {{0, 0}, {5, 0}, {5, 6}, {0, 6}};
  planes = {half, derived};
  ResolveConflicts(&planes, GroupingOptions{});
  ASSERT_EQ(planes.size(), 1u);
  EXPECT_EQ(planes[0].id, "small");
}

// A gable face found along part of its ridge, against the mirror image of
// the opposite face: coplanar, so the derived face takes its place though
// it is almost half its area; 0.5 m higher it is another roof, and the
// derived face yields, as it does when a line of the fragment runs deep
// inside it.
TEST(PlaneGrouping, ADerivedFaceAbsorbsACoplanarFragmentOfIt) {
  // z = 10 + 0.7 y, rising to the ridge at y = 6.
  const Eigen::Vector3d n = Eigen::Vector3d(0, -0.7, 1).normalized();
  auto plane_at = [&](double z0) { return Eigen::Vector4d(n.x(), n.y(), n.z(), -n.z() * z0); };
  RoofPlaneHypothesis derived, fragment;
  derived.id = "derived";
  derived.plane = plane_at(10);
  derived.patch = {{0, 0}, {10, 0}, {10, 6}, {0, 6}};
  derived.score = 30;
  derived.derived = true;
  fragment.id = "fragment";
  fragment.plane = plane_at(10.05);
  fragment.patch = {{0, 1}, {5, 1}, {5, 6}, {0, 6}};                     // 25 m² of 60
  fragment.lines_xy = {{Eigen::Vector2d(0, 6), Eigen::Vector2d(5, 6)}};  // along the ridge
  fragment.score = 50;
  std::vector<RoofPlaneHypothesis> planes = {fragment, derived};
  std::vector<std::string> rejected = ResolveConflicts(&planes, GroupingOptions{});
  ASSERT_EQ(planes.size(), 1u);
  EXPECT_EQ(planes[0].id, "derived");
  ASSERT_EQ(rejected.size(), 1u);
  EXPECT_EQ(rejected[0].rfind("fragment: lies in the derived derived, larger and coplanar", 0), 0u)
      << rejected[0];

  fragment.plane = plane_at(10.5);
  planes = {fragment, derived};
  ResolveConflicts(&planes, GroupingOptions{});
  ASSERT_EQ(planes.size(), 1u);
  EXPECT_EQ(planes[0].id, "fragment");

  // Turned off, the derived face yields to the coplanar fragment too.
  GroupingOptions off;
  off.derived_absorbs_coplanar = false;
  fragment.plane = plane_at(10.05);
  planes = {fragment, derived};
  ResolveConflicts(&planes, off);
  ASSERT_EQ(planes.size(), 1u);
  EXPECT_EQ(planes[0].id, "fragment");

  // A line of the fragment down the middle of the derived face (2.5 m
  // inside it) bounds something there: the derived face yields.
  fragment.lines_xy.push_back({Eigen::Vector2d(5, 1), Eigen::Vector2d(5, 6)});
  planes = {fragment, derived};
  ResolveConflicts(&planes, GroupingOptions{});
  ASSERT_EQ(planes.size(), 1u);
  EXPECT_EQ(planes[0].id, "fragment");
}

TEST(PlaneGrouping, PlanesAcceptedOnTheirLinesYieldToConfirmedOnes) {
  RoofPlaneHypothesis confirmed, on_lines, derived;
  confirmed.id = "confirmed";
  confirmed.patch = {{0, 0}, {10, 0}, {10, 5}, {0, 5}};
  confirmed.score = 1;
  on_lines.id = "on lines";
  on_lines.patch = {{0, 0}, {20, 0}, {20, 6}, {0, 6}};
  on_lines.score = 100;  // larger, but the images could not tell its height
  on_lines.height_from_lines = true;
  derived.id = "derived";
  derived.patch = {{30, 0}, {40, 0}, {40, 6}, {30, 6}};
  derived.score = 1000;
  derived.derived = true;
  // Elsewhere, a plane accepted on its lines is still found: it goes
  // before a derived one, whatever their scores.
  RoofPlaneHypothesis on_lines_too = on_lines;
  on_lines_too.id = "on lines too";
  on_lines_too.patch = derived.patch;
  std::vector<RoofPlaneHypothesis> planes = {on_lines, derived, confirmed, on_lines_too};
  const std::vector<std::string> rejected = ResolveConflicts(&planes, GroupingOptions{});
  ASSERT_EQ(planes.size(), 2u);
  EXPECT_EQ(planes[0].id, "confirmed");
  EXPECT_EQ(planes[1].id, "on lines too");
  ASSERT_EQ(rejected.size(), 2u);
  EXPECT_EQ(rejected[0].rfind("on lines: overlaps the stronger confirmed", 0), 0u) << rejected[0];
  EXPECT_EQ(rejected[1].rfind("derived: overlaps the stronger on lines too", 0), 0u) << rejected[1];
}

// A roof plane hypothesis through `point` with unit normal `n` over an
// axis-aligned plan rectangle.
RoofPlaneHypothesis Face(const std::string& id, const Eigen::Vector3d& n,
                         const Eigen::Vector3d& point, double x0, double y0, double x1, double y1,
                         double score) {
  RoofPlaneHypothesis h;
  h.id = id;
  h.plane << n, -n.dot(point);
  h.patch = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  h.score = score;
  return h;
}

// A face as the verification scored it: similarity, score scaled by it,
// its lines and the longest one's length.
RoofPlaneHypothesis WithSimilarity(RoofPlaneHypothesis h, double sim, int lines = 3,
                                   double longest_line_m = 7) {
  h.similarity = sim;
  h.score *= sim;
  h.lines = lines;
  h.longest_line_m = longest_line_m;
  return h;
}

TEST(PlaneGrouping, TheTwoFacesOfAGableMeetAtTheRidgeInsteadOfConflicting) {
  Gable g;
  const Eigen::Vector3d ridge(0, 4, 8);
  // Both patches run 2 m past the ridge (y = 4): they overlap by two
  // thirds, but the ridge parts them, a third of each across, and the
  // ridge line supports both.
  RoofPlaneHypothesis south = Face("south", g.south, ridge, 0, 0, 10, 6, 2);
  RoofPlaneHypothesis north = Face("north", g.north, ridge, 0, 2, 10, 8, 1);
  const std::array<Eigen::Vector2d, 2> ridge_xy = {Eigen::Vector2d(1, 4.1),
                                                   Eigen::Vector2d(9, 3.9)};
  south.lines_xy = {ridge_xy, {Eigen::Vector2d(0, 0), Eigen::Vector2d(10, 0)}};
  north.lines_xy = {ridge_xy};
  std::vector<RoofPlaneHypothesis> planes = {south, north};
  EXPECT_TRUE(ResolveConflicts(&planes, GroupingOptions{}).empty());
  EXPECT_EQ(planes.size(), 2u);

  // No line along the ridge in one of them: nothing shows that the two
  // faces border there, and they compete.
  RoofPlaneHypothesis north_eave_only = north;
  north_eave_only.lines_xy = {{Eigen::Vector2d(0, 8), Eigen::Vector2d(10, 8)}};
  planes = {south, north_eave_only};
  EXPECT_EQ(ResolveConflicts(&planes, GroupingOptions{}).size(), 1u);
  EXPECT_EQ(planes.size(), 1u);

  // Without the rule, the weaker face goes.
  GroupingOptions off;
  off.conflict_meet_max_across = 0;
  planes = {south, north};
  const std::vector<std::string> rejected = ResolveConflicts(&planes, off);
  ASSERT_EQ(planes.size(), 1u);
  EXPECT_EQ(planes[0].id, "south");
  ASSERT_EQ(rejected.size(), 1u);
  EXPECT_EQ(rejected[0].rfind("north: overlaps the stronger south", 0), 0u) << rejected[0];

  // A plane whose whole patch lies in the south face's spill is a rival,
  // not a neighbour, though it lies on its own side of the line where the
  // two meet.
  RoofPlaneHypothesis inside = Face("inside", g.north, ridge, 0, 4.2, 10, 5.8, 1);
  inside.lines_xy = {ridge_xy};
  planes = {south, inside};
  ASSERT_EQ(ResolveConflicts(&planes, GroupingOptions{}).size(), 1u);
  ASSERT_EQ(planes.size(), 1u);
  EXPECT_EQ(planes[0].id, "south");

  // Nor are two faces neighbours that both lie mostly on one side of the
  // line where they meet (an overlap of 65 %).
  RoofPlaneHypothesis astray = Face("astray", g.north, ridge, 3.5, 0, 13.5, 4.5, 1);
  astray.lines_xy = {ridge_xy};
  planes = {south, astray};
  ASSERT_EQ(ResolveConflicts(&planes, GroupingOptions{}).size(), 1u);
  EXPECT_EQ(planes[0].id, "south");
}

TEST(PlaneGrouping, AHipEndIsCutAtItsHipRatherThanDroppedForTheLongFaceOverIt) {
  // Hipped roof over x in [0, 8], y in [0, 12], eaves at z = 6, 45 deg: the
  // west face z = 6 + x and the south hip end z = 6 + y meet along the hip
  // x = y. The west face's patch runs over the hip end, as a patch grown
  // from its eave does, and overlaps it by 56 %.
  const Eigen::Vector3d west_n = Eigen::Vector3d(-1, 0, 1).normalized();
  const Eigen::Vector3d south_n = Eigen::Vector3d(0, -1, 1).normalized();
  const Eigen::Vector3d corner(0, 0, 6);
  RoofPlaneHypothesis west = WithSimilarity(Face("west", west_n, corner, 0, 0, 4.5, 12, 3), 0.8);
  west.lines_xy = {{Eigen::Vector2d(0, 0), Eigen::Vector2d(0, 12)},  // eave
                   {Eigen::Vector2d(4, 4), Eigen::Vector2d(4, 8)}};  // ridge
  RoofPlaneHypothesis south = WithSimilarity(Face("south", south_n, corner, 0, 0, 8, 4.5, 1), 0.8);
  south.lines_xy = {{Eigen::Vector2d(0, 0), Eigen::Vector2d(8, 0)},   // eave
                    {Eigen::Vector2d(8, 0), Eigen::Vector2d(4, 4)}};  // the other hip
  std::vector<RoofPlaneHypothesis> planes = {west, south};
  EXPECT_TRUE(ResolveConflicts(&planes, GroupingOptions{}).empty());
  ASSERT_EQ(planes.size(), 2u);
  // The hip end keeps its side of the hip only.
  EXPECT_NEAR(std::abs(SignedArea(planes[1].patch)), 36 - 0.5 * 4.5 * 4.5, 1e-6);
  for (const Eigen::Vector2d& x : planes[1].patch) EXPECT_LE(x.y(), x.x() + 1e-9);

  // Without the rule the hip end goes.
  GroupingOptions off;
  off.conflict_cut_at_crease = false;
  planes = {west, south};
  ASSERT_EQ(ResolveConflicts(&planes, off).size(), 1u);
  EXPECT_EQ(planes[0].id, "west");

  // A line of the hip end that runs across the hip says the border is not
  // there.
  RoofPlaneHypothesis across = south;
  across.lines_xy.push_back({Eigen::Vector2d(1, 1), Eigen::Vector2d(1, 6)});
  planes = {west, across};
  ASSERT_EQ(ResolveConflicts(&planes, GroupingOptions{}).size(), 1u);
  EXPECT_EQ(planes[0].id, "west");

  // Nor is a plane cut that meets the west face in a valley, rising above
  // it on its own side (z = 6 + 2x - y): the west face would be the roof
  // there.
  const Eigen::Vector3d valley_n = Eigen::Vector3d(-2, 1, 1).normalized();
  RoofPlaneHypothesis valley = south;
  valley.id = "valley";
  valley.plane << valley_n, -valley_n.dot(corner);
  planes = {west, valley};
  ASSERT_EQ(ResolveConflicts(&planes, GroupingOptions{}).size(), 1u);
  EXPECT_EQ(planes[0].id, "west");

  // Nor a plane of one line: the cut needs a face, not a fragment.
  RoofPlaneHypothesis one_line =
      WithSimilarity(Face("one", south_n, corner, 0, 0, 8, 4.5, 1), 0.8, 1);
  one_line.lines_xy = {south.lines_xy[0]};
  planes = {west, one_line};
  ASSERT_EQ(ResolveConflicts(&planes, GroupingOptions{}).size(), 1u);
  EXPECT_EQ(planes[0].id, "west");

  // A derived hip end (MirroredHipEnds) has no supporting line but carries
  // the mirrored lines of the end it came from; those tell a face as well.
  RoofPlaneHypothesis derived = south;
  derived.id = "derived";
  derived.derived = true;
  derived.lines = 0;
  derived.longest_line_m = 0;
  planes = {west, derived};
  EXPECT_TRUE(ResolveConflicts(&planes, GroupingOptions{}).empty());
  ASSERT_EQ(planes.size(), 2u);
  EXPECT_NEAR(std::abs(SignedArea(planes[1].patch)), 36 - 0.5 * 4.5 * 4.5, 1e-6);
  // A found plane is held to its supporting lines.
  RoofPlaneHypothesis unsupported = derived;
  unsupported.derived = false;
  planes = {west, unsupported};
  ASSERT_EQ(ResolveConflicts(&planes, GroupingOptions{}).size(), 1u);
  EXPECT_EQ(planes[0].id, "west");
}

TEST(PlaneGrouping, AFlatPlaneUnderARidgeLineGivesWayToTheFacesThatHoldIt) {
  // The top of a mansard roof: two faces of 10 deg rise from the break
  // lines (x = 0 and x = 5, z = 10) to a ridge 0.44 m higher. The flat
  // plane through the break lines covers both faces and beats each by its
  // area; the faces fit the images better, but by less than the 0.1 gain.
  const double t = std::tan(10 * M_PI / 180);
  const Eigen::Vector3d west_n = Eigen::Vector3d(-t, 0, 1).normalized();
  const Eigen::Vector3d east_n = Eigen::Vector3d(t, 0, 1).normalized();
  const Eigen::Vector3d ridge(2.5, 0, 10 + 2.5 * t);
  auto face = [](const RoofPlaneHypothesis& h, double sim) {
    return WithSimilarity(h, sim, 3, 10);
  };
  const std::array<Eigen::Vector2d, 2> ridge_xy = {Eigen::Vector2d(2.5, 3),
                                                   Eigen::Vector2d(2.5, 7)};
  RoofPlaneHypothesis flat = face(Face("flat", {0, 0, 1}, {0, 0, 10}, 0, 0, 5, 10, 50), 0.84);
  flat.lines_xy = {{Eigen::Vector2d(0, 0), Eigen::Vector2d(0, 10)},
                   {Eigen::Vector2d(5, 0), Eigen::Vector2d(5, 10)}};
  RoofPlaneHypothesis west = face(Face("west", west_n, ridge, 0, 0, 2.5, 10, 25), 0.90);
  west.lines_xy = {{Eigen::Vector2d(0, 0), Eigen::Vector2d(0, 10)}, ridge_xy};
  RoofPlaneHypothesis east = face(Face("east", east_n, ridge, 2.5, 0, 5, 10, 25), 0.88);
  east.lines_xy = {{Eigen::Vector2d(5, 0), Eigen::Vector2d(5, 10)}, ridge_xy};

  std::vector<RoofPlaneHypothesis> planes = {flat, west, east};
  std::vector<std::string> rejected = ResolveConflicts(&planes, GroupingOptions{});
  ASSERT_EQ(planes.size(), 2u);
  EXPECT_EQ(planes[0].id, "west");
  EXPECT_EQ(planes[1].id, "east");
  ASSERT_EQ(rejected.size(), 1u);
  EXPECT_EQ(rejected[0].rfind(
                "flat: overlaps 2 planes that each fit the images better or hold a line off it", 0),
            0u)
      << rejected[0];

  // Without the ridge line the faces are only a little better: the flat
  // plane stays, as it does with the rule off.
  GroupingOptions off;
  off.conflict_replace_min_step_m = 0;
  planes = {flat, west, east};
  ASSERT_EQ(ResolveConflicts(&planes, off).size(), 2u);
  EXPECT_EQ(planes[0].id, "flat");
  RoofPlaneHypothesis west_eave = west, east_eave = east;
  west_eave.lines_xy.pop_back();
  east_eave.lines_xy.pop_back();
  planes = {flat, west_eave, east_eave};
  ASSERT_EQ(ResolveConflicts(&planes, GroupingOptions{}).size(), 2u);
  EXPECT_EQ(planes[0].id, "flat");

  // A ridge line less than 0.4 m above the flat plane (7 deg faces) is
  // within what the grouping lets a line stray from its plane.
  const double t7 = std::tan(7 * M_PI / 180);
  const Eigen::Vector3d low_ridge(2.5, 0, 10 + 2.5 * t7);
  RoofPlaneHypothesis west7 = west, east7 = east;
  west7.plane << Eigen::Vector3d(-t7, 0, 1).normalized(), 0;
  west7.plane[3] = -west7.plane.head<3>().dot(low_ridge);
  east7.plane << Eigen::Vector3d(t7, 0, 1).normalized(), 0;
  east7.plane[3] = -east7.plane.head<3>().dot(low_ridge);
  planes = {flat, west7, east7};
  ASSERT_EQ(ResolveConflicts(&planes, GroupingOptions{}).size(), 2u);
  EXPECT_EQ(planes[0].id, "flat");
}

// Two terraced houses, 7 and 8 m wide, whose north faces (36.9 deg) have
// ridges 1.2 m apart in height; one plane carried over both beats each
// face alone by its area, though each face fits the images better.
struct Terrace {
  Eigen::Vector3d north = Eigen::Vector3d(0, 3, 4).normalized();
  RoofPlaneHypothesis west =
      WithSimilarity(Face("west", north, {0, 0, 9.2}, 0, 0, 7, 5.6, 7 * 5.6), 0.93);
  RoofPlaneHypothesis east =
      WithSimilarity(Face("east", north, {0, 0, 8.0}, 7, 0, 15, 5.6, 8 * 5.6), 0.89);
  RoofPlaneHypothesis across =
      WithSimilarity(Face("across", north, {0, 0, 8.6}, 0, 0, 15, 5.6, 15 * 5.6), 0.74);
};

TEST(PlaneGrouping, APlaneAcrossTwoFacesGivesWayToTheFacesTogether) {
  const Terrace t;
  const Eigen::Vector3d& north = t.north;
  const RoofPlaneHypothesis &west = t.west, &east = t.east, &across = t.across;
  // The faces replace the plane whole here; cut across its width, one face
  // would replace its part of it (see the next test).
  GroupingOptions whole;
  whole.conflict_cut_across_fall = false;
  std::vector<RoofPlaneHypothesis> planes = {across, west, east};
  std::vector<std::string> rejected = ResolveConflicts(&planes, whole);
  ASSERT_EQ(planes.size(), 2u);
  EXPECT_EQ(planes[0].id, "west");
  EXPECT_EQ(planes[1].id, "east");
  ASSERT_EQ(rejected.size(), 1u);
  EXPECT_EQ(rejected[0].rfind("across: overlaps 2 planes that each fit the images better", 0), 0u)
      << rejected[0];
  EXPECT_NE(rejected[0].find("west"), std::string::npos);
  EXPECT_NE(rejected[0].find("east"), std::string::npos);

  // Without the rule, the pairwise order keeps the large plane.
  GroupingOptions off = whole;
  off.conflict_replace_by_several = false;
  planes = {across, west, east};
  rejected = ResolveConflicts(&planes, off);
  ASSERT_EQ(planes.size(), 1u);
  EXPECT_EQ(planes[0].id, "across");
  EXPECT_EQ(rejected.size(), 2u);

  // A face that fits the images worse than the large plane does not count
  // towards replacing it, and one face alone never does.
  planes = {across, west,
            WithSimilarity(Face("east", north, {0, 0, 8.0}, 7, 0, 15, 5.6, 8 * 5.6), 0.70)};
  ASSERT_EQ(ResolveConflicts(&planes, whole).size(), 2u);
  EXPECT_EQ(planes[0].id, "across");

  // Nor do faces that fit the images only a little better: pieces of one
  // face seen as two.
  planes = {across, WithSimilarity(Face("west", north, {0, 0, 9.2}, 0, 0, 7, 5.6, 7 * 5.6), 0.8),
            WithSimilarity(Face("east", north, {0, 0, 8.0}, 7, 0, 15, 5.6, 8 * 5.6), 0.8)};
  ASSERT_EQ(ResolveConflicts(&planes, whole).size(), 2u);
  EXPECT_EQ(planes[0].id, "across");

  // Nor do planes of one line (the grouping's minimum is two) ...
  planes = {across, west,
            WithSimilarity(Face("east", north, {0, 0, 8.0}, 7, 0, 15, 5.6, 8 * 5.6), 0.89, 1)};
  ASSERT_EQ(ResolveConflicts(&planes, whole).size(), 2u);
  EXPECT_EQ(planes[0].id, "across");

  // ... nor fragments: five small planes of short lines that fit a few
  // samples well outweigh the large plane together.
  planes = {across};
  for (int i = 0; i < 5; ++i)
    planes.push_back(WithSimilarity(
        Face("piece " + std::to_string(i), north, {0, 0, 8.6}, 3 * i, 0, 3 * i + 3, 5.6, 40), 0.9,
        2, 2.5));
  const std::vector<RoofPlaneHypothesis> pieces = planes;
  ASSERT_EQ(ResolveConflicts(&planes, whole).size(), 5u);
  EXPECT_EQ(planes[0].id, "across");
  GroupingOptions short_lines = whole;
  short_lines.conflict_replace_min_line_m = 2.5;
  planes = pieces;
  EXPECT_EQ(ResolveConflicts(&planes, short_lines).size(), 1u);
  EXPECT_EQ(planes.size(), 5u);

  // Nor do faces whose evidence together is less than the large plane's.
  const RoofPlaneHypothesis big_across =
      WithSimilarity(Face("across", north, {0, 0, 8.6}, 0, 0, 15, 5.6, 2.0 * 15 * 5.6), 0.74);
  planes = {big_across, west, east};
  ASSERT_EQ(ResolveConflicts(&planes, whole).size(), 2u);
  EXPECT_EQ(planes[0].id, "across");

  // Nor a face that also conflicts with another kept plane: a stronger
  // plane over the east house's place keeps it out, and the west face
  // alone does not replace the large plane.
  const RoofPlaneHypothesis other =
      WithSimilarity(Face("other", north, {0, 0, 8.0}, 10, 0, 20, 5.6, 1000), 0.95);
  planes = {across, west, east, other};
  rejected = ResolveConflicts(&planes, whole);
  ASSERT_EQ(planes.size(), 2u);
  EXPECT_EQ(planes[0].id, "across");
  EXPECT_EQ(planes[1].id, "other");
}

TEST(PlaneGrouping, AFaceAcrossAPlanesDepthCutsItThere) {
  // A gabled house between two shed roofs in a terraced row: one shed
  // plane carried over the whole row (18 m) beats the gable's two faces
  // (6 m wide) by its area; the gable's ridge runs 2.9 m above it.
  const double t15 = std::tan(15 * kDeg), t40 = std::tan(40 * kDeg);
  const Eigen::Vector3d shed_n = Eigen::Vector3d(0, -t15, 1).normalized();  // rises to +y
  const Eigen::Vector3d south_n = Eigen::Vector3d(0, -t40, 1).normalized();
  const Eigen::Vector3d north_n = Eigen::Vector3d(0, t40, 1).normalized();
  RoofPlaneHypothesis shed =
      WithSimilarity(Face("shed", shed_n, {0, 0, 6}, 0, 0, 18, 10, 180), 0.8, 4, 18);
  const Eigen::Vector3d ridge(6, 5, 6 + 5 * t40);
  RoofPlaneHypothesis south =
      WithSimilarity(Face("south", south_n, ridge, 6, 0, 12, 5, 30), 0.9, 3, 6);
  RoofPlaneHypothesis north =
      WithSimilarity(Face("north", north_n, ridge, 6, 5, 12, 10, 30), 0.85, 3, 6);
  const std::array<Eigen::Vector2d, 2> ridge_xy = {Eigen::Vector2d(6, 5), Eigen::Vector2d(12, 5)};
  south.lines_xy = {ridge_xy, {Eigen::Vector2d(6, 0), Eigen::Vector2d(12, 0)}};
  north.lines_xy = {ridge_xy, {Eigen::Vector2d(6, 10), Eigen::Vector2d(12, 10)}};

  std::vector<RoofPlaneHypothesis> planes = {shed, south, north};
  GroupingOptions off;
  off.conflict_cut_across_fall = false;
  ResolveConflicts(&planes, off);
  ASSERT_EQ(planes.size(), 1u);
  EXPECT_EQ(planes[0].id, "shed");

  planes = {shed, south, north};
  std::vector<std::string> notes = ResolveConflicts(&planes, GroupingOptions{});
  ASSERT_EQ(planes.size(), 4u);
  EXPECT_EQ(planes[0].id, "shed");
  EXPECT_EQ(planes[1].id, "shed part 2");
  EXPECT_EQ(planes[2].id, "south");
  EXPECT_EQ(planes[3].id, "north");
  // The pieces beside the gable, each 6 m wide, their scores with them.
  for (int k : {0, 1}) {
    EXPECT_NEAR(SignedArea(planes[k].patch), 60, 1e-6);
    EXPECT_NEAR(planes[k].score, 60 * 0.8, 1e-6);
  }
  ASSERT_FALSE(notes.empty());
  EXPECT_EQ(notes[0].rfind("shed: cut across its fall line where 2 plane(s) hold a line off it", 0),
            0u)
      << notes[0];

  // A dormer's faces, over half of the face's depth, do not cut it.
  RoofPlaneHypothesis dormer_s = south, dormer_n = north;
  for (RoofPlaneHypothesis* d : {&dormer_s, &dormer_n})
    for (Eigen::Vector2d& x : d->patch) x.y() = 2.5 + 0.5 * x.y();
  planes = {shed, dormer_s, dormer_n};
  ResolveConflicts(&planes, GroupingOptions{});
  EXPECT_EQ(planes[0].id, "shed");
  for (const RoofPlaneHypothesis& q : planes) EXPECT_NE(q.id, "shed part 2");

  // Nor do faces that fit the images worse than the plane, nor a sliver
  // of a face narrower than 3 m.
  planes = {shed, WithSimilarity(Face("south", south_n, ridge, 6, 0, 12, 5, 30), 0.7, 3, 6),
            WithSimilarity(Face("north", north_n, ridge, 6, 5, 12, 10, 30), 0.7, 3, 6)};
  planes[1].lines_xy = south.lines_xy;
  planes[2].lines_xy = north.lines_xy;
  ResolveConflicts(&planes, GroupingOptions{});
  ASSERT_EQ(planes.size(), 1u);
  EXPECT_EQ(planes[0].id, "shed");
  // The gable's faces moved to x0..x1 along the row.
  auto gable_at = [&](double x0, double x1) {
    std::vector<RoofPlaneHypothesis> faces = {south, north};
    for (RoofPlaneHypothesis& f : faces)
      for (Eigen::Vector2d& x : f.patch) x.x() = x.x() == 6 ? x0 : x1;
    return faces;
  };
  const std::vector<RoofPlaneHypothesis> narrow = gable_at(8, 10);
  planes = {shed, narrow[0], narrow[1]};
  ResolveConflicts(&planes, GroupingOptions{});
  ASSERT_EQ(planes.size(), 1u);
  EXPECT_EQ(planes[0].id, "shed");

  // Nor a face that roofs less than half of the strip it would take: a
  // slanting sliver across the row.
  RoofPlaneHypothesis sliver = south;
  sliver.id = "sliver";
  sliver.patch = {{6, 0}, {7, 0}, {12, 10}, {11, 10}};
  sliver.lines_xy = {{Eigen::Vector2d(6.5, 0), Eigen::Vector2d(11.5, 10)}};
  sliver.score = 10 * sliver.similarity;
  planes = {shed, sliver};
  ResolveConflicts(&planes, GroupingOptions{});
  ASSERT_EQ(planes.size(), 1u);
  EXPECT_EQ(planes[0].id, "shed");

  // A cut whose faces do not all stay is undone: a stronger plane over the
  // north face keeps it out, and the shed stays whole beside it.
  const RoofPlaneHypothesis other =
      WithSimilarity(Face("other", north_n, ridge, 6.5, 6.2, 11.5, 14, 500), 0.9);
  planes = {shed, south, north, other};
  notes = ResolveConflicts(&planes, GroupingOptions{});
  ASSERT_EQ(planes.size(), 2u);
  EXPECT_EQ(planes[0].id, "shed");
  EXPECT_NEAR(SignedArea(planes[0].patch), 180, 1e-6);
  EXPECT_EQ(planes[1].id, "other");
  for (const std::string& why : notes) EXPECT_EQ(why.find("cut across"), std::string::npos) << why;

  // A flat plane is cut along the steepest face's fall line: a shed roof
  // between two flat roofs at its eave's height.
  RoofPlaneHypothesis flat =
      WithSimilarity(Face("flat", {0, 0, 1}, {0, 0, 6}, 0, 0, 18, 10, 180), 0.7, 4, 18);
  RoofPlaneHypothesis mid =
      WithSimilarity(Face("mid", shed_n, {0, 0, 6}, 6, 0, 12, 10, 60), 0.8, 3, 10);
  mid.lines_xy = {{Eigen::Vector2d(6, 10), Eigen::Vector2d(12, 10)}};  // its top, 2.7 m up
  planes = {flat, mid};
  ResolveConflicts(&planes, GroupingOptions{});
  ASSERT_EQ(planes.size(), 3u);
  EXPECT_EQ(planes[0].id, "flat");
  EXPECT_EQ(planes[1].id, "flat part 2");
  EXPECT_EQ(planes[2].id, "mid");

  // Nor is a piece narrower than 3 m kept beside the faces: the gable at
  // the row's end leaves one piece only.
  const std::vector<RoofPlaneHypothesis> at_end = gable_at(1, 7);
  planes = {shed, at_end[0], at_end[1]};
  ResolveConflicts(&planes, GroupingOptions{});
  ASSERT_EQ(planes.size(), 3u);
  EXPECT_EQ(planes[0].id, "shed");
  EXPECT_NEAR(SignedArea(planes[0].patch), 110, 1e-6);
}

TEST(PlaneGrouping, APlanePushedOutByAReplacedPlaneIsDecidedAgain) {
  // The terraced faces replace the plane across them;
  // a lower roof in front of them (a flat annex, 4 x 7.6 m) had lost to that
  // plane (74 % of it under its patch) but overlaps neither face by more
  // than half.
  const Terrace t;
  const Eigen::Vector3d& north = t.north;
  const RoofPlaneHypothesis &west = t.west, &east = t.east, &across = t.across;
  const RoofPlaneHypothesis annex =
      WithSimilarity(Face("annex", {0, 0, 1}, {0, 0, 3}, 5.5, -2, 9.5, 5.6, 30), 0.8);
  std::vector<RoofPlaneHypothesis> planes = {across, west, east, annex};
  std::vector<std::string> rejected = ResolveConflicts(&planes, GroupingOptions{});
  ASSERT_EQ(planes.size(), 3u);
  EXPECT_EQ(planes[0].id, "west");
  EXPECT_EQ(planes[1].id, "east");
  EXPECT_EQ(planes[2].id, "annex");
  ASSERT_EQ(rejected.size(), 1u);
  EXPECT_EQ(rejected[0].rfind("across: overlaps 2 planes", 0), 0u) << rejected[0];

  // Without deciding again it stays out for a plane that is not built.
  GroupingOptions once;
  once.conflict_redecide = false;
  planes = {across, west, east, annex};
  rejected = ResolveConflicts(&planes, once);
  ASSERT_EQ(planes.size(), 2u);
  ASSERT_EQ(rejected.size(), 2u);
  EXPECT_EQ(rejected[1].rfind("annex: overlaps the stronger across", 0), 0u) << rejected[1];

  // Decided again, a plane the replaced one had pushed out does not push
  // out the faces that replaced it: an annex as strong as the faces, over
  // the east face by 46 % but past the 50 % with a face grown a little,
  // stays out.
  const RoofPlaneHypothesis wide_east =
      WithSimilarity(Face("east", north, {0, 0, 8.0}, 6.5, 0, 15, 5.6, 8.5 * 5.6), 0.89);
  const RoofPlaneHypothesis strong_annex =
      WithSimilarity(Face("annex", {0, 0, 1}, {0, 0, 3}, 5.5, -2, 9.5, 5.6, 55), 0.8);
  planes = {across, west, wide_east, strong_annex};
  rejected = ResolveConflicts(&planes, GroupingOptions{});
  ASSERT_EQ(planes.size(), 2u);
  EXPECT_EQ(planes[0].id, "west");
  EXPECT_EQ(planes[1].id, "east");
}

TEST(PlaneGrouping, WholePipelineGivesAClosedGable) {
  Gable g;
  const std::vector<HalfPlane> hps = {
      Accepted(g.lines, 0, -1, g.south, 4.0), Accepted(g.lines, 0, +1, g.north, 4.0),
      Accepted(g.lines, 1, +1, g.south, 2.0), Accepted(g.lines, 2, -1, g.north, 2.0)};
  GroundModel ground;
  ground.height = 0.0;
  const AssemblyResult r =
      AssembleBuildings(ToRoofPlanes(GroupHalfPlanes(g.lines, hps).planes), ground);
  ASSERT_EQ(r.model.buildings.size(), 1u);
  EXPECT_EQ(r.model.buildings[0].roof_type, roof_type::kGabled);
  EXPECT_NEAR(r.model.buildings[0].measured_height, 8.0, 1e-6);
}

}  // namespace
}  // namespace roofsweep

namespace roofsweep {
namespace {

// A one-line plane from its patch (plan rectangle) on z = z0 + sx x + sy y.
PlaneGroup OneLinePlane(int line, double x0, double y0, double x1, double y1, double z0, double sx,
                        double sy) {
  PlaneGroup g;
  Eigen::Vector3d n(-sx, -sy, 1);
  n.normalize();
  g.plane << n, -n.z() * z0;
  g.patch = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  g.lines = {line};
  return g;
}

// §5: "at least two lines (one of them can be virtual)". Both faces of a
// gable with only their eaves matched meet at the ridge: each has a
// virtual line. A lone one-line plane, one whose neighbour lies on its own
// side of the intersection, and one too far from its neighbour have none.
TEST(PlaneGrouping, AVirtualLineWithANeighbourCountsAsASecondLine) {
  const double t = std::tan(35 * M_PI / 180);
  GroupingOptions o;
  {
    // Ridge along x at y = 4, z = 10; faces fall to y = 0 and y = 8.
    std::vector<PlaneGroup> planes = {OneLinePlane(1, 0, 0.2, 10, 3.8, 10 - 4 * t, 0, t),
                                      OneLinePlane(2, 0, 4.2, 10, 7.8, 10 + 4 * t, 0, -t)};
    EXPECT_TRUE(VirtualLine(planes[0], planes[1], o));
    const auto reasons = DropWeaklySupported(&planes, o);
    EXPECT_EQ(planes.size(), 2u);
    EXPECT_TRUE(reasons.empty());
    o.virtual_lines = false;
    EXPECT_EQ(DropWeaklySupported(&planes, o).size(), 2u);
    EXPECT_TRUE(planes.empty());
    o.virtual_lines = true;
  }
  {
    // The same faces 3 m apart (beyond max_gap_m of the intersection).
    std::vector<PlaneGroup> planes = {OneLinePlane(1, 0, -2.8, 10, 0.8, 10 - 4 * t, 0, t),
                                      OneLinePlane(2, 0, 7.2, 10, 10.8, 10 + 4 * t, 0, -t)};
    EXPECT_FALSE(VirtualLine(planes[0], planes[1], o));
  }
  {
    // Two planes over one patch (a plane and a wrong one crossing it).
    const PlaneGroup a = OneLinePlane(1, 0, 0, 10, 4, 8, 0, 0);
    const PlaneGroup b = OneLinePlane(2, 0, 0, 10, 4, 6, 0, t);
    EXPECT_FALSE(VirtualLine(a, b, o));
  }
  {
    // A lone plane.
    std::vector<PlaneGroup> planes = {OneLinePlane(1, 0, 0, 10, 4, 8, 0, t)};
    EXPECT_EQ(DropWeaklySupported(&planes, o).size(), 1u);
  }
  {
    // Nearly coplanar neighbours (5 degrees apart) make no virtual line.
    const double t5 = std::tan(5 * M_PI / 180);
    const PlaneGroup a = OneLinePlane(1, 0, 0, 10, 4, 8, 0, 0);
    const PlaneGroup b = OneLinePlane(2, 0, 4.2, 10, 8, 8 - 4 * t5, 0, t5);
    EXPECT_FALSE(VirtualLine(a, b, o));
  }
}

// A hip end's rectangular patch runs across the hip into the long face:
// the hip cuts a corner off it. Here the end (falling east, eaves at
// x = 10) has a quarter of its patch across the hip, the long face (falling
// south, eaves at y = 0) an eighth: they meet along it (`realistic-7`
// BLDG_0022, whose two hip ends went as orphans on every seed).
TEST(PlaneGrouping, AHipEndMeetsTheLongFaceAcrossACornerOfItsPatch) {
  const double t = std::tan(35 * M_PI / 180);
  const PlaneGroup end = OneLinePlane(1, 8, 0, 10, 4, 10 * t, -t, 0);
  const PlaneGroup face = OneLinePlane(2, 0, 0, 9, 4, 0, 0, t);
  GroupingOptions o;
  EXPECT_TRUE(VirtualLine(end, face, o));
  EXPECT_TRUE(VirtualLine(face, end, o));
  // Half of the end's patch across: a plane through the other, not beside it.
  EXPECT_FALSE(VirtualLine(OneLinePlane(1, 6, 0, 10, 4, 10 * t, -t, 0), face, o));
  o.virtual_max_across = 0.2;
  EXPECT_FALSE(VirtualLine(end, face, o));
}

TEST(PlaneGrouping, APlaneWhoseVirtualLinePartnerIsRejectedGoesToo) {
  // The gable of the test above as roof planes: a one-line face and a
  // three-line face meeting at the ridge, and a one-line plane 30 m away
  // kept by a neighbour of its own (a two-line plane beside it).
  const double t = std::tan(35 * M_PI / 180);
  const GroupingOptions o;
  std::vector<PlaneGroup> groups = {OneLinePlane(1, 0, 0.2, 10, 3.8, 10 - 4 * t, 0, t),
                                    OneLinePlane(2, 0, 4.2, 10, 7.8, 10 + 4 * t, 0, -t),
                                    OneLinePlane(3, 30, 0.2, 40, 3.8, 10 - 4 * t, 0, t),
                                    OneLinePlane(4, 30, 4.2, 40, 7.8, 10 + 4 * t, 0, -t)};
  groups[1].lines = {2, 5, 6};
  groups[3].lines = {4, 7};
  std::vector<RoofPlaneHypothesis> planes = ToRoofPlanes(groups);
  EXPECT_TRUE(DropOrphanedPlanes(&planes, o).empty());
  ASSERT_EQ(planes.size(), 4u);
  // The ridge's three-line partner is rejected (say by the verification):
  // the one-line face loses its virtual line; the far pair is untouched.
  planes.erase(planes.begin() + 1);
  const std::vector<std::string> reasons = DropOrphanedPlanes(&planes, o);
  ASSERT_EQ(reasons.size(), 1u);
  EXPECT_NE(reasons[0].find("plane 0 (line 1)"), std::string::npos) << reasons[0];
  ASSERT_EQ(planes.size(), 2u);
  EXPECT_EQ(planes[0].id, "plane 2 (line 3)");
  // Planes with two real lines stand alone.
  planes.erase(planes.begin());
  EXPECT_TRUE(DropOrphanedPlanes(&planes, o).empty());
  EXPECT_EQ(planes.size(), 1u);
}

// A garage's flat roof (three lines) under a stronger sloped plane of one
// line, say a wall top swept at the wrong angle, that meets no other plane.
// A garage on `easy` was lost to such a plane, which the orphan check then
// dropped as well. Settled with the orphans first, the garage stays.
TEST(PlaneGrouping, APlaneThatWillBeOrphanedPushesNoPlaneOut) {
  const GroupingOptions o;
  const Eigen::Vector3d up(0, 0, 1), tilted = Eigen::Vector3d(0, -0.5, 1).normalized();
  auto planes = [&] {
    return std::vector<RoofPlaneHypothesis>{
        WithSimilarity(Face("wall top", tilted, {0, 0, -5}, -5, -1, 10, 4, 60), 0.6, 1),
        WithSimilarity(Face("garage", up, {0, 0, 3}, 0, 0, 3, 3, 9), 0.8, 3, 3)};
  };
  // The conflicts alone, then the orphans: both go.
  std::vector<RoofPlaneHypothesis> apart = planes();
  const std::vector<std::string> conflicts = ResolveConflicts(&apart, o);
  ASSERT_EQ(conflicts.size(), 1u);
  EXPECT_EQ(conflicts[0].rfind("garage: overlaps the stronger wall top", 0), 0u) << conflicts[0];
  EXPECT_EQ(DropOrphanedPlanes(&apart, o).size(), 1u);
  EXPECT_TRUE(apart.empty());

  std::vector<RoofPlaneHypothesis> settled = planes();
  const std::vector<std::string> reasons = SettleVerifiedPlanes(&settled, o);
  ASSERT_EQ(reasons.size(), 1u);
  EXPECT_EQ(reasons[0].rfind("wall top: 1 supporting line(s) < 2", 0), 0u) << reasons[0];
  ASSERT_EQ(settled.size(), 1u);
  EXPECT_EQ(settled[0].id, "garage");
}

TEST(PlaneGrouping, PlanesNeedTwoLines) {
  std::vector<PlaneGroup> planes(3);
  planes[0].lines = {4};
  planes[1].lines = {1, 2};
  planes[2].lines = {};
  GroupingOptions o;
  o.min_lines = 2;
  const std::vector<std::string> reasons = DropWeaklySupported(&planes, o);
  ASSERT_EQ(planes.size(), 1u);
  EXPECT_EQ(planes[0].lines, (std::vector<int>{1, 2}));
  ASSERT_EQ(reasons.size(), 2u);
  EXPECT_NE(reasons[0].find("plane of line 4: 1 supporting line(s) < 2"), std::string::npos);
}

}  // namespace
}  // namespace roofsweep
