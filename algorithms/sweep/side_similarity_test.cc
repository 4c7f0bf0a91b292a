#include "algorithms/sweep/side_similarity.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/core.hpp>
#include <vector>

#include "algorithms/geometry/view.h"
#include "algorithms/sweep/test_scene.h"

namespace roofsweep {
namespace {

cv::Mat Noise(int cols, int rows) {
  cv::Mat image(rows, cols, CV_32F);
  cv::RNG rng(7);
  rng.fill(image, cv::RNG::UNIFORM, 0.0, 1.0);
  return image;
}

// The five probes of a window of radius r centred at c whose columns step
// by dx and rows by dy (measured pixel positions).
std::array<Eigen::Vector2d, 5> Probes(const Eigen::Vector2d& c, const Eigen::Vector2d& dx,
                                      const Eigen::Vector2d& dy, int r) {
  return {c, c - r * dx, c + r * dx, c - r * dy, c + r * dy};
}

TEST(AffineWindow, SamplesLikeBilinearAtEveryPixel) {
  const cv::Mat image = Noise(64, 48);
  const int r = 3, w = 2 * r + 1;
  // Rotated, sheared and scaled, with its centre between pixels.
  const Eigen::Vector2d c(30.37, 21.81), dx(0.93, 0.27), dy(-0.31, 1.12);
  std::vector<float> values(w * w);
  ASSERT_TRUE(AffineWindow(Probes(c, dx, dy, r), r).Sample(image, values.data()));
  for (int iy = -r, k = 0; iy <= r; ++iy)
    for (int ix = -r; ix <= r; ++ix, ++k) {
      const Eigen::Vector2d p = c + ix * dx + iy * dy;
      float expected;
      ASSERT_TRUE(SampleBilinear(image, p.x() - 0.5, p.y() - 0.5, &expected));
      EXPECT_NEAR(values[k], expected, 1e-5) << ix << " " << iy;
    }
}

TEST(AffineWindow, ReachesTheLastPixelAndRefusesBeyond) {
  const cv::Mat image = Noise(20, 16);
  const int r = 2, w = 2 * r + 1;
  std::vector<float> values(w * w);
  // Pixel-aligned, its bottom-right corner on the centre of the last pixel.
  const Eigen::Vector2d dx(1, 0), dy(0, 1);
  const Eigen::Vector2d c(20 - 0.5 - r, 16 - 0.5 - r);
  ASSERT_TRUE(AffineWindow(Probes(c, dx, dy, r), r).Sample(image, values.data()));
  EXPECT_FLOAT_EQ(values[w * w - 1], image.at<float>(15, 19));
  EXPECT_FLOAT_EQ(values[0], image.at<float>(15 - 2 * r, 19 - 2 * r));
  // A hundredth of a pixel further is outside; so is a window off the left
  // edge.
  const Eigen::Vector2d off(0.01, 0);
  EXPECT_FALSE(AffineWindow(Probes(c + off, dx, dy, r), r).Sample(image, values.data()));
  EXPECT_FALSE(AffineWindow(Probes(Eigen::Vector2d(r + 0.49, 8), dx, dy, r), r)
                   .Sample(image, values.data()));
  EXPECT_TRUE(
      AffineWindow(Probes(Eigen::Vector2d(r + 0.5, 8), dx, dy, r), r).Sample(image, values.data()));
}

TEST(ZeroMeanCorrelation, NormalisedCrossCorrelation) {
  const int n = 49;
  cv::RNG rng(3);
  std::vector<float> ref(n), other(n);
  double mean = 0;
  for (float& v : ref) mean += v = static_cast<float>(rng.uniform(0.0, 1.0));
  mean /= n;
  double norm = 0;
  for (float& v : ref) {
    v -= static_cast<float>(mean);
    norm += v * v;
  }
  for (float& v : ref) v /= static_cast<float>(std::sqrt(norm));
  // Gain and offset do not change the correlation; inverting the contrast
  // flips its sign; a flat window has none.
  for (int k = 0; k < n; ++k) other[k] = 0.3f + 0.5f * ref[k];
  EXPECT_NEAR(ZeroMeanCorrelation(ref.data(), other.data(), n), 1.0, 1e-5);
  for (int k = 0; k < n; ++k) other[k] = 0.7f - 2.0f * ref[k];
  EXPECT_NEAR(ZeroMeanCorrelation(ref.data(), other.data(), n), -1.0, 1e-5);
  std::fill(other.begin(), other.end(), 0.4f);
  EXPECT_EQ(ZeroMeanCorrelation(ref.data(), other.data(), n), 0.0);
  // Against the definition, in double precision, for an unrelated window.
  for (float& v : other) v = static_cast<float>(rng.uniform(0.0, 1.0));
  double m = 0, dot = 0, ss = 0;
  for (float v : other) m += v;
  m /= n;
  for (int k = 0; k < n; ++k) dot += ref[k] * (other[k] - m), ss += (other[k] - m) * (other[k] - m);
  EXPECT_NEAR(ZeroMeanCorrelation(ref.data(), other.data(), n), dot / std::sqrt(ss), 1e-6);
}

// Sim from one table of correlations equals a fresh evaluation bit for bit,
// whichever points and views are active: the sweep judges outliers, valid
// views and its first refinement step from one table.
TEST(SideSimilarity, ReduceOfCorrelationsEqualsEvaluate) {
  sweep_test::TestScene scene;
  sweep_test::Quad face;
  face.origin = Eigen::Vector3d(-5, 0, 10);
  face.u = Eigen::Vector3d(10, 0, 0);
  face.v = Eigen::Vector3d(0, 6, -3.5);
  scene.quads = {face};
  const Block block = sweep_test::FourViewBlock();
  const std::vector<cv::Mat> images = sweep_test::RenderAll(scene, block);
  SweepOptions o;
  std::vector<ViewTexture> textures;
  for (const cv::Mat& image : images) textures.push_back(PrepareViewTexture(image, o));
  const Segment3 ridge{face.origin, face.origin + face.u};
  const auto family = HalfPlaneFamily::Make(ridge, 1, o.max_line_slope_deg);
  ASSERT_TRUE(family);
  const Camera& camera = block.CameraOf(block.views[0]);
  const auto p0 = Project(camera, block.views[0].pose, ridge.a);
  const auto p1 = Project(camera, block.views[0].pose, ridge.b);
  const auto off =
      Project(camera, block.views[0].pose, ridge.At(0.5) + Eigen::Vector3d(0, 1, -0.5));
  ASSERT_TRUE(p0 && p1 && off);
  const std::vector<BandPoint> points =
      BandPoints(textures[0], *p0, *p1, ImageSide(*p0, *p1, *off), {}, o);
  ASSERT_GE(points.size(), 20u);
  SideSimilarity sim(block, textures, *family, 0, {1, 2, 3}, points, o);
  std::vector<bool> some_points(points.size()), two_views = {true, false, true};
  for (size_t i = 0; i < points.size(); ++i) some_points[i] = i % 3 != 1;
  for (double theta_deg : {-30.0, -10.0, 20.0}) {
    const double theta = theta_deg * M_PI / 180;
    const std::vector<double> table = sim.Correlations(theta);
    for (int setting = 0; setting < 3; ++setting) {
      sim.SetActive(setting == 0 ? std::vector<bool>(points.size(), true) : some_points);
      sim.SetActiveViews(setting < 2 ? std::vector<bool>(3, true) : two_views);
      std::vector<double> point_a, point_b, view_a, view_b;
      EXPECT_EQ(sim.Reduce(table, &point_a, &view_a), sim.Evaluate(theta, &point_b, &view_b));
      EXPECT_EQ(point_a, point_b);
      EXPECT_EQ(view_a, view_b);
      EXPECT_EQ(sim.Reduce(table), sim.Evaluate(theta));
    }
  }
  // At the face's own slope the similarity is high, so the test compares
  // real correlations, not zeros.
  sim.SetActive(std::vector<bool>(points.size(), true));
  sim.SetActiveViews(std::vector<bool>(3, true));
  EXPECT_GT(sim.Evaluate(-30.26 * M_PI / 180), 0.4);
}

}  // namespace
}  // namespace roofsweep
