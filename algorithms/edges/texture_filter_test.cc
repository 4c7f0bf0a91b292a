#include "algorithms/edges/texture_filter.h"

#include <gtest/gtest.h>

#include "algorithms/edges/extract_segments.h"
#include "algorithms/edges/synthetic_images.h"

namespace roofsweep {
namespace {

// A horizontal segment at height y from x0 to x1; `brighter_above` sets
// its polarity (Segment2D: the brighter side on the left of p0 -> p1, and
// with y down, walking right, left is up).
Segment2D Horizontal(double y, double x0, double x1, float contrast, bool brighter_above = true) {
  Segment2D s;
  s.p0 = {brighter_above ? x0 : x1, y};
  s.p1 = {brighter_above ? x1 : x0, y};
  s.contrast = contrast;
  return s;
}

TEST(MarkRepetitiveTexture, InnerRowsOfACourseAreTextureTheOuterOnesNot) {
  Segments2D rows;
  for (int k = 0; k < 7; ++k) rows.push_back(Horizontal(10 + 6.6 * k, 5, 80, 0.05f));
  const std::vector<bool> t = MarkRepetitiveTexture(rows, EdgeOptions{});
  ASSERT_EQ(t.size(), 7u);
  EXPECT_FALSE(t.front());  // a row on one side only: an eave beside its tiles
  EXPECT_FALSE(t.back());
  for (int k = 1; k < 6; ++k) EXPECT_TRUE(t[k]) << k;
}

TEST(MarkRepetitiveTexture, AStrongEdgeInsideTheCourseIsKept) {
  Segments2D rows;
  for (int k = 0; k < 7; ++k)
    rows.push_back(Horizontal(10 + 6.6 * k, 5, 80, k == 3 ? 0.2f : 0.05f));
  const std::vector<bool> t = MarkRepetitiveTexture(rows, EdgeOptions{});
  EXPECT_FALSE(t[3]);
  EXPECT_TRUE(t[2]);  // its weaker neighbours stay texture
  EXPECT_TRUE(t[4]);
}

TEST(MarkRepetitiveTexture, OppositePolarityIrregularSpacingAndNoOverlapAreNotTexture) {
  // A painted stripe: its two edges face away from each other.
  Segments2D stripe = {Horizontal(20, 0, 60, 0.1f, true), Horizontal(26, 0, 60, 0.1f, false),
                       Horizontal(32, 0, 60, 0.1f, true)};
  std::vector<bool> t = MarkRepetitiveTexture(stripe, EdgeOptions{});
  EXPECT_FALSE(t[1]);  // its same-polarity neighbours are not on both sides

  // Neighbours at 3 and 14 px: no period.
  Segments2D irregular = {Horizontal(17, 0, 60, 0.1f), Horizontal(20, 0, 60, 0.1f),
                          Horizontal(34, 0, 60, 0.1f)};
  t = MarkRepetitiveTexture(irregular, EdgeOptions{});
  EXPECT_FALSE(t[1]);

  // Rows beside the segment but beyond its ends.
  Segments2D apart = {Horizontal(14, 100, 160, 0.1f), Horizontal(20, 0, 60, 0.1f),
                      Horizontal(26, 100, 160, 0.1f)};
  t = MarkRepetitiveTexture(apart, EdgeOptions{});
  EXPECT_FALSE(t[1]);
}

TEST(MarkRepetitiveTexture, ExtractSegmentsMarksTileCoursesNotTheRoofOutline) {
  // A roof face of tile courses 7 px apart (a dark lip at the lower end of
  // each row) on a bright ground, as the simulator's clay tiles look at
  // 5 cm GSD.
  const cv::Size size(160, 160);
  const cv::Mat image = testing::RenderRegions(
      size,
      [](double x, double y) {
        if (x < 30 || x > 130 || y < 30 || y > 130) return 0;
        return std::fmod(y - 30, 7.0) > 5.5 ? 2 : 1;
      },
      {cv::Vec3f(0.8f, 0.8f, 0.75f), cv::Vec3f(0.6f, 0.3f, 0.2f), cv::Vec3f(0.45f, 0.22f, 0.15f)});
  EdgeOptions unmarked;
  unmarked.mark_texture = false;
  for (const Segment2D& g : ExtractSegments(image, unmarked)) EXPECT_FALSE(g.texture);
  const Segments2D all = ExtractSegments(image, EdgeOptions{});
  Segments2D kept;
  for (const Segment2D& g : all)
    if (!g.texture) kept.push_back(g);
  auto horizontal_inside = [](const Segments2D& s) {
    int n = 0;
    for (const Segment2D& g : s)
      n += std::abs(g.Direction().y()) < 0.1 && g.Midpoint().y() > 36 && g.Midpoint().y() < 124;
    return n;
  };
  auto outline = [](const Segments2D& s) {
    int n = 0;
    for (const Segment2D& g : s)
      n += g.Length() > 80 &&
           (std::abs(g.Midpoint().y() - 30) < 1.5 || std::abs(g.Midpoint().y() - 130) < 1.5 ||
            std::abs(g.Midpoint().x() - 30) < 1.5 || std::abs(g.Midpoint().x() - 130) < 1.5);
    return n;
  };
  EXPECT_GE(horizontal_inside(all), 20);  // both edges of every lip
  EXPECT_LE(horizontal_inside(kept), 2);
  EXPECT_EQ(outline(kept), 4);
}

}  // namespace
}  // namespace roofsweep
