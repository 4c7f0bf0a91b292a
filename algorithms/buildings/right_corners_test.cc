#include "algorithms/buildings/right_corners.h"

#include <gtest/gtest.h>

#include <cmath>

namespace roofsweep {
namespace {

using Lines = std::vector<std::array<Eigen::Vector2d, 2>>;

std::array<Eigen::Vector2d, 2> L(double x0, double y0, double x1, double y1) {
  return {Eigen::Vector2d(x0, y0), Eigen::Vector2d(x1, y1)};
}

TEST(CountRightCorners, ThreeSidesOfAShedHaveTwoAndAllFourHaveFour) {
  const RightCornerOptions o;
  const Lines u = {L(0, 0, 2.4, 0), L(0, 0, 0, 2.4), L(2.4, 0, 2.4, 2.4)};
  EXPECT_EQ(CountRightCorners(u, o), 2);
  Lines closed = u;
  closed.push_back(L(0, 2.4, 2.4, 2.4));
  EXPECT_EQ(CountRightCorners(closed, o), 4);
  // Two parallel sides make no corner, however close.
  EXPECT_EQ(CountRightCorners({L(0, 0, 3, 0), L(0, 1, 3, 1)}, o), 0);
}

TEST(CountRightCorners, NeedsLongArmsASquareAngleAndAMeetingPoint) {
  RightCornerOptions o;
  o.max_gap_m = 0.5;
  // Square, meeting at the corner.
  EXPECT_EQ(CountRightCorners({L(0, 0, 3, 0), L(0, 0.2, 0, 3)}, o), 1);
  // The crossing 0.6 m past the end of one of them.
  EXPECT_EQ(CountRightCorners({L(0, 0, 3, 0), L(-0.6, 0.2, -0.6, 3)}, o), 0);
  // An arm shorter than min_arm_m.
  EXPECT_EQ(CountRightCorners({L(0, 0, 3, 0), L(0, 0, 0, 0.8)}, o), 0);
  // 15 degrees off square.
  const double a = 75 * M_PI / 180;
  EXPECT_EQ(CountRightCorners({L(0, 0, 3, 0), L(0, 0, 3 * std::cos(a), 3 * std::sin(a))}, o), 0);
  // 8 degrees off is within the default 10.
  const double b = 82 * M_PI / 180;
  EXPECT_EQ(CountRightCorners({L(0, 0, 3, 0), L(0, 0, 3 * std::cos(b), 3 * std::sin(b))}, o), 1);
}

}  // namespace
}  // namespace roofsweep
