#include "algorithms/matching/colour_balance.h"

#include <gtest/gtest.h>

#include <cmath>

#include "algorithms/matching/sim_block_fixture.h"

namespace roofsweep {
namespace {

// Multiplies the linear R and B channels of an sRGB image.
cv::Mat Tint(const cv::Mat& image, double r, double b) {
  ColourCorrection k;
  k.gain = Eigen::Vector3d(r, 1, b);
  return ApplyColourCorrection(image, k);
}

TEST(ColourBalance, SrgbRoundTrip) {
  for (double v : {0.0, 0.002, 0.04, 0.2, 0.5, 0.9, 1.0})
    EXPECT_NEAR(LinearToSrgb(SrgbToLinear(v)), v, 1e-9);
}

TEST(ColourBalance, RecoversAKnownTint) {
  const SimBlock b = SimulateSmallBlock(1);
  const auto before = EstimateColourBalance(b.block, b.images);
  ASSERT_EQ(before.size(), b.images.size());
  // Tint view 0 (its R up 6 %, B down 5 %): relative to every other view
  // its correction must change by the inverse.
  std::vector<cv::Mat> tinted = b.images;
  tinted[0] = Tint(b.images[0], 1.06, 0.95);
  const auto after = EstimateColourBalance(b.block, tinted);
  for (size_t k = 1; k < after.size(); ++k) {
    const double r =
        (after[k].gain[0] / after[0].gain[0]) / (before[k].gain[0] / before[0].gain[0]);
    const double bl =
        (after[k].gain[2] / after[0].gain[2]) / (before[k].gain[2] / before[0].gain[2]);
    EXPECT_NEAR(r, 1.06, 0.01) << "view " << k;
    EXPECT_NEAR(bl, 0.95, 0.01) << "view " << k;
  }
  // G is the reference channel and stays.
  for (const ColourCorrection& c : after) EXPECT_EQ(c.gain[1], 1.0);
}

TEST(ColourBalance, DegenerateInputIsIdentity) {
  const SimBlock b = SimulateSmallBlock(1);
  Block one = b.block;
  one.views.resize(1);
  const auto k1 = EstimateColourBalance(one, {b.images[0]});
  ASSERT_EQ(k1.size(), 1u);
  EXPECT_TRUE(k1[0].Identity());
  Block unknown = b.block;
  unknown.ground = GroundModel{};
  for (const ColourCorrection& c : EstimateColourBalance(unknown, b.images))
    EXPECT_TRUE(c.Identity());
}

}  // namespace
}  // namespace roofsweep
