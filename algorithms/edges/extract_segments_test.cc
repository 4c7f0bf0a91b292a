#include "algorithms/edges/extract_segments.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "algorithms/core/error.h"
#include "algorithms/edges/segment_fusion.h"
#include "algorithms/edges/segment_geometry.h"
#include "algorithms/edges/synthetic_images.h"

namespace roofsweep {
namespace {

using testing::AddNoise;
using testing::Luma;
using testing::RenderHalfPlanes;
using testing::RenderRegions;

// The true edge line through `point` at `angle_deg`, clipped to the image
// shrunk by `margin` px (the outermost pixels have no gradient).
Segment2D TrueEdge(const Eigen::Vector2d& point, double angle_deg, cv::Size size, double margin) {
  const double a = angle_deg * M_PI / 180.0;
  const Eigen::Vector2d d(std::cos(a), std::sin(a));
  double lo = -1e9, hi = 1e9;
  const double mins[2] = {margin, margin};
  const double maxs[2] = {size.width - margin, size.height - margin};
  for (int k = 0; k < 2; ++k) {
    if (std::fabs(d[k]) < 1e-12) continue;
    double t0 = (mins[k] - point[k]) / d[k];
    double t1 = (maxs[k] - point[k]) / d[k];
    if (t0 > t1) std::swap(t0, t1);
    lo = std::max(lo, t0);
    hi = std::min(hi, t1);
  }
  Segment2D s;
  s.p0 = point + lo * d;
  s.p1 = point + hi * d;
  return s;
}

// Best coverage of `truth` by one segment (within 2 px, 5°).
double BestCoverage(const Segment2D& truth, const Segments2D& found) {
  double best = 0;
  for (const auto& s : found) best = std::max(best, CoveredFraction(truth, s, 2.0, 5.0));
  return best;
}

EdgeOptions WithMethod(GradientMethod m) {
  EdgeOptions o;
  o.method = m;
  return o;
}

cv::Vec3f IsoluminantPartner(const cv::Vec3f& c, float r, float g) {
  // Solve for blue so that the partner has exactly the same luma.
  const float b = (Luma(c) - 0.299f * r - 0.587f * g) / 0.114f;
  return {r, g, b};
}

// (a) Equal luminance, different hue.
TEST(ExtractSegments, IsoluminantHueEdgeFoundByColourMethodsOnly) {
  const cv::Size size(160, 160);
  const Eigen::Vector2d point(80.3, 79.6);
  const cv::Vec3f left(0.70f, 0.35f, 0.40f);
  const cv::Vec3f right = IsoluminantPartner(left, 0.30f, 0.55f);
  ASSERT_GT(right[2], 0.f);
  ASSERT_LT(right[2], 1.f);
  cv::Mat image = RenderHalfPlanes(size, point, 30.0, left, right);
  AddNoise(image, 0.004, 7);
  const Segment2D truth = TrueEdge(point, 30.0, size, 4);

  EXPECT_GT(BestCoverage(truth, ExtractSegments(image, WithMethod(GradientMethod::kMax))), 0.9);
  EXPECT_GT(BestCoverage(truth, ExtractSegments(image, WithMethod(GradientMethod::kDiZenzo))), 0.9);
  EXPECT_LT(BestCoverage(truth, ExtractSegments(image, WithMethod(GradientMethod::kGrey))), 0.1);
}

// (b) The same colour, only the shading differs (a ridge between two faces).
TEST(ExtractSegments, ShadingEdgeFoundByAllMethods) {
  const cv::Size size(160, 160);
  const Eigen::Vector2d point(70.2, 90.7);
  const cv::Vec3f bright(0.62f, 0.31f, 0.22f);
  const cv::Vec3f dark = bright * 0.75f;
  cv::Mat image = RenderHalfPlanes(size, point, -62.0, bright, dark);
  AddNoise(image, 0.004, 8);
  const Segment2D truth = TrueEdge(point, -62.0, size, 4);
  for (GradientMethod m : {GradientMethod::kMax, GradientMethod::kDiZenzo, GradientMethod::kGrey}) {
    const Segments2D found = ExtractSegments(image, WithMethod(m));
    EXPECT_GT(BestCoverage(truth, found), 0.9) << static_cast<int>(m);
    ASSERT_FALSE(found.empty());
    // The longest one is the edge: brighter side on the left, side colours
    // close to the two faces.
    const Segment2D& s = found.front();
    EXPECT_GT(s.LeftNormal().dot(
                  Eigen::Vector2d(std::sin(-62.0 * M_PI / 180), -std::cos(-62.0 * M_PI / 180))),
              0.99);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(s.colour_left[k], bright[k], 0.02);
      EXPECT_NEAR(s.colour_right[k], dark[k], 0.02);
    }
    // A step h blurred with sigma 1 peaks at about h / sqrt(2 pi) = 0.4 h;
    // h is the red step (max), the colour step's norm (Di Zenzo), the luma step.
    const float h = m == GradientMethod::kMax       ? bright[0] - dark[0]
                    : m == GradientMethod::kDiZenzo ? static_cast<float>(cv::norm(bright - dark))
                                                    : Luma(bright) - Luma(dark);
    EXPECT_GT(s.contrast, 0.3f * h);
    EXPECT_LT(s.contrast, 0.41f * h);
    EXPECT_LT(s.rms_residual, 0.1f);
    const EdgeBand expected = m == GradientMethod::kMax       ? EdgeBand::kRed  // largest step
                              : m == GradientMethod::kDiZenzo ? EdgeBand::kFused
                                                              : EdgeBand::kGrey;
    EXPECT_EQ(s.band, expected);
  }
}

// (c) Sub-pixel accuracy on an anti-aliased straight edge.
TEST(ExtractSegments, SubPixelAccuracyOnAntiAliasedEdge) {
  const cv::Size size(200, 200);
  const Eigen::Vector2d point(100.37, 99.81);
  for (double angle : {0.0, 7.3, 23.3, 45.0, 61.7, 90.0, 118.4, 152.9}) {
    for (double noise : {0.0, 0.01}) {
      cv::Mat image = RenderHalfPlanes(size, point, angle, cv::Vec3f(0.72f, 0.66f, 0.55f),
                                       cv::Vec3f(0.31f, 0.30f, 0.33f));
      if (noise > 0) AddNoise(image, noise, 11);
      const Segments2D found = ExtractSegments(image, EdgeOptions{});
      ASSERT_FALSE(found.empty()) << angle;
      const Segment2D& s = found.front();
      const double a = angle * M_PI / 180;
      const Eigen::Vector2d n(std::sin(a), -std::cos(a));
      const double e0 = (s.p0 - point).dot(n);
      const double e1 = (s.p1 - point).dot(n);
      const double angle_error =
          std::acos(std::min(
              1.0, std::fabs(s.Direction().dot(Eigen::Vector2d(std::cos(a), std::sin(a)))))) *
          180 / M_PI;
      EXPECT_LT(std::fabs(e0), 0.1) << "angle " << angle << " noise " << noise;
      EXPECT_LT(std::fabs(e1), 0.1) << "angle " << angle << " noise " << noise;
      EXPECT_LT(angle_error, 0.2) << "angle " << angle << " noise " << noise;
      EXPECT_GT(s.Length(), 150.0) << angle;
    }
  }
}

// (d) A circle must not become many short segments.
TEST(ExtractSegments, CircleIsNotCutIntoShortSegments) {
  const cv::Size size(200, 200);
  for (double radius : {40.0, 60.0, 80.0}) {
    cv::Mat image = RenderRegions(
        size, [&](double x, double y) { return std::hypot(x - 100.4, y - 99.7) < radius ? 0 : 1; },
        {cv::Vec3f(0.8f, 0.7f, 0.3f), cv::Vec3f(0.2f, 0.3f, 0.4f)});
    AddNoise(image, 0.005, 3);
    for (GradientMethod m :
         {GradientMethod::kMax, GradientMethod::kDiZenzo, GradientMethod::kGrey}) {
      const Segments2D found = ExtractSegments(image, WithMethod(m));
      EXPECT_LE(found.size(), 2u) << "radius " << radius;
    }
  }
}

// A polygon, by contrast, gives one segment per side.
TEST(ExtractSegments, RotatedSquareGivesFourSides) {
  const cv::Size size(200, 200);
  const double a = 0.3;
  const Eigen::Vector2d c(100.2, 99.6), u(std::cos(a), std::sin(a)), v(-std::sin(a), std::cos(a));
  cv::Mat image =
      RenderRegions(size,
                    [&](double x, double y) {
                      const Eigen::Vector2d p = Eigen::Vector2d(x, y) - c;
                      return std::fabs(p.dot(u)) < 50 && std::fabs(p.dot(v)) < 50 ? 0 : 1;
                    },
                    {cv::Vec3f(0.7f, 0.4f, 0.3f), cv::Vec3f(0.3f, 0.35f, 0.3f)});
  AddNoise(image, 0.005, 4);
  const Segments2D found = ExtractSegments(image, EdgeOptions{});
  ASSERT_EQ(found.size(), 4u);
  for (const auto& s : found) {
    EXPECT_GT(s.Length(), 90.0);
    // Bright inside on the left: the left normal points to the centre.
    EXPECT_GT(s.LeftNormal().dot(c - s.Midpoint()), 0);
  }
}

// (f) Minimum length.
TEST(ExtractSegments, MinimumLengthRespected) {
  const cv::Size size(220, 120);
  // Squares of side 8, 12, 18, 26 and 40 px.
  const double sides[5] = {8, 12, 18, 26, 40};
  const double xs[5] = {10, 35, 65, 100, 150};
  cv::Mat image = RenderRegions(
      size,
      [&](double x, double y) {
        for (int k = 0; k < 5; ++k) {
          if (x > xs[k] + 0.3 && x < xs[k] + 0.3 + sides[k] && y > 40.6 && y < 40.6 + sides[k]) {
            return 0;
          }
        }
        return 1;
      },
      {cv::Vec3f(0.8f, 0.8f, 0.7f), cv::Vec3f(0.2f, 0.25f, 0.2f)});
  for (double min_length : {15.0, 25.0}) {
    EdgeOptions o;
    o.min_length = min_length;
    const Segments2D found = ExtractSegments(image, o);
    ASSERT_FALSE(found.empty());
    for (const auto& s : found) EXPECT_GE(s.Length(), min_length);
    // The 40 px square's sides survive both (its straight part is ~36 px).
    int long_sides = 0;
    for (const auto& s : found) long_sides += s.Length() > 30 ? 1 : 0;
    EXPECT_EQ(long_sides, 4);
  }
  EdgeOptions o;
  o.min_length = 15;
  int short_ones = 0;
  for (const auto& s : ExtractSegments(image, o)) short_ones += s.Length() < 25 ? 1 : 0;
  EXPECT_GT(short_ones, 0);  // the 18 and 26 px squares give some at 15 px
}

TEST(ExtractSegments, FusionAddsTheEdgesOnlyTheOtherMethodSees) {
  const cv::Size size(160, 160);
  const cv::Vec3f a(0.70f, 0.35f, 0.40f);
  const cv::Vec3f b = IsoluminantPartner(a, 0.30f, 0.55f);
  const cv::Vec3f c = a * 0.6f;
  // Vertical isoluminant edge at x = 60.3, horizontal shading edge at
  // y = 110.6 below it.
  cv::Mat image = RenderRegions(
      size, [&](double x, double y) { return y > 110.6 ? 2 : (x < 60.3 ? 0 : 1); }, {a, b, c});
  AddNoise(image, 0.004, 5);
  const Segment2D hue = TrueEdge({60.3, 50}, 90, cv::Size(160, 110), 4);
  const Segment2D shade = TrueEdge({50, 110.6}, 0, size, 4);

  EdgeOptions grey = WithMethod(GradientMethod::kGrey);
  const Segments2D alone = ExtractSegments(image, grey);
  EXPECT_LT(BestCoverage(hue, alone), 0.1);
  EXPECT_GT(BestCoverage(shade, alone), 0.9);
  grey.fuse_methods = {GradientMethod::kMax};
  const Segments2D fused = ExtractSegments(image, grey);
  EXPECT_GT(BestCoverage(hue, fused), 0.8);
  EXPECT_GT(BestCoverage(shade, fused), 0.9);
  // The shading edge, which both see, is not added twice.
  int shade_copies = 0;
  for (const auto& s : fused) shade_copies += CoveredFraction(s, shade, 2.0, 5.0) > 0.5 ? 1 : 0;
  EXPECT_EQ(shade_copies, 1);
  int from_max = 0;
  for (const auto& s : fused) from_max += s.method == GradientMethod::kMax ? 1 : 0;
  EXPECT_GE(from_max, 1);
}

// A hip between two tiled faces: each face carries dark tile courses every
// 6 px along its own eave (horizontal on one side, vertical on the other),
// the faces differ in shading, and the hip runs at 45° between them, so
// the courses meet it at 45° on both sides.
// A hip between two tiled faces: each face carries tile courses, 10 %
// darker, every 8 px along its own eave (horizontal on one side, vertical on
// the other), the faces differ in shading by 15 %, and the hip runs at 45°
// between them, so the courses meet it at 45° on both sides. (With courses
// 20 % darker, neither scale finds it.)
TEST(ExtractSegments, CoarseFusionFindsTheHipBetweenTiledFaces) {
  const cv::Size size(240, 240);
  const cv::Vec3f light(0.62f, 0.30f, 0.22f), shaded = light * 0.85f;
  auto course = [](double v) { return std::fmod(v, 8.0) < 2.0; };
  cv::Mat image = RenderRegions(
      size,
      [&](double x, double y) {
        const bool above = y < x;  // the hip is the diagonal y = x
        return above ? (course(y) ? 1 : 0) : (course(x) ? 3 : 2);
      },
      {light, light * 0.9f, shaded, shaded * 0.9f}, 4);
  AddNoise(image, 0.004, 9);
  const Segment2D hip = TrueEdge({120, 120}, 45, size, 30);

  const Segments2D alone = ExtractSegments(image, EdgeOptions{});
  EdgeOptions coarse;
  coarse.coarse_fusion = true;
  const Segments2D fused = ExtractSegments(image, coarse);

  double covered_alone = 0, covered_fused = 0;
  int from_coarse = 0;
  for (const auto& s : alone) covered_alone += CoveredFraction(hip, s, 2.0, 5.0);
  for (const auto& s : fused) {
    covered_fused += CoveredFraction(hip, s, 2.0, 5.0);
    from_coarse += s.scale == 2 ? 1 : 0;
  }
  EXPECT_LT(covered_alone, 0.3);
  EXPECT_GT(covered_fused, 0.8);
  EXPECT_GE(from_coarse, 1);
  // What the full resolution found stays as it was.
  int full_resolution = 0;
  for (const auto& s : fused) full_resolution += s.scale == 1 ? 1 : 0;
  EXPECT_EQ(full_resolution, static_cast<int>(alone.size()));
}

TEST(AddUncoveredParts, AddsOnlyTheGapsLongEnough) {
  auto seg = [](double x0, double y0, double x1, double y1) {
    Segment2D s;
    s.p0 = {x0, y0};
    s.p1 = {x1, y1};
    s.support = 100;
    return s;
  };
  // Covered over [0, 40] and [50, 70] (1 px off the line), not beyond 70.
  Segments2D base = {seg(0, 10, 40, 10), seg(50, 11, 70, 11), seg(80, 40, 100, 60)};
  const Segments2D extra = {seg(0, 10, 100, 10)};
  EXPECT_EQ(AddUncoveredParts(base, extra, 2.0, 5.0, 15.0), 1);
  ASSERT_EQ(base.size(), 4u);
  // The 10 px gap is too short; [70, 100] is added with the attributes of
  // its segment and its share of the support.
  EXPECT_NEAR(base[3].p0.x(), 70, 1e-9);
  EXPECT_NEAR(base[3].p1.x(), 100, 1e-9);
  EXPECT_NEAR(base[3].p0.y(), 10, 1e-9);
  EXPECT_EQ(base[3].support, 30);
  // A segment that is present is not added again, nor one too short.
  Segments2D again = base;
  EXPECT_EQ(AddUncoveredParts(again, {seg(5, 10, 35, 10), seg(0, 30, 10, 30)}, 2.0, 5.0, 15.0), 0);
  // Beyond the distance nothing covers it.
  EXPECT_EQ(AddUncoveredParts(again, {seg(0, 14, 40, 14)}, 2.0, 5.0, 15.0), 1);
}

TEST(ExtractSegments, Deterministic) {
  const cv::Mat image = testing::RenderRoofScene(cv::Size(300, 240), 42);
  const Segments2D a = ExtractSegments(image, EdgeOptions{});
  const Segments2D b = ExtractSegments(image, EdgeOptions{});
  ASSERT_EQ(a.size(), b.size());
  ASSERT_GT(a.size(), 20u);
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].p0, b[i].p0);
    EXPECT_EQ(a[i].p1, b[i].p1);
  }
  for (size_t i = 1; i < a.size(); ++i) EXPECT_GE(a[i - 1].Length(), a[i].Length());
}

