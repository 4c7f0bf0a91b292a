#include "algorithms/matching/residual_test.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace roofsweep {
namespace {

// A line fitted to n observations with endpoint noise sigma: 2n rms² is
// sigma² chi²(2n - 4), drawn here as a sum of squared normals.
LineFitResidual NoisyFit(int n, double sigma, std::mt19937& rng) {
  std::normal_distribution<double> z(0, sigma);
  double ss = 0;
  for (int k = 0; k < 2 * n - 4; ++k) {
    const double e = z(rng);
    ss += e * e;
  }
  return {std::sqrt(ss / (2.0 * n)), n};
}

TEST(ResidualNoise, RecoversTheNoiseLevel) {
  std::mt19937 rng(5);
  std::vector<LineFitResidual> fits;
  for (int i = 0; i < 2000; ++i) fits.push_back(NoisyFit(3 + i % 8, 0.3, rng));
  const ResidualNoise noise = EstimateResidualNoise(fits);
  EXPECT_EQ(noise.lines, 2000);
  // Without the median of chi²(k)/k (0.69 for k = 2) it comes out ~10 % low.
  EXPECT_NEAR(noise.sigma_px, 0.3, 0.01);
}

TEST(ResidualNoise, StaysNearTheNoiseLevelDespiteWrongLines) {
  std::mt19937 rng(7);
  std::vector<LineFitResidual> fits;
  for (int i = 0; i < 600; ++i) fits.push_back(NoisyFit(3 + i % 6, 0.3, rng));
  // A third of the lines carry one observation off by 2 px.
  for (int i = 0; i < 300; ++i) {
    LineFitResidual f = NoisyFit(3 + i % 6, 0.3, rng);
    f.rms_px = std::sqrt(f.rms_px * f.rms_px + 4.0 / (2.0 * f.observations));
    fits.push_back(f);
  }
  // Two-view lines fit exactly and say nothing about the noise.
  for (int i = 0; i < 500; ++i) fits.push_back({0.0, 2});
  const ResidualNoise noise = EstimateResidualNoise(fits);
  EXPECT_EQ(noise.lines, 900);
  // The wrong third inflates the median (loosening the test), boundedly.
  EXPECT_GT(noise.sigma_px, 0.3);
  EXPECT_LT(noise.sigma_px, 0.4);
}

TEST(ResidualNoise, TooFewTestableLinesGiveNoEstimate) {
  std::mt19937 rng(3);
  std::vector<LineFitResidual> fits;
  for (int i = 0; i < 19; ++i) fits.push_back(NoisyFit(4, 0.5, rng));
  for (int i = 0; i < 100; ++i) fits.push_back({0.0, 2});
  const ResidualNoise noise = EstimateResidualNoise(fits);
  EXPECT_EQ(noise.lines, 19);
  EXPECT_EQ(noise.sigma_px, 0);
  // Without a noise level nothing is rejected.
  EXPECT_TRUE(ResidualConsistent({10.0, 4}, noise.sigma_px, 0.001));
}

TEST(ResidualConsistent, RejectsOffsetObservationsAndKeepsAlmostAllCorrectLines) {
  std::mt19937 rng(11);
  const double sigma = 0.2, alpha = 0.001;
  int rejected_correct = 0, kept_wrong = 0;
  const int trials = 4000;
  for (int i = 0; i < trials; ++i) {
    const int n = 3 + i % 8;
    const LineFitResidual ok = NoisyFit(n, sigma, rng);
    rejected_correct += !ResidualConsistent(ok, sigma, alpha);
    // One observation 1.5 px off at both ends (a neighbouring edge): about
    // half of that offset stays in the residual of a least-squares fit.
    LineFitResidual wrong = ok;
    wrong.rms_px = std::sqrt(ok.rms_px * ok.rms_px + 2 * 0.75 * 0.75 / (2.0 * n));
    kept_wrong += ResidualConsistent(wrong, sigma, alpha);
  }
  // alpha = 0.001: about 4 of 4000 correct lines; 20 would be a wrong quantile.
  EXPECT_LE(rejected_correct, 20);
  EXPECT_LT(kept_wrong, trials / 10);
}

TEST(ResidualConsistent, TwoViewLinesAndTheSwitchAlwaysPass) {
  EXPECT_TRUE(ResidualConsistent({5.0, 2}, 0.2, 0.001));
  EXPECT_TRUE(ResidualConsistent({5.0, 6}, 0.2, 0.0));
  EXPECT_FALSE(ResidualConsistent({5.0, 6}, 0.2, 0.001));
}

}  // namespace
}  // namespace roofsweep
