#include "algorithms/matching/robust_estimate.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace roofsweep {
namespace {

TEST(RobustMcd1D, IgnoresThirtyPercentOutliers) {
  std::mt19937 rng(3);
  std::normal_distribution<double> in(50, 2), out(80, 5);
  std::vector<double> v;
  for (int i = 0; i < 700; ++i) v.push_back(in(rng));
  for (int i = 0; i < 300; ++i) v.push_back(out(rng));
  const Robust1D r = RobustMcd1D(v);
  EXPECT_NEAR(r.location, 50, 0.3);
  EXPECT_NEAR(r.scale, 2, 0.3);
}

TEST(RobustMcd2D, IgnoresThirtyPercentOutliers) {
  std::mt19937 rng(5);
  std::normal_distribution<double> z(0, 1);
  std::vector<Eigen::Vector2d> pts;
  // Inliers: mean (10, -5), covariance [[4, 1.2], [1.2, 1]].
  Eigen::Matrix2d L;
  L << 2, 0, 0.6, 0.8;
  for (int i = 0; i < 700; ++i)
    pts.push_back(Eigen::Vector2d(10, -5) + L * Eigen::Vector2d(z(rng), z(rng)));
  for (int i = 0; i < 300; ++i)
    pts.push_back(Eigen::Vector2d(30, 20) + 3 * Eigen::Vector2d(z(rng), z(rng)));
  const Robust2D r = RobustMcd2D(pts, 1);
  ASSERT_TRUE(r.valid);
  EXPECT_NEAR(r.mean.x(), 10, 0.3);
  EXPECT_NEAR(r.mean.y(), -5, 0.2);
  EXPECT_NEAR(r.cov(0, 0), 4, 0.6);
  EXPECT_NEAR(r.cov(1, 1), 1, 0.2);
  EXPECT_NEAR(r.cov(0, 1), 1.2, 0.3);
  EXPECT_GE(r.inliers, 600);
  EXPECT_LE(r.inliers, 720);
  // The plain mean is dragged far off: the test would notice a non-robust estimator.
  Eigen::Vector2d m = Eigen::Vector2d::Zero();
  for (const auto& p : pts) m += p;
  m /= pts.size();
  EXPECT_GT((m - Eigen::Vector2d(10, -5)).norm(), 5);
}

TEST(SelectKth, AgreesWithNthElement) {
  std::mt19937 rng(11);
  for (int n : {1, 2, 16, 17, 40, 151, 400}) {
    for (int levels : {3, 1000000}) {  // many ties, almost none
      std::uniform_int_distribution<int> v(0, levels - 1);
      std::vector<double> values(n);
      for (double& x : values) x = v(rng) * 0.25;
      for (int k = 0; k < n; ++k) {
        std::vector<double> a = values, b = values, buffer(n);
        std::nth_element(b.begin(), b.begin() + k, b.end());
        ASSERT_EQ(SelectKth(&a, &buffer, k), b[k]) << "n " << n << " k " << k;
      }
    }
  }
}

TEST(RobustMcd2D, QuantisedColoursWithManyTies) {
  // a*, b* of an 8-bit flat roof take a few values only: most squared
  // distances tie, which the h-subset selection must handle (the h-th
  // smallest often lies among equal values).
  std::vector<Eigen::Vector2d> pts;
  for (int i = 0; i < 140; ++i) pts.emplace_back(i % 3, (i / 3) % 3);
  for (int i = 0; i < 60; ++i) pts.emplace_back(20 + i % 2, 20);
  const Robust2D r = RobustMcd2D(pts, 7, 4);
  ASSERT_TRUE(r.valid);
  EXPECT_NEAR(r.mean.x(), 1, 0.1);
  EXPECT_NEAR(r.mean.y(), 1, 0.1);
  EXPECT_GE(r.inliers, 130);
  EXPECT_LE(r.inliers, 140);
  // All equal: the scatter is the regularisation alone.
  const Robust2D same = RobustMcd2D(std::vector<Eigen::Vector2d>(100, {3, -2}), 1, 4);
  ASSERT_TRUE(same.valid);
  EXPECT_EQ(same.mean, Eigen::Vector2d(3, -2));
  EXPECT_LT(same.cov.norm(), 1e-3);
}

TEST(RobustMcd2D, TooFewPointsIsInvalid) { EXPECT_FALSE(RobustMcd2D({{0, 0}, {1, 1}}).valid); }

}  // namespace
}  // namespace roofsweep