// (i) Bad inputs.
TEST(ExtractSegments, GreyImageUsesTheGreyMethod) {
  const cv::Mat colour = RenderHalfPlanes(cv::Size(100, 100), {50.2, 50.7}, 12,
                                          cv::Vec3f::all(0.7f), cv::Vec3f::all(0.3f));
  cv::Mat grey;
  cv::extractChannel(colour, grey, 0);
  const Segments2D found = ExtractSegments(grey, EdgeOptions{});  // method kMax asked
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].method, GradientMethod::kGrey);
  EXPECT_EQ(found[0].band, EdgeBand::kGrey);
  EXPECT_NEAR(found[0].colour_left[0], 0.7f, 0.02);
  EXPECT_NEAR(found[0].colour_left[2], 0.7f, 0.02);
}

TEST(ExtractSegments, SixteenBitDerivedLowRangeData) {
  // 12-bit data in a 16-bit container, scaled by 65535: values <= 0.0625.
  cv::Mat image =
      RenderHalfPlanes(cv::Size(120, 120), {60.3, 60.1}, 33, cv::Vec3f(0.040f, 0.038f, 0.036f),
                       cv::Vec3f(0.030f, 0.029f, 0.027f));
  image.forEach<cv::Vec3f>([](cv::Vec3f& p, const int*) {
    for (int k = 0; k < 3; ++k) p[k] = std::round(p[k] * 65535.f) / 65535.f;
  });
  const Segments2D found = ExtractSegments(image, EdgeOptions{});
  ASSERT_EQ(found.size(), 1u);
  EXPECT_GT(found[0].Length(), 100);
}

