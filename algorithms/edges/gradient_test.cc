#include "algorithms/edges/gradient.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cstdint>
#include <opencv2/imgproc.hpp>

#include "algorithms/edges/edge_points.h"
#include "algorithms/edges/extract_segments.h"
#include "algorithms/edges/synthetic_images.h"
#include "algorithms/edges/thresholds.h"

namespace roofsweep {
namespace {

// The gradient vectors of the whole field, for checking.
void Vectors(const GradientField& g, cv::Mat& gx, cv::Mat& gy) {
  gx = cv::Mat::zeros(g.magnitude.size(), CV_32F);
  gy = cv::Mat::zeros(g.magnitude.size(), CV_32F);
  for (int y = 1; y < g.magnitude.rows - 1; ++y) {
    GradientRow(g, y, nullptr, gx.ptr<float>(y), gy.ptr<float>(y));
  }
}

// A field whose gradient direction is along x (ramp along x) or y, with a
// given magnitude image, for the non-maximum suppression tests.
GradientField FieldWithMagnitude(const cv::Mat& magnitude, bool along_x) {
  GradientField g;
  g.method = GradientMethod::kGrey;
  g.magnitude = magnitude;
  cv::Mat ramp(magnitude.size(), CV_32F);
  for (int y = 0; y < ramp.rows; ++y)
    for (int x = 0; x < ramp.cols; ++x) ramp.at<float>(y, x) = static_cast<float>(along_x ? x : y);
  g.smoothed = {ramp};
  g.horizontal = cv::Mat::zeros(magnitude.size(), CV_8U);
  g.horizontal(cv::Rect(1, 1, magnitude.cols - 2, magnitude.rows - 2)).setTo(along_x ? 1 : 0);
  return g;
}

cv::Mat RandomColour(int w, int h, std::uint64_t seed) {
  cv::Mat image(h, w, CV_32FC3);
  cv::RNG rng(seed);
  rng.fill(image, cv::RNG::UNIFORM, 0.0, 1.0);
  return image;
}

TEST(Gradient, MaxPicksTheStrongestBand) {
  const cv::Mat image = RandomColour(20, 16, 1);
  const GradientField g =
      ComputeGradient(GradientPlanes(image, GradientMethod::kMax), GradientMethod::kMax, 0.0);
  cv::Mat gx, gy;
  Vectors(g, gx, gy);
  for (int y = 1; y < 15; ++y) {
    for (int x = 1; x < 19; ++x) {
      double best = -1;
      int band = -1;
      double bx = 0, by = 0;
      for (int b = 0; b < 3; ++b) {
        const double dx =
            0.5 * (image.at<cv::Vec3f>(y, x + 1)[b] - image.at<cv::Vec3f>(y, x - 1)[b]);
        const double dy =
            0.5 * (image.at<cv::Vec3f>(y + 1, x)[b] - image.at<cv::Vec3f>(y - 1, x)[b]);
        if (std::hypot(dx, dy) > best) {
          best = std::hypot(dx, dy);
          band = b;
          bx = dx;
          by = dy;
        }
      }
      EXPECT_NEAR(g.magnitude.at<float>(y, x), best, 1e-5);
      EXPECT_EQ(CarryingBand(g, x, y), static_cast<EdgeBand>(band));
      EXPECT_NEAR(gx.at<float>(y, x), bx, 1e-5);
      EXPECT_NEAR(gy.at<float>(y, x), by, 1e-5);
    }
  }
  EXPECT_EQ(g.magnitude.at<float>(0, 5), 0.f);  // border
}

TEST(Gradient, DiZenzoClosedFormMatchesEigenDecomposition) {
  const cv::Mat image = RandomColour(18, 14, 2);
  const GradientField g = ComputeGradient(GradientPlanes(image, GradientMethod::kDiZenzo),
                                          GradientMethod::kDiZenzo, 0.0);
  EXPECT_EQ(CarryingBand(g, 5, 5), EdgeBand::kFused);
  cv::Mat gx, gy;
  Vectors(g, gx, gy);
  for (int y = 1; y < 13; ++y) {
    for (int x = 1; x < 17; ++x) {
      Eigen::Matrix<double, 3, 2> j;
      for (int b = 0; b < 3; ++b) {
        j(b, 0) = 0.5 * (image.at<cv::Vec3f>(y, x + 1)[b] - image.at<cv::Vec3f>(y, x - 1)[b]);
        j(b, 1) = 0.5 * (image.at<cv::Vec3f>(y + 1, x)[b] - image.at<cv::Vec3f>(y - 1, x)[b]);
      }
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(j.transpose() * j);
      const double lambda = es.eigenvalues()(1);
      const Eigen::Vector2d ev = es.eigenvectors().col(1);
      EXPECT_NEAR(g.magnitude.at<float>(y, x), std::sqrt(lambda), 1e-5);
      const Eigen::Vector2d got(gx.at<float>(y, x), gy.at<float>(y, x));
      EXPECT_NEAR(got.norm(), std::sqrt(lambda), 1e-5);
      EXPECT_NEAR(std::fabs(got.normalized().dot(ev)), 1.0, 1e-3);
    }
  }
}

TEST(Gradient, DiZenzoSignFollowsTheStrongestBand) {
  // Red rises to the right strongly, blue falls: the direction is +x.
  cv::Mat image(5, 5, CV_32FC3);
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 5; ++x)
      image.at<cv::Vec3f>(y, x) = cv::Vec3f(0.2f * x, 0.5f, 0.5f - 0.05f * x);
  const GradientField g = ComputeGradient(GradientPlanes(image, GradientMethod::kDiZenzo),
                                          GradientMethod::kDiZenzo, 0.0);
  cv::Mat gx, gy;
  Vectors(g, gx, gy);
  EXPECT_GT(gx.at<float>(2, 2), 0.f);
  EXPECT_NEAR(g.magnitude.at<float>(2, 2), std::hypot(0.2, 0.05), 1e-5);
}

TEST(Gradient, GreyUsesLuma) {
  cv::Mat image(5, 5, CV_32FC3);
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 5; ++x) image.at<cv::Vec3f>(y, x) = cv::Vec3f(0.1f * x, 0.f, 0.f);
  const auto planes = GradientPlanes(image, GradientMethod::kGrey);
  ASSERT_EQ(planes.size(), 1u);
  const GradientField g = ComputeGradient(planes, GradientMethod::kGrey, 0.0);
  EXPECT_NEAR(g.magnitude.at<float>(2, 2), 0.299 * 0.1, 1e-5);
}

