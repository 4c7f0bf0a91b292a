#include "algorithms/buildings/mirror_completion.h"

#include <gtest/gtest.h>

#include <cmath>

#include "algorithms/buildings/convex_polygon2.h"
#include "algorithms/buildings/test_planes.h"

namespace roofsweep {
namespace {

// The south face of a gable 10 m along x: ridge at y = 4, z = 8, falling
// to the eave at y = 0, z = 6 (26.6 degrees).
RoofPlaneHypothesis SouthFace() {
  RoofPlaneHypothesis p;
  p.id = "south";
  const Eigen::Vector3d n = Eigen::Vector3d(0, -2, 4).normalized();
  p.plane << n, -n.dot(Eigen::Vector3d(0, 4, 8));
  // Its patch runs half a metre past the ridge, as patches do.
  p.patch = {{0, 0}, {10, 0}, {10, 4.5}, {0, 4.5}};
  p.lines = 2;
  p.lines_xy = {{Eigen::Vector2d(0, 0), Eigen::Vector2d(10, 0)},      // eave
                {Eigen::Vector2d(0.5, 4), Eigen::Vector2d(9.5, 4)}};  // ridge
  p.score = 10;
  return p;
}

double PlaneZ(const RoofPlaneHypothesis& p, double x, double y) {
  return -(p.plane[0] * x + p.plane[1] * y + p.plane[3]) / p.plane[2];
}

TEST(MirroredFaces, AFaceWithARidgeProposesTheFaceBeyondIt) {
  const std::vector<RoofPlaneHypothesis> out = MirroredFaces({SouthFace()});
  ASSERT_EQ(out.size(), 1u);
  const RoofPlaneHypothesis& q = out[0];
  EXPECT_TRUE(q.derived);
  EXPECT_EQ(q.id, "south mirrored");
  // The north face: 8 m at the ridge, 6 m at y = 8.
  EXPECT_NEAR(PlaneZ(q, 3, 4), 8.0, 1e-9);
  EXPECT_NEAR(PlaneZ(q, 7, 8), 6.0, 1e-9);
  // Over the south patch below the ridge, reflected: y in [4, 8].
  EXPECT_NEAR(std::abs(SignedArea(q.patch)), 40.0, 1e-9);
  for (const auto& v : q.patch) {
    EXPECT_GE(v.y(), 4 - 1e-9);
    EXPECT_LE(v.y(), 8 + 1e-9);
  }
  ASSERT_EQ(q.lines_xy.size(), 1u);
  EXPECT_NEAR(q.lines_xy[0][0].y(), 4.0, 1e-12);
}

TEST(MirroredFaces, NothingWithoutARidgeOrWhereTheOtherFaceIsFound) {
  RoofPlaneHypothesis eave_only = SouthFace();
  eave_only.lines_xy.pop_back();
  EXPECT_TRUE(MirroredFaces({eave_only}).empty());

  // The north face is there already.
  const std::vector<RoofPlaneHypothesis> north = MirroredFaces({SouthFace()});
  ASSERT_EQ(north.size(), 1u);
  RoofPlaneHypothesis found = north[0];
  found.derived = false;
  EXPECT_TRUE(MirroredFaces({SouthFace(), found}).empty());

  // A ridge line with most of the patch above it is not the top of the face.
  RoofPlaneHypothesis low = SouthFace();
  low.lines_xy[1] = {Eigen::Vector2d(0.5, 1), Eigen::Vector2d(9.5, 1)};
  EXPECT_TRUE(MirroredFaces({low}).empty());

  // Flat roofs and walls are not mirrored.
  RoofPlaneHypothesis flat = SouthFace();
  flat.plane << 0, 0, 1, -6;
  EXPECT_TRUE(MirroredFaces({flat}).empty());
}

// A garden shed's gable: 2.6 m along x, each face 1.2 m deep at 34 degrees
// (the simulator's outbuildings), its patch 3.4 m2.
TEST(MirroredFaces, AShedsFaceProposesItsOtherFace) {
  RoofPlaneHypothesis p;
  p.id = "shed";
  const double rise = std::tan(0.6) * 1.2;
  const Eigen::Vector3d n = Eigen::Vector3d(0, -rise, 1.2).normalized();
  p.plane << n, -n.dot(Eigen::Vector3d(0, 1.2, 2.2 + rise));
  p.patch = {{0, 0}, {2.6, 0}, {2.6, 1.3}, {0, 1.3}};
  p.lines = 2;
  p.lines_xy = {{Eigen::Vector2d(0, 0), Eigen::Vector2d(2.6, 0)},
                {Eigen::Vector2d(0.1, 1.2), Eigen::Vector2d(2.5, 1.2)}};
  p.score = 1;
  const std::vector<RoofPlaneHypothesis> out = MirroredFaces({p});
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NEAR(std::abs(SignedArea(out[0].patch)), 2.6 * 1.2, 1e-9);
  EXPECT_NEAR(PlaneZ(out[0], 1, 2.4), 2.2, 1e-9);

  // A face of a tenth of that proposes nothing.
  RoofPlaneHypothesis tiny = p;
  for (auto& v : tiny.patch) v *= std::sqrt(0.1);
  for (auto& l : tiny.lines_xy)
    for (auto& v : l) v *= std::sqrt(0.1);
  MirrorCompletionOptions short_ridge;
  short_ridge.ridge_min_length_m = 0.5;
  EXPECT_TRUE(MirroredFaces({tiny}, short_ridge).empty());
  short_ridge.min_patch_m2 = 0.1;  // it is the size that stops it
  EXPECT_EQ(MirroredFaces({tiny}, short_ridge).size(), 1u);
}

// The ridge's matched piece is too short (the faces are of one colour),
// and the north face was found along 3 m of the ridge only: where the two
// planes meet is the ridge, and the whole north face is proposed.
TEST(MirroredFaces, TheRidgeIsWhereTheFaceMeetsAPlaneFallingTheOtherWay) {
  RoofPlaneHypothesis south = SouthFace();
  south.lines_xy[1] = {Eigen::Vector2d(4, 4), Eigen::Vector2d(5.5, 4)};  // 1.5 m
  RoofPlaneHypothesis north;
  north.id = "north part";
  const Eigen::Vector3d n = Eigen::Vector3d(0, 2, 4).normalized();
  north.plane << n, -n.dot(Eigen::Vector3d(0, 4, 8));
  north.patch = {{7, 4}, {10, 4}, {10, 8}, {7, 8}};
  north.lines = 2;
  const std::vector<RoofPlaneHypothesis> out = MirroredFaces({south, north});
  ASSERT_EQ(out.size(), 1u);
  const RoofPlaneHypothesis& q = out[0];
  EXPECT_EQ(q.id, "south mirrored");
  EXPECT_NEAR(PlaneZ(q, 3, 4), 8.0, 1e-9);
  EXPECT_NEAR(PlaneZ(q, 7, 8), 6.0, 1e-9);
  EXPECT_NEAR(std::abs(SignedArea(q.patch)), 40.0, 1e-9);
  ASSERT_EQ(q.lines_xy.size(), 1u);
  EXPECT_NEAR(q.lines_xy[0][0].y(), 4.0, 1e-9);
  EXPECT_NEAR((q.lines_xy[0][1] - q.lines_xy[0][0]).norm(), 10.0, 1e-9);

  MirrorCompletionOptions off;
  off.virtual_ridges = false;
  EXPECT_TRUE(MirroredFaces({south, north}, off).empty());

  // A plane rising the same way beyond is no ridge (a higher shed roof).
  RoofPlaneHypothesis same_way = north;
  const Eigen::Vector3d m = Eigen::Vector3d(0, -2, 4).normalized();
  same_way.plane << m, -m.dot(Eigen::Vector3d(0, 4, 9));
  EXPECT_TRUE(MirroredFaces({south, same_way}).empty());

  // Nor one 2 m away across a gap (another building).
  RoofPlaneHypothesis apart = north;
  for (auto& v : apart.patch) v.y() += 2;
  EXPECT_TRUE(MirroredFaces({south, apart}).empty());
}

// A hipped roof 12 x 6 m: ridge along x from -3 to 3 at z = 5, eaves at
// z = 2 on x = +-6 and y = +-3, every face at 45 degrees. `with_ends`:
// the west end (w), the east end (e).
std::vector<RoofPlaneHypothesis> HippedRoof(const std::string& with_ends) {
  auto face = [](const std::string& id, const Eigen::Vector3d& up_normal, const Eigen::Vector3d& on,
                 Ring2 patch) {
    RoofPlaneHypothesis p;
    p.id = id;
    const Eigen::Vector3d n = up_normal.normalized();
    p.plane << n, -n.dot(on);
    p.patch = std::move(patch);
    p.lines = 2;
    p.score = 10;
    return p;
  };
  std::vector<RoofPlaneHypothesis> roof = {
      face("south", {0, -1, 1}, {0, 0, 5}, {{-6, -3}, {6, -3}, {3, 0}, {-3, 0}}),
      face("north", {0, 1, 1}, {0, 0, 5}, {{-3, 0}, {3, 0}, {6, 3}, {-6, 3}})};
  if (with_ends.find('w') != std::string::npos) {
    roof.push_back(face("west", {-1, 0, 1}, {-3, 0, 5}, {{-6, -3}, {-3, 0}, {-6, 3}}));
    roof.back().lines_xy = {{Eigen::Vector2d(-6, -3), Eigen::Vector2d(-6, 3)},   // eave
                            {Eigen::Vector2d(-6, -3), Eigen::Vector2d(-3, 0)}};  // hip
  }
  if (with_ends.find('e') != std::string::npos)
    roof.push_back(face("east", {1, 0, 1}, {3, 0, 5}, {{6, -3}, {6, 3}, {3, 0}}));
  return roof;
}

TEST(MirroredHipEnds, AHipEndProposesTheOneAtTheOtherEndOfItsRidge) {
  const std::vector<RoofPlaneHypothesis> out = MirroredHipEnds(HippedRoof("w"));
  ASSERT_EQ(out.size(), 1u);
  const RoofPlaneHypothesis& q = out[0];
  EXPECT_TRUE(q.derived);
  EXPECT_EQ(q.id, "west mirrored along its ridge");
  EXPECT_EQ(q.lines, 0);  // no 3D line supports it
  // The east end: z = 5 at the ridge's end, 2 at the eave x = 6.
  EXPECT_NEAR(PlaneZ(q, 3, 0), 5.0, 1e-9);
  EXPECT_NEAR(PlaneZ(q, 6, -2), 2.0, 1e-9);
  EXPECT_NEAR(std::abs(SignedArea(q.patch)), 9.0, 1e-9);
  for (const auto& v : q.patch) EXPECT_GE(v.x(), 3 - 1e-9);
  // It carries the west end's lines mirrored: the east eave and hip.
  ASSERT_EQ(q.lines_xy.size(), 2u);
  EXPECT_NEAR(q.lines_xy[0][0].x(), 6.0, 1e-9);
  EXPECT_NEAR(q.lines_xy[0][1].x(), 6.0, 1e-9);
  EXPECT_NEAR(q.longest_line_m, 6.0, 1e-9);
}

TEST(MirroredHipEnds, TheLongFacesRunningOnToTheEndsGiveTheSameEnd) {
  // The long faces grown along the footprint to its ends, over the east
  // end (as the growth along footprints leaves them).
  std::vector<RoofPlaneHypothesis> roof = HippedRoof("w");
  roof[0].patch = {{-6, -3}, {6, -3}, {6, 0}, {-3, 0}};
  roof[1].patch = {{-3, 0}, {6, 0}, {6, 3}, {-6, 3}};
  const std::vector<RoofPlaneHypothesis> out = MirroredHipEnds(roof);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NEAR(PlaneZ(out[0], 3, 0), 5.0, 1e-9);
  EXPECT_NEAR(PlaneZ(out[0], 6, 1), 2.0, 1e-9);
}

TEST(MirroredHipEnds, NothingWhereBothEndsAreFoundOrThereIsNoHipEnd) {
  EXPECT_TRUE(MirroredHipEnds(HippedRoof("we")).empty());
  EXPECT_TRUE(MirroredHipEnds(HippedRoof("")).empty());
  // A face rising along the ridge in the middle of the roof (a dormer's
  // cheek, a fragment) is no end.
  std::vector<RoofPlaneHypothesis> roof = HippedRoof("");
  roof.push_back(roof[0]);
  roof.back().id = "middle";
  const Eigen::Vector3d n = Eigen::Vector3d(-1, 0, 1).normalized();
  roof.back().plane << n, -n.dot(Eigen::Vector3d(0, 0, 4));
  roof.back().patch = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  EXPECT_TRUE(MirroredHipEnds(roof).empty());
}

TEST(MirroredHipEnds, AFaceBesideTheLongFacesThatMeetsThemElsewhereIsNoEnd) {
  // A neighbour's face west of the roof, rising east as the west end
  // would, 3 m lower: its planes meet the long faces' at (0, 0, 5), far
  // from its patch, which is no end of theirs.
  std::vector<RoofPlaneHypothesis> roof = HippedRoof("");
  RoofPlaneHypothesis beside = HippedRoof("w")[2];
  beside.id = "beside";
  const Eigen::Vector3d n = Eigen::Vector3d(-1, 0, 1).normalized();
  beside.plane << n, -n.dot(Eigen::Vector3d(-6, 0, -1));
  beside.patch = {{-7, -3}, {-6.2, -3}, {-6.2, 3}, {-7, 3}};
  roof.push_back(beside);
  EXPECT_TRUE(MirroredHipEnds(roof).empty());
  // Without the test of where they meet it would be mirrored.
  HipEndMirrorOptions anywhere;
  anywhere.max_gap_m = 100;
  anywhere.apex_max_dz_m = 100;
  EXPECT_EQ(MirroredHipEnds(roof, anywhere).size(), 1u);
}

}  // namespace
// A mansard on a 10 x 8 m footprint (x along its length): steep lower
// faces (65 deg) 1.5 m deep from the eaves at z = 6 to the break at
// z = 9.22, shallow upper faces above. Its steep south face.
RoofPlaneHypothesis MansardSouthLowerFace() {
  RoofPlaneHypothesis p = TestPlane(SlopedPlane({5, 0, 6}, 65, -90),
                                    {{0, 0}, {10, 0}, {8.5, 1.5}, {1.5, 1.5}}, "south lower");
  p.lines_xy = {{Eigen::Vector2d(0, 0), Eigen::Vector2d(10, 0)}};
  p.similarity = 0.6;
  return p;
}

const Ring2 kRectangle = {{0, 0}, {10, 0}, {10, 8}, {0, 8}};

// The tests of one face alone: not left to the roof models beyond a ridge.
FootprintMirrorOptions AnyFace() {
  FootprintMirrorOptions o;
  o.leave_one_face = false;
  return o;
}

TEST(FacesMirroredAcrossFootprints, AMansardsSteepFaceProposesTheOneOppositeIt) {
  const std::vector<RoofPlaneHypothesis> out = FacesMirroredAcrossFootprints(
      {MansardSouthLowerFace()}, {TestFootprint("F1", kRectangle)}, AnyFace());
  ASSERT_EQ(out.size(), 1u);
  const RoofPlaneHypothesis& q = out[0];
  EXPECT_TRUE(q.derived);
  EXPECT_EQ(q.id, "south lower mirrored across footprint F1");
  // The north face: 6 m at the north eave (y = 8), rising southwards at
  // 65 deg to the break 1.5 m in.
  EXPECT_NEAR(PlaneZ(q, 2, 8), 6.0, 1e-9);
  EXPECT_NEAR(PlaneZ(q, 7, 6.5), 6 + 1.5 * std::tan(65 * M_PI / 180), 1e-9);
  EXPECT_NEAR(std::abs(SignedArea(q.patch)), 12.75, 1e-9);
  for (const auto& v : q.patch) EXPECT_GE(v.y(), 6.5 - 1e-9);
  ASSERT_EQ(q.lines_xy.size(), 1u);
  EXPECT_NEAR(q.lines_xy[0][0].y(), 8.0, 1e-12);
}

TEST(FacesMirroredAcrossFootprints, AHipEndProposesTheOtherEndAcrossTheShortAxis) {
  // The west end of a hipped roof: falling west from x = 3 at 40 deg.
  RoofPlaneHypothesis end =
      TestPlane(SlopedPlane({0, 4, 6}, 40, 180), {{0, 0}, {3, 4}, {0, 8}}, "west end");
  end.lines_xy = {{Eigen::Vector2d(0, 0), Eigen::Vector2d(0, 8)}};  // its eave
  const std::vector<RoofPlaneHypothesis> out =
      FacesMirroredAcrossFootprints({end}, {TestFootprint("F1", kRectangle)}, AnyFace());
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NEAR(PlaneZ(out[0], 10, 4), 6.0, 1e-9);
  EXPECT_NEAR(PlaneZ(out[0], 7, 4), 6 + 3 * std::tan(40 * M_PI / 180), 1e-9);
}

TEST(FacesMirroredAcrossFootprints, NothingWhereTheFootprintIsNoRectangle) {
  // An L: the rectangle with its north-east quarter taken out.
  const Ring2 ell = {{0, 0}, {10, 0}, {10, 4}, {5, 4}, {5, 8}, {0, 8}};
  EXPECT_TRUE(
      FacesMirroredAcrossFootprints({MansardSouthLowerFace()}, {TestFootprint("L", ell)}, AnyFace())
          .empty());
}

TEST(FacesMirroredAcrossFootprints, NothingForAFaceAcrossTheAxisOrOneMirroredAlready) {
  // A shed over the whole footprint is its own mirror image.
  const RoofPlaneHypothesis shed = TestPlane(SlopedPlane({5, 0, 4}, 8, -90), kRectangle, "shed");
  EXPECT_TRUE(
      FacesMirroredAcrossFootprints({shed}, {TestFootprint("F1", kRectangle)}, AnyFace()).empty());
  // A flat roof falls nowhere.
  const RoofPlaneHypothesis flat = TestPlane({0, 0, 1, -6}, {{0, 0}, {10, 0}, {10, 3}}, "flat");
  EXPECT_TRUE(
      FacesMirroredAcrossFootprints({flat}, {TestFootprint("F1", kRectangle)}, AnyFace()).empty());
  // The north face found already.
  const std::vector<RoofPlaneHypothesis> north = FacesMirroredAcrossFootprints(
      {MansardSouthLowerFace()}, {TestFootprint("F1", kRectangle)}, AnyFace());
  ASSERT_EQ(north.size(), 1u);
  RoofPlaneHypothesis found = north[0];
  found.derived = false;
  EXPECT_TRUE(FacesMirroredAcrossFootprints({MansardSouthLowerFace(), found},
                                            {TestFootprint("F1", kRectangle)}, AnyFace())
                  .empty());
  // The top strip of a shed rises away from the axis: its mirror image
  // would fall the wrong way.
  const RoofPlaneHypothesis shed_top =
      TestPlane(SlopedPlane({5, 8, 6}, 15, -90), {{0, 6}, {10, 6}, {10, 8}, {0, 8}}, "shed top");
  EXPECT_TRUE(
      FacesMirroredAcrossFootprints({shed_top}, {TestFootprint("F1", kRectangle)}, AnyFace())
          .empty());
  // A face with no line in plan gives an image the assembly would refuse.
  RoofPlaneHypothesis unlined = MansardSouthLowerFace();
  unlined.lines_xy.clear();
  EXPECT_TRUE(FacesMirroredAcrossFootprints({unlined}, {TestFootprint("F1", kRectangle)}, AnyFace())
                  .empty());
  // A face outside the footprint is not its face.
  RoofPlaneHypothesis away = MansardSouthLowerFace();
  for (auto& v : away.patch) v.y() -= 20;
  EXPECT_TRUE(
      FacesMirroredAcrossFootprints({away}, {TestFootprint("F1", kRectangle)}, AnyFace()).empty());
}

TEST(FacesMirroredAcrossFootprints, AFootprintWithOneFaceIsLeftToTheRoofModelsBeyondItsRidge) {
  // A gable's south face, ridge along the long axis.
  RoofPlaneHypothesis south =
      TestPlane(SlopedPlane({5, 0, 6}, 35, -90), {{0, 0}, {10, 0}, {10, 4}, {0, 4}}, "south");
  south.lines_xy = {{Eigen::Vector2d(0, 0), Eigen::Vector2d(10, 0)}};
  EXPECT_TRUE(FacesMirroredAcrossFootprints({south}, {TestFootprint("F1", kRectangle)}).empty());
  // With a hip end beside it the footprint holds two faces, and the roof
  // models beyond a ridge do not run there.
  RoofPlaneHypothesis end =
      TestPlane(SlopedPlane({0, 4, 6}, 40, 180), {{0, 0}, {3, 4}, {0, 8}}, "west end");
  end.lines_xy = {{Eigen::Vector2d(0, 0), Eigen::Vector2d(0, 8)}};
  const std::vector<RoofPlaneHypothesis> out =
      FacesMirroredAcrossFootprints({south, end}, {TestFootprint("F1", kRectangle)});
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].id, "south mirrored across footprint F1");
  EXPECT_EQ(out[1].id, "west end mirrored across footprint F1");
}

}  // namespace roofsweep