TEST(ExtractSegments, AllBlackAndTinyImagesGiveNothing) {
  EXPECT_TRUE(ExtractSegments(cv::Mat::zeros(64, 64, CV_32FC3), EdgeOptions{}).empty());
  EXPECT_TRUE(ExtractSegments(cv::Mat::zeros(64, 64, CV_32FC1), EdgeOptions{}).empty());
  EXPECT_TRUE(
      ExtractSegments(cv::Mat(1, 1, CV_32FC3, cv::Scalar(0.5, 0.2, 0.1)), EdgeOptions{}).empty());
  EXPECT_TRUE(
      ExtractSegments(cv::Mat(2, 50, CV_32FC3, cv::Scalar(0.5, 0.2, 0.1)), EdgeOptions{}).empty());
  cv::Mat stripe(3, 3, CV_32FC1, cv::Scalar(0));
  stripe.col(2).setTo(1);
  EXPECT_TRUE(ExtractSegments(stripe, EdgeOptions{}).empty());
}

TEST(ExtractSegments, RejectsEmptyWrongTypeAndNaN) {
  EXPECT_THROW(ExtractSegments(cv::Mat(), EdgeOptions{}), Error);
  EXPECT_THROW(ExtractSegments(cv::Mat::zeros(10, 10, CV_8UC3), EdgeOptions{}), Error);
  EXPECT_THROW(ExtractSegments(cv::Mat::zeros(10, 10, CV_16UC1), EdgeOptions{}), Error);
  EXPECT_THROW(ExtractSegments(cv::Mat::zeros(10, 10, CV_32FC4), EdgeOptions{}), Error);
  EXPECT_THROW(ExtractSegments(cv::Mat::zeros(10, 10, CV_64FC3), EdgeOptions{}), Error);
  cv::Mat nan_image(20, 20, CV_32FC3, cv::Scalar(0.5, 0.5, 0.5));
  nan_image.at<cv::Vec3f>(7, 3)[1] = std::numeric_limits<float>::quiet_NaN();
  try {
    ExtractSegments(nan_image, EdgeOptions{});
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("x=3, y=7"), std::string::npos) << e.what();
  }
  cv::Mat inf_image(20, 20, CV_32FC1, cv::Scalar(0.5));
  inf_image.at<float>(2, 2) = std::numeric_limits<float>::infinity();
  EXPECT_THROW(ExtractSegments(inf_image, EdgeOptions{}), Error);
  // +inf and -inf together sum to NaN, and are found too.
  inf_image.at<float>(5, 9) = -std::numeric_limits<float>::infinity();
  try {
    ExtractSegments(inf_image, EdgeOptions{});
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("x=2, y=2"), std::string::npos) << e.what();
  }
}