// GradientAt and the axis plane must agree with GradientRow to the bit:
// DetectEdgePoints takes the axis from the plane and the vectors from
// GradientAt, where it used to take both from GradientRow.
TEST(Gradient, AtAPixelAndTheAxisEqualTheRow) {
  const cv::Mat colour = RandomColour(37, 23, 4);
  cv::Mat grey;
  cv::cvtColor(colour, grey, cv::COLOR_RGB2GRAY);
  for (const cv::Mat& image : {colour, grey}) {
    for (GradientMethod method :
         {GradientMethod::kMax, GradientMethod::kDiZenzo, GradientMethod::kGrey}) {
      const GradientField g = ComputeGradient(GradientPlanes(image, method), method, 1.0);
      cv::Mat gx, gy;
      Vectors(g, gx, gy);
      const int w = image.cols, h = image.rows;
      for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
          const bool border = x == 0 || y == 0 || x == w - 1 || y == h - 1;
          const int want =
              border ? 0 : std::fabs(gx.at<float>(y, x)) >= std::fabs(gy.at<float>(y, x));
          ASSERT_EQ(g.horizontal.at<std::uint8_t>(y, x), want) << x << "," << y;
          if (border) continue;
          const GradientVector v = GradientAt(g, x, y);
          ASSERT_EQ(v.gx, gx.at<float>(y, x)) << x << "," << y;
          ASSERT_EQ(v.gy, gy.at<float>(y, x)) << x << "," << y;
        }
      }
      const EdgeBand fixed = image.channels() == 1 || method == GradientMethod::kGrey
                                 ? EdgeBand::kGrey
                                 : EdgeBand::kFused;
      if (image.channels() == 1 || method != GradientMethod::kMax) {
        EXPECT_EQ(GradientAt(g, 3, 4).band, fixed);
      }
    }
  }
}

