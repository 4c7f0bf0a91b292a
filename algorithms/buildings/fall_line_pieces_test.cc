#include "algorithms/buildings/fall_line_pieces.h"

#include <gtest/gtest.h>

#include <cmath>

#include "algorithms/buildings/convex_polygon2.h"
#include "algorithms/buildings/polygon2.h"
#include "algorithms/buildings/test_planes.h"

namespace roofsweep {
namespace {

// The south face of a terraced row along x, 18 m long and 6 m deep: it
// falls at 35° towards -y, its eave on y = 0, its ridge on y = 6. Gabled
// houses stand over x 0-6 and 12-18, their verges at x = 6 and x = 12
// (down the fall line, the whole depth), a flat-roofed house between them.
const Eigen::Vector4d kSouth = SlopedPlane({0, 3, 9}, 35, 270);

RoofPlaneHypothesis Row() {
  RoofPlaneHypothesis face = TestPlane(kSouth, {{0, 0}, {18, 0}, {18, 6}, {0, 6}}, "south");
  face.similarity = 0.8;
  // Eave and ridge run on across the flat house; the two verges.
  face.lines_xy = {
      {{{0, 0}, {18, 0}}}, {{{0, 6}, {18, 6}}}, {{{6, 0.1}, {6, 5.9}}}, {{{12, 5.9}, {12, 0.1}}}};
  face.lines = 4;
  return face;
}

TEST(PiecesAcrossFallLines, AFaceIsCutAtItsVerges) {
  const std::vector<FallLinePiece> pieces = PiecesAcrossFallLines({Row()});
  ASSERT_EQ(pieces.size(), 3u);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(pieces[k].plane, 0);
    EXPECT_EQ(pieces[k].order, k);
    EXPECT_EQ(pieces[k].piece.id, "south piece " + std::to_string(k + 1) + " of 3");
    EXPECT_TRUE(pieces[k].piece.plane.isApprox(kSouth));
    EXPECT_NEAR(SignedArea(pieces[k].piece.patch), 36, 1e-9);
  }
  // In order across the fall line (here along +x).
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(RingBounds(pieces[k].piece.patch)[0], 6 * k, 1e-9);
    EXPECT_NEAR(RingBounds(pieces[k].piece.patch)[2], 6 * k + 6, 1e-9);
  }
  // A line goes with each piece its middle lies in, a verge with both.
  EXPECT_EQ(pieces[0].piece.lines, 1);  // the verge at x = 6
  EXPECT_EQ(pieces[1].piece.lines, 4);  // eave, ridge (middles at x = 9), both verges
  EXPECT_EQ(pieces[2].piece.lines, 1);
}

TEST(PiecesAcrossFallLines, OnlyLinesDownTheFallLineWithRoomOnBothSidesCut) {
  RoofPlaneHypothesis face = Row();
  // A verge at the patch's end, a dormer's line over a third of the depth,
  // a line 20° off the fall line.
  face.lines_xy = {{{{0, 0}, {18, 0}}},
                   {{{18, 0}, {18, 6}}},
                   {{{9, 2}, {9, 4}}},
                   {{{6, 0.2}, {6 + 5.6 * std::tan(20 * M_PI / 180), 5.8}}}};
  EXPECT_TRUE(PiecesAcrossFallLines({face}).empty());
  // Two verges 2 m apart: the second is too close to the first.
  face.lines_xy = {{{{6, 0}, {6, 6}}}, {{{8, 0}, {8, 6}}}};
  EXPECT_EQ(PiecesAcrossFallLines({face}).size(), 2u);
  // A flat roof has no fall line.
  face = Row();
  face.plane = Eigen::Vector4d(0, 0, 1, -9);
  EXPECT_TRUE(PiecesAcrossFallLines({face}).empty());
}

TEST(CutRefutedFallLinePieces, AFaceRefutedOverTheFlatHouseSplitsInTwo) {
  std::vector<RoofPlaneHypothesis> planes = {Row()};
  // A longer west part: the eave runs on 2 m further west.
  planes[0].patch = ConvexHull({{-2, 0}, {18, 0}, {18, 6}, {-2, 6}});
  planes[0].lines_xy[0] = {{{-2, 0}, {18, 0}}};
  const std::vector<FallLinePiece> pieces = PiecesAcrossFallLines(planes);
  ASSERT_EQ(pieces.size(), 3u);
  EXPECT_EQ(CutRefutedFallLinePieces(pieces, {0, 1, 0}, &planes), std::vector<int>{1});
  ASSERT_EQ(planes.size(), 2u);
  // The larger part (west, 8 m) stays the plane, the other is a copy.
  EXPECT_EQ(planes[0].id, "south");
  EXPECT_NEAR(SignedArea(planes[0].patch), 48, 1e-9);
  EXPECT_NEAR(RingBounds(planes[0].patch)[2], 6, 1e-9);  // its max x
  EXPECT_NEAR(planes[0].score, 48 * 0.8, 1e-9);
  EXPECT_EQ(planes[1].id, "south part 2");
  EXPECT_NEAR(SignedArea(planes[1].patch), 36, 1e-9);
  EXPECT_NEAR(RingBounds(planes[1].patch)[0], 12, 1e-9);  // min x
  EXPECT_TRUE(planes[1].plane.isApprox(kSouth));
}

TEST(CutRefutedFallLinePieces, AnEndPieceRefutedShrinksTheFace) {
  std::vector<RoofPlaneHypothesis> planes = {Row()};
  const std::vector<FallLinePiece> pieces = PiecesAcrossFallLines(planes);
  EXPECT_EQ(CutRefutedFallLinePieces(pieces, {1, 0, 0}, &planes), std::vector<int>{0});
  ASSERT_EQ(planes.size(), 1u);
  EXPECT_NEAR(SignedArea(planes[0].patch), 72, 1e-9);
}

TEST(CutRefutedFallLinePieces, AFaceRefutedEverywhereStaysWhole) {
  std::vector<RoofPlaneHypothesis> planes = {Row()};
  const std::vector<FallLinePiece> pieces = PiecesAcrossFallLines(planes);
  EXPECT_TRUE(CutRefutedFallLinePieces(pieces, {1, 1, 1}, &planes).empty());
  ASSERT_EQ(planes.size(), 1u);
  EXPECT_NEAR(SignedArea(planes[0].patch), 108, 1e-9);
  EXPECT_TRUE(CutRefutedFallLinePieces(pieces, {0, 0, 0}, &planes).empty());
  EXPECT_NEAR(SignedArea(planes[0].patch), 108, 1e-9);
}

}  // namespace
}  // namespace roofsweep