TEST(ExtractSegments, RejectsBadOptions) {
  const cv::Mat image = cv::Mat::zeros(10, 10, CV_32FC3);
  EdgeOptions o;
  o.sigma = -1;
  EXPECT_THROW(ExtractSegments(image, o), Error);
  o = EdgeOptions{};
  o.sigma = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(ExtractSegments(image, o), Error);
  o = EdgeOptions{};
  o.fit_max_deviation = 0;
  EXPECT_THROW(ExtractSegments(image, o), Error);
  o = EdgeOptions{};
  o.min_support = 1;
  EXPECT_THROW(ExtractSegments(image, o), Error);
}

TEST(ExtractSegments, RegionOfInterestViewWorks) {
  const cv::Mat big = RenderHalfPlanes(cv::Size(200, 200), {100.2, 100.7}, 20,
                                       cv::Vec3f(0.7f, 0.6f, 0.5f), cv::Vec3f(0.3f, 0.3f, 0.3f));
  const cv::Mat view = big(cv::Rect(50, 50, 100, 100));  // not continuous
  ASSERT_FALSE(view.isContinuous());
  const Segments2D found = ExtractSegments(view, EdgeOptions{});
  ASSERT_EQ(found.size(), 1u);
  // The line passes (50.2, 50.7) in the view's own coordinates.
  const Eigen::Vector2d n = found[0].LeftNormal();
  EXPECT_LT(std::fabs((found[0].p0 - Eigen::Vector2d(50.2, 50.7)).dot(n)), 0.1);
}

}  // namespace
}  // namespace roofsweep