TEST(Gradient, RejectsMismatchedPlanes) {
  const cv::Mat image = RandomColour(8, 8, 3);
  EXPECT_ANY_THROW(
      ComputeGradient(GradientPlanes(image, GradientMethod::kMax), GradientMethod::kGrey, 1.0));
  EXPECT_ANY_THROW(ComputeGradient({}, GradientMethod::kMax, 1.0));
}

TEST(Thresholds, AutomaticRuleFollowsTheNoise) {
  // Pure noise of standard deviation s: smoothed, its gradient is Rayleigh
  // with a scale proportional to s, so the thresholds scale with s.
  EdgeOptions o;
  float highs[2];
  for (int k = 0; k < 2; ++k) {
    cv::Mat image(200, 200, CV_32FC3, cv::Scalar::all(0.5));
    testing::AddNoise(image, k == 0 ? 0.03 : 0.09, 9);
    const GradientField g = ComputeGradient(GradientPlanes(image, GradientMethod::kGrey),
                                            GradientMethod::kGrey, o.sigma);
    const HysteresisThresholds t = ChooseThresholds(g.magnitude, o);
    EXPECT_NEAR(t.high, o.auto_high_factor * t.noise, 1e-6);
    EXPECT_NEAR(t.low, o.auto_low_ratio * t.high, 1e-6);
    highs[k] = t.high;
    // Pure noise gives no straight segments.
    EXPECT_LE(ExtractSegments(image, o).size(), 1u);
  }
  EXPECT_NEAR(highs[1] / highs[0], 3.0, 0.2);
  // Explicit thresholds win; no noise falls back to the floor.
  o.high_threshold = 0.2;
  o.low_threshold = 0.1;
  const HysteresisThresholds t = ChooseThresholds(cv::Mat::zeros(10, 10, CV_32F), o);
  EXPECT_FLOAT_EQ(t.high, 0.2f);
  EXPECT_FLOAT_EQ(t.low, 0.1f);
  const HysteresisThresholds floor =
      ChooseThresholds(cv::Mat::zeros(10, 10, CV_32F), EdgeOptions{});
  EXPECT_FLOAT_EQ(floor.high, static_cast<float>(EdgeOptions{}.auto_min_high));
}

TEST(EdgePoints, HysteresisKeepsWeakPointsConnectedToStrongOnes) {
  // Vertical gradient: a horizontal edge on row 3, strong at x = 2 only,
  // and a weak run on row 5, not connected to it (row 4 is zero).
  cv::Mat magnitude = cv::Mat::zeros(7, 12, CV_32F);
  for (int x = 1; x < 11; ++x) magnitude.at<float>(3, x) = x == 2 ? 1.0f : 0.3f;
  for (int x = 1; x < 5; ++x) magnitude.at<float>(5, x) = 0.3f;
  const GradientField g = FieldWithMagnitude(magnitude, false);
  EXPECT_EQ(DetectEdgePoints(g, 0.2f, 0.2f).points.size(), 14u);
  const EdgeMap map = DetectEdgePoints(g, 0.2f, 0.9f);
  EXPECT_EQ(map.points.size(), 10u);
  for (const auto& p : map.points) {
    EXPECT_EQ(p.py, 3);
    EXPECT_EQ(map.index.at<int>(p.py, p.px), &p - map.points.data());
    EXPECT_FLOAT_EQ(p.y, 3.5f);
  }
  EXPECT_EQ(map.index.at<int>(5, 2), -1);
}

TEST(EdgePoints, ParabolicSubPixelOffset) {
  GradientField g = FieldWithMagnitude(cv::Mat::zeros(5, 7, CV_32F), true);
  // Samples of the parabola 1 - (x - 3.3)^2 / 10 at x = 2, 3, 4.
  auto f = [](double x) { return static_cast<float>(1 - (x - 3.3) * (x - 3.3) / 10); };
  for (int y = 1; y < 4; ++y) {
    g.magnitude.at<float>(y, 2) = f(2);
    g.magnitude.at<float>(y, 3) = f(3);
    g.magnitude.at<float>(y, 4) = f(4);
  }
  const EdgeMap map = DetectEdgePoints(g, 0.1f, 0.1f);
  ASSERT_EQ(map.points.size(), 3u);
  EXPECT_NEAR(map.points[0].x, 3.3 + 0.5, 1e-5);  // pixel 3's centre is at 3.5
}

}  // namespace
}  // namespace roofsweep
