#include "algorithms/sweep/points_of_interest.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace roofsweep {
namespace {

ViewTexture AllPoints(int cols, int rows) {
  ViewTexture t;
  t.grey = cv::Mat(rows, cols, CV_32F, cv::Scalar(0.5));
  t.poi = cv::Mat(rows, cols, CV_8U, cv::Scalar(255));
  return t;
}

TEST(BandPoints, BandOnTheRequestedSideOffTheLine) {
  const ViewTexture t = AllPoints(200, 200);
  SweepOptions o;
  o.band_width_px = 40;
  o.ncc_radius = 2;
  o.max_points = 0;  // no thinning
  const Eigen::Vector2d p0(50, 100), p1(150, 100);
  for (int side : {1, -1}) {
    const auto pts = BandPoints(t, p0, p1, side, {}, o);
    ASSERT_FALSE(pts.empty());
    for (const BandPoint& p : pts) {
      EXPECT_EQ(ImageSide(p0, p1, p.pixel), side);
      EXPECT_GE(p.distance, o.min_distance_px + o.ncc_radius);
      EXPECT_LE(p.distance, o.band_width_px);
      EXPECT_NEAR(p.distance, std::abs(p.pixel.y() - 100), 1e-9);
      EXPECT_GE(p.pixel.x(), 50 + o.end_margin_px);
      EXPECT_LE(p.pixel.x(), 150 - o.end_margin_px);
    }
    // Full band: every pixel centre of the rectangle.
    EXPECT_EQ(pts.size(), 94u * 36u);
  }
}

TEST(BandPoints, ClippedBehindAnotherLine) {
  const ViewTexture t = AllPoints(200, 200);
  SweepOptions o;
  o.band_width_px = 40;
  o.ncc_radius = 2;
  o.max_points = 0;
  const Eigen::Vector2d p0(50, 100), p1(150, 100);
  // A parallel line 20 px away on side +1 (cross > 0: y > 100 here).
  ASSERT_EQ(ImageSide(p0, p1, Eigen::Vector2d(100, 120)), 1);
  const std::vector<Segment2> blockers = {{Eigen::Vector2d(40, 120), Eigen::Vector2d(160, 120)}};
  const auto pts = BandPoints(t, p0, p1, 1, blockers, o);
  ASSERT_FALSE(pts.empty());
  // ... and the windows stay off the blocking line as off the line itself.
  for (const BandPoint& p : pts) EXPECT_LE(p.distance, 20.0 - o.min_distance_px - o.ncc_radius);
  // A blocker from the line's end point into the band (a hip at a ridge
  // end) hides only the points behind it.
  // (Not at 45 degrees, so that no pixel centre lies exactly 4 px off it.)
  const Eigen::Vector2d hip_end(110.3, 140);
  const std::vector<Segment2> hip = {{p1, hip_end}};
  const auto beside = BandPoints(t, p0, p1, 1, hip, o);
  size_t expected = 0;
  for (const BandPoint& p : BandPoints(t, p0, p1, 1, {}, o)) {
    // Left of the hip and at least min_distance + radius = 4 px from it.
    const Eigen::Vector2d d = hip_end - p1, x = p.pixel - p1;
    const double cross = d.x() * x.y() - d.y() * x.x();
    const double along = std::clamp(x.dot(d) / d.squaredNorm(), 0.0, 1.0);
    expected += cross > 0 && (x - along * d).norm() >= 4.0;
  }
  EXPECT_EQ(beside.size(), expected);
  EXPECT_GT(expected, 1000u);
}

TEST(BandPoints, ThinnedToMaxPoints) {
  const ViewTexture t = AllPoints(200, 200);
  SweepOptions o;
  o.max_points = 100;
  EXPECT_EQ(BandPoints(t, {50, 100}, {150, 100}, 1, {}, o).size(), 100u);
}

}  // namespace
}  // namespace roofsweep
