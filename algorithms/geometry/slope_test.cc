#include "algorithms/geometry/slope.h"

#include <gtest/gtest.h>

#include <cmath>

namespace roofsweep {
namespace {

TEST(SlopeDeg, OfAnyLengthAndEitherOrientation) {
  EXPECT_DOUBLE_EQ(SlopeDeg({0, 0, 1}), 0.0);
  EXPECT_DOUBLE_EQ(SlopeDeg({0, 0, -3}), 0.0);
  EXPECT_NEAR(SlopeDeg({0, 2, 0}), 90.0, 1e-12);
  const double t = 30 * M_PI / 180;
  EXPECT_NEAR(SlopeDeg({0, std::sin(t), std::cos(t)}), 30.0, 1e-12);
  EXPECT_NEAR(SlopeDeg({0, -5 * std::sin(t), -5 * std::cos(t)}), 30.0, 1e-12);
  EXPECT_DOUBLE_EQ(SlopeDeg({0, 0, 0}), 90.0);
}

}  // namespace
}  // namespace roofsweep
