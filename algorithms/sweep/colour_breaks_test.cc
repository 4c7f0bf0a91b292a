#include "algorithms/sweep/colour_breaks.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <opencv2/core.hpp>

#include "algorithms/sweep/test_scene.h"

namespace roofsweep {
namespace {

using sweep_test::Quad;
using sweep_test::TestScene;

const double kTan35 = std::tan(35 * M_PI / 180);

// A roof face 6 m deep rising from an eave at y = 6 (z = 6) to the ridge at
// y = 0, from x = x0 to x1, in one colour.
Quad Piece(double x0, double x1, const Eigen::Vector3f& colour, uint32_t seed) {
  Quad q;
  q.origin = {x0, 0, 6 + 6 * kTan35};
  q.u = {x1 - x0, 0, 0};
  q.v = {0, 6, -6 * kTan35};
  q.colour = colour;
  q.seed = seed;
  return q;
}

RoofPlaneHypothesis FaceFrom(double x0, double x1) {
  const Quad q = Piece(x0, x1, Eigen::Vector3f::Zero(), 1);
  Eigen::Vector3d n = q.u.cross(q.v).normalized();
  if (n.z() < 0) n = -n;
  RoofPlaneHypothesis h;
  h.plane << n, -n.dot(q.origin);
  h.patch = {{x0 + 0.3, 0.3}, {x1 - 0.3, 0.3}, {x1 - 0.3, 5.7}, {x0 + 0.3, 5.7}};
  h.id = "face";
  return h;
}

std::vector<std::array<Eigen::Vector2d, 2>> Breaks(const TestScene& scene,
                                                   const RoofPlaneHypothesis& h) {
  const Block block = sweep_test::FourViewBlock();
  return FindColourBreaks(block, sweep_test::RenderAll(scene, block), {h}, ColourBreakOptions())
      .at(0);
}

const Eigen::Vector3f kRedTiles(0.55f, 0.27f, 0.2f), kGreySlate(0.33f, 0.34f, 0.37f);

TEST(FindColourBreaks, TwoHousesRoofedApartAreCutAtTheirPartyWall) {
  TestScene scene;
  scene.quads = {Piece(-9, 1.5, kRedTiles, 3), Piece(1.5, 9, kGreySlate, 4)};
  const auto b = Breaks(scene, FaceFrom(-9, 9));
  ASSERT_EQ(b.size(), 1u);
  EXPECT_NEAR(b[0][0].x(), 1.5, 0.1);
  EXPECT_NEAR(b[0][1].x(), 1.5, 0.1);
  // Down the fall line, over most of the face's depth.
  EXPECT_GT(std::abs(b[0][1].y() - b[0][0].y()), 4.0);
}

// At a quarter of the resolution (36 cm pixels) the samples are half a
// pixel apart instead of 0.1 m, and the break is still found, to about one
// sample.
TEST(FindColourBreaks, CoarserImagesAreSampledPerHalfPixel) {
  TestScene scene;
  scene.quads = {Piece(-9, 1.5, kRedTiles, 3), Piece(1.5, 9, kGreySlate, 4)};
  Block block = sweep_test::FourViewBlock();
  Camera& cam = block.cameras[0];
  cam.width = 160, cam.height = 120;
  cam.fx = cam.fy = 250;
  cam.cx = 80, cam.cy = 60;
  const auto b = FindColourBreaks(block, sweep_test::RenderAll(scene, block), {FaceFrom(-9, 9)},
                                  ColourBreakOptions())
                     .at(0);
  ASSERT_EQ(b.size(), 1u);
  EXPECT_NEAR(b[0][0].x(), 1.5, 0.3);
  EXPECT_NEAR(b[0][1].x(), 1.5, 0.3);
}

TEST(FindColourBreaks, OneRoofingOverSeveralHousesHasNoBreak) {
  TestScene scene;
  scene.quads = {Piece(-9, 1.5, kRedTiles, 3), Piece(1.5, 9, kRedTiles, 4)};
  EXPECT_TRUE(Breaks(scene, FaceFrom(-9, 9)).empty());
}

TEST(FindColourBreaks, AChangeOverPartOfTheDepthIsNoBreak) {
  // Grey over the upper 60 % of the depth only (a shadow, a dormer's
  // cladding): the median over the whole depth changes, the eave band's
  // does not.
  TestScene scene;
  Quad grey = Piece(1.5, 9, kGreySlate, 4);
  grey.v *= 0.6;
  grey.origin.z() += 0.02;  // in front of the face
  scene.quads = {grey, Piece(-9, 9, kRedTiles, 3)};
  const Block block = sweep_test::FourViewBlock();
  const std::vector<cv::Mat> images = sweep_test::RenderAll(scene, block);
  EXPECT_TRUE(FindColourBreaks(block, images, {FaceFrom(-9, 9)}, {}).at(0).empty());
  ColourBreakOptions one_band;
  one_band.depth_bands = 1;
  EXPECT_EQ(FindColourBreaks(block, images, {FaceFrom(-9, 9)}, one_band).at(0).size(), 1u);
}

TEST(FindColourBreaks, ABreakNearTheEndOfTheFaceIsLeftAlone) {
  // 2 m from the face's end: a hip, a verge or a gable wall, not a house.
  TestScene scene;
  scene.quads = {Piece(-9, 7, kRedTiles, 3), Piece(7, 9, kGreySlate, 4)};
  EXPECT_TRUE(Breaks(scene, FaceFrom(-9, 9)).empty());
}

TEST(FindColourBreaks, FlatRoofsAndGreyImagesGiveNone) {
  TestScene scene;
  scene.quads = {Piece(-9, 1.5, kRedTiles, 3), Piece(1.5, 9, kGreySlate, 4)};
  const Block block = sweep_test::FourViewBlock();
  RoofPlaneHypothesis flat = FaceFrom(-9, 9);
  flat.plane << 0, 0, 1, -8;
  std::vector<cv::Mat> images = sweep_test::RenderAll(scene, block);
  EXPECT_TRUE(FindColourBreaks(block, images, {flat}, {}).at(0).empty());
  for (cv::Mat& m : images) cv::extractChannel(m.clone(), m, 1);
  EXPECT_TRUE(FindColourBreaks(block, images, {FaceFrom(-9, 9)}, {}).at(0).empty());
}

}  // namespace
}  // namespace roofsweep
