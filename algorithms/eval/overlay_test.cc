#include "algorithms/eval/overlay.h"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "algorithms/buildings/lod1_block.h"
#include "algorithms/core/error.h"
#include "algorithms/eval/test_models.h"
#include "tests/support/shared_data.h"

namespace roofsweep {
namespace {

using V = Eigen::Vector3d;

cv::Vec3b PixelAt(const cv::Mat& img, double x, double y, double x0, double y_top, double mpp) {
  return img.at<cv::Vec3b>(static_cast<int>((y_top - y) / mpp), static_cast<int>((x - x0) / mpp));
}

TEST(Overlay, FillsMatchedAndMissedPlanesDifferently) {
  const CityModel truth = eval_test::ThreeHouses();
  CityModel result = truth;
  result.buildings.pop_back();  // the hip house is missed
  const EvalResult e = Evaluate(result, truth, {});
  OverlayOptions o;
  const cv::Mat img = RenderOverlay(result, truth, e, o);
  ASSERT_EQ(img.type(), CV_8UC3);
  // Extent x -5..99, y -5..15 at 0.1 m: a 1040 x 200 map, legend below.
  EXPECT_EQ(img.cols, 1040);
  EXPECT_GT(img.rows, 200 + 100);
  const double x0 = -5, y_top = 15;
  const cv::Vec3b matched = PixelAt(img, 45, 2, x0, y_top, 0.1);  // gable, south plane
  const cv::Vec3b missed = PixelAt(img, 87, 2, x0, y_top, 0.1);   // hip, south plane
  EXPECT_EQ(matched, cv::Vec3b(190, 235, 190));
  EXPECT_EQ(missed, cv::Vec3b(190, 190, 255));
  EXPECT_EQ(PixelAt(img, 60, 12, x0, y_top, 0.1), cv::Vec3b(255, 255, 255));

  const std::string dir = testing::TempDir("overlay");
  ASSERT_TRUE(cv::imwrite(dir + "/overlay.png", img));
  std::cout << "overlay written to " << dir << "/overlay.png\n";
}

TEST(Overlay, FalseResultPlanesAreOutlinedInMagenta) {
  const CityModel truth = eval_test::ThreeHouses();
  const CityModel result =
      eval_test::Transformed(truth, [](const V& v) { return V(v + V(2, 0.5, 0)); });
  const EvalResult e = Evaluate(result, truth, {});
  ASSERT_EQ(e.roof_planes.tp_result, 5);  // the hip ends are false
  const cv::Mat img = RenderOverlay(result, truth, e);
  cv::Mat magenta;
  cv::inRange(img, cv::Scalar(200, 0, 200), cv::Scalar(200, 0, 200), magenta);
  // Two hip-end triangles (sides 5*sqrt(2) twice and 10) at 0.1 m, 2 px
  // wide, plus the legend swatch: well over 300 fully magenta pixels.
  EXPECT_GT(cv::countNonZero(magenta), 300);
  const std::string dir = testing::TempDir("overlay_shifted");
  ASSERT_TRUE(cv::imwrite(dir + "/overlay.png", img));
  std::cout << "overlay written to " << dir << "/overlay.png\n";
}

int CountColour(const cv::Mat& img, const cv::Scalar& bgr) {
  cv::Mat mask;
  cv::inRange(img, bgr, bgr, mask);
  return cv::countNonZero(mask);
}

TEST(Overlay, Lod1BlocksAreOutlinedInOrange) {
  const CityModel truth = eval_test::ThreeHouses();
  CityModel result = truth;
  result.buildings.pop_back();  // the hip house, 14 x 10 m, has a block instead
  CityModel blocks;
  blocks.buildings.push_back(Lod1Block({{80, 0}, {94, 0}, {94, 10}, {80, 10}}, 30, 36));
  const EvalResult e = Evaluate(result, truth, {});
  const cv::Mat without = RenderOverlay(result, truth, e);
  const cv::Mat with = RenderOverlay(result, truth, e, {}, &blocks);
  const cv::Scalar orange(0, 140, 255);
  EXPECT_EQ(CountColour(without, orange), 0);
  // A 48 m outline at 0.1 m, 2 px wide, anti-aliased at the corners, and
  // the legend's swatch.
  EXPECT_GT(CountColour(with, orange), 700);
  EXPECT_EQ(with.cols, without.cols);
  EXPECT_EQ(with.rows, without.rows + 18);  // one more legend line
  const double x0 = -5, y_top = 15;
  EXPECT_EQ(PixelAt(with, 87, 0, x0, y_top, 0.1), cv::Vec3b(0, 140, 255));  // the south wall
  EXPECT_EQ(PixelAt(with, 87, 5, x0, y_top, 0.1), PixelAt(without, 87, 5, x0, y_top, 0.1));
}

TEST(Overlay, RefusesAnEvaluationOfOtherModels) {
  const CityModel m = eval_test::ThreeHouses();
  const EvalResult e = Evaluate(CityModel{}, m, {});
  EXPECT_THROW(RenderOverlay(m, m, e), Error);
}

}  // namespace
}  // namespace roofsweep
