#include "algorithms/buildings/footprint_pieces.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "algorithms/buildings/convex_polygon2.h"
#include "algorithms/buildings/polygon2.h"
#include "algorithms/buildings/test_planes.h"

namespace roofsweep {
namespace {

// A row of three 6 x 10 m houses along x; the first two gabled (the south
// face falls at 35° towards -y), the third flat.
const Eigen::Vector4d kSouth = SlopedPlane({0, 5, 9}, 35, 270);
const std::vector<Footprint> kRow = {TestFootprint("a", {{0, 0}, {6, 0}, {6, 10}, {0, 10}}),
                                     TestFootprint("b", {{6, 0}, {12, 0}, {12, 10}, {6, 10}}),
                                     TestFootprint("c", {{12, 0}, {18, 0}, {18, 10}, {12, 10}})};

TEST(PiecesOverFootprints, OnePiecePerFootprintOfAFaceThatSpansHouses) {
  RoofPlaneHypothesis face = TestPlane(kSouth, {{0.5, 0}, {16, 0}, {16, 4.8}, {0.5, 4.8}}, "south");
  // The ridge over a and b, the eave over all three.
  face.lines_xy = {{{{0.5, 4.8}, {11, 4.8}}}, {{{0.5, 0}, {16, 0}}}};
  const std::vector<FootprintPiece> pieces = PiecesOverFootprints({face}, kRow);
  ASSERT_EQ(pieces.size(), 3u);
  const double expected[] = {5.5 * 4.8, 6 * 4.8, 4 * 4.8};
  for (int f = 0; f < 3; ++f) {
    EXPECT_EQ(pieces[f].plane, 0);
    EXPECT_EQ(pieces[f].footprint, f);
    EXPECT_EQ(pieces[f].piece.id, "south over footprint " + kRow[f].id);
    EXPECT_TRUE(pieces[f].piece.plane.isApprox(kSouth));
    EXPECT_NEAR(SignedArea(pieces[f].piece.patch), expected[f], 1e-9);
  }
  // A line goes with the piece its middle lies over: the ridge (middle at
  // x = 5.75) with a, the eave (x = 8.25) with b, neither with c.
  EXPECT_EQ(pieces[0].piece.lines, 1);
  EXPECT_NEAR(pieces[0].piece.lines_xy[0][1].x(), 11, 1e-12);
  EXPECT_EQ(pieces[1].piece.lines, 1);
  EXPECT_NEAR(pieces[1].piece.lines_xy[0][1].y(), 0, 1e-12);
  EXPECT_EQ(pieces[2].piece.lines, 0);
}

TEST(PiecesOverFootprints, NoneForAFaceOverOneBuildingOrBarelyOverAnother) {
  // Within one house, with 1 m² over the next (an eave, registration).
  const RoofPlaneHypothesis inside =
      TestPlane(kSouth, {{0, 0}, {6.2, 0}, {6.2, 5}, {0, 5}}, "inside");
  EXPECT_TRUE(PiecesOverFootprints({inside}, kRow).empty());
  // Over two rectangles of one multipolygon footprint (one id).
  const std::vector<Footprint> one = {TestFootprint("m", kRow[0].outline),
                                      TestFootprint("m", kRow[1].outline)};
  const RoofPlaneHypothesis both = TestPlane(kSouth, {{0, 0}, {12, 0}, {12, 5}, {0, 5}}, "both");
  EXPECT_TRUE(PiecesOverFootprints({both}, one).empty());
  // The same face over the two houses of the row is weighed piece by piece.
  EXPECT_EQ(PiecesOverFootprints({both}, kRow).size(), 2u);
}

TEST(PatchOverPieces, TheHullOfThePiecesKept) {
  const RoofPlaneHypothesis face =
      TestPlane(kSouth, {{0.5, -0.5}, {16, -0.5}, {16, 4.8}, {0.5, 4.8}}, "south");
  const std::vector<FootprintPiece> p = PiecesOverFootprints({face}, kRow);
  ASSERT_EQ(p.size(), 3u);
  // The end over c dropped: the hull of a's and b's pieces, without the
  // eave's half metre over no footprint.
  const Ring2 ab = PatchOverPieces({p[0].piece.patch, p[1].piece.patch}, {kRow[2].outline});
  EXPECT_NEAR(SignedArea(ab), 11.5 * 4.8, 1e-9);
  EXPECT_NEAR(IntersectionArea(ab, kRow[2].outline), 0, 1e-9);
  // The middle dropped: the hull of the ends would cover it again, so the
  // larger piece alone stays (a, 5.5 m, against 4 m over c).
  const Ring2 ac = PatchOverPieces({p[0].piece.patch, p[2].piece.patch}, {kRow[1].outline});
  EXPECT_NEAR(SignedArea(ac), 5.5 * 4.8, 1e-9);
  EXPECT_NEAR(IntersectionArea(ac, kRow[1].outline), 0, 1e-9);
  EXPECT_TRUE(PatchOverPieces({}, {kRow[0].outline}).empty());
}

TEST(CutRefutedPieces, OnlyWherePiecesAreLeft) {
  const RoofPlaneHypothesis face =
      TestPlane(kSouth, {{0.5, 0}, {16, 0}, {16, 4.8}, {0.5, 4.8}}, "south");
  const RoofPlaneHypothesis flat =
      TestPlane({0, 0, 1, -6}, {{6.5, 5}, {17, 5}, {17, 9}, {6.5, 9}}, "flat");
  std::vector<RoofPlaneHypothesis> planes = {face, flat};
  for (RoofPlaneHypothesis& p : planes) {
    p.similarity = 0.8;
    p.score = SignedArea(p.patch) * p.similarity;
  }
  const std::vector<FootprintPiece> pieces = PiecesOverFootprints(planes, kRow);
  ASSERT_EQ(pieces.size(), 5u);  // the face over a, b, c; the flat roof over b, c
  // The face's piece over c refuted, and both pieces of the flat roof.
  const std::vector<int> cut = CutRefutedPieces(pieces, {0, 0, 1, 1, 1}, kRow, &planes);
  EXPECT_EQ(cut, std::vector<int>({2}));
  EXPECT_NEAR(SignedArea(planes[0].patch), 11.5 * 4.8, 1e-9);
  EXPECT_NEAR(IntersectionArea(planes[0].patch, kRow[2].outline), 0, 1e-9);
  EXPECT_NEAR(planes[0].score, 11.5 * 4.8 * 0.8, 1e-9);
  // The flat roof, refuted everywhere, stays as it was verified.
  EXPECT_EQ(planes[1].patch, flat.patch);
  EXPECT_NEAR(planes[1].score, 10.5 * 4 * 0.8, 1e-9);
  // Nothing refuted: nothing changes.
  std::vector<RoofPlaneHypothesis> same = {face, flat};
  EXPECT_TRUE(CutRefutedPieces(pieces, {0, 0, 0, 0, 0}, kRow, &same).empty());
  EXPECT_EQ(same[0].patch, face.patch);
}

}  // namespace
}  // namespace roofsweep
