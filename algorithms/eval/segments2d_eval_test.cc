#include "algorithms/eval/segments2d_eval.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "algorithms/eval/test_models.h"

namespace roofsweep {
namespace eval {
namespace {

sim::TrueEdge Edge(double x0, double y0, double x1, double y1, sim::EdgeKind kind) {
  sim::TrueEdge e;
  e.a = Eigen::Vector3d(x0, y0, 0);
  e.b = Eigen::Vector3d(x1, y1, 0);
  e.kind = kind;
  e.building = 0;
  return e;
}

Segment2D Seg(double x0, double y0, double x1, double y1) {
  Segment2D s;
  s.p0 = Eigen::Vector2d(x0, y0);
  s.p1 = Eigen::Vector2d(x1, y1);
  return s;
}

const VisibilityFn kAllVisible = [](const Eigen::Vector2d&, double) { return true; };

TEST(Segments2DEval, PerfectDetectionScoresOne) {
  // Ridge from pixel (50, 100) to (150, 100), detected exactly (reversed).
  const std::vector<sim::TrueEdge> truth = {Edge(-10, 0, 10, 0, sim::EdgeKind::kRidge)};
  const Segment2DScores s =
      EvaluateSegments2D(eval_test::NadirTestCamera(), eval_test::NadirTestPose(), truth,
                         kAllVisible, {Seg(150, 100, 50, 100)});
  EXPECT_NEAR(s.roof.length_px, 100.0, 1.0);
  EXPECT_DOUBLE_EQ(s.Recall(), 1.0);
  EXPECT_DOUBLE_EQ(s.Precision(), 1.0);
  EXPECT_NEAR(s.detected_px, 100.0, 1e-9);
  EXPECT_DOUBLE_EQ(s.per_kind.at(sim::EdgeKind::kRidge).Ratio(), 1.0);
  EXPECT_NEAR(s.roof_interior.length_px, 90.0, 1.0);  // 5 px off each end
}

TEST(Segments2DEval, ThreePixelShiftScoresZero) {
  const std::vector<sim::TrueEdge> truth = {Edge(-10, 0, 10, 0, sim::EdgeKind::kEave)};
  const Segment2DScores s =
      EvaluateSegments2D(eval_test::NadirTestCamera(), eval_test::NadirTestPose(), truth,
                         kAllVisible, {Seg(50, 103, 150, 103)});
  EXPECT_GT(s.roof.length_px, 90.0);
  EXPECT_DOUBLE_EQ(s.Recall(), 0.0);
  EXPECT_DOUBLE_EQ(s.Precision(), 0.0);
}

TEST(Segments2DEval, WithinOnePixelAndRotatedTenDegrees) {
  const std::vector<sim::TrueEdge> truth = {Edge(-10, 0, 10, 0, sim::EdgeKind::kRidge)};
  // 1 px off: covered.
  EXPECT_DOUBLE_EQ(EvaluateSegments2D(eval_test::NadirTestCamera(), eval_test::NadirTestPose(),
                                      truth, kAllVisible, {Seg(50, 101, 150, 101)})
                       .Recall(),
                   1.0);
  // Rotated by 10 deg about the midpoint: only the angle fails.
  const double a = 10 * M_PI / 180, h = 50;
  const Segment2DScores s = EvaluateSegments2D(eval_test::NadirTestCamera(),
                                               eval_test::NadirTestPose(), truth, kAllVisible,
                                               {Seg(100 - h * std::cos(a), 100 - h * std::sin(a),
                                                    100 + h * std::cos(a), 100 + h * std::sin(a))});
  EXPECT_DOUBLE_EQ(s.Recall(), 0.0);
  EXPECT_DOUBLE_EQ(s.Precision(), 0.0);
}

TEST(Segments2DEval, HalfCoveredAndNonRoofKinds) {
  const std::vector<sim::TrueEdge> truth = {Edge(-10, 0, 10, 0, sim::EdgeKind::kHip),
                                            Edge(-10, 10, 10, 10, sim::EdgeKind::kGroundMarking)};
  // Half of the hip; all of the marking (y = 50); a false segment at y = 150.
  const Segment2DScores s = EvaluateSegments2D(
      eval_test::NadirTestCamera(), eval_test::NadirTestPose(), truth, kAllVisible,
      {Seg(50, 100, 100, 100), Seg(50, 50, 150, 50), Seg(50, 150, 150, 150)});
  // Markings do not count in roof recall; the 1.5 px tolerance reaches past
  // the segment end by up to 2 samples.
  EXPECT_NEAR(s.Recall(), 0.51, 0.015);
  EXPECT_NEAR(s.roof_interior.Ratio(), 46.0 / 90.0, 0.02);
  EXPECT_NEAR(s.per_kind.at(sim::EdgeKind::kGroundMarking).Ratio(), 1.0, 1e-9);
  EXPECT_NEAR(s.Precision(), 150.0 / 250.0, 1e-9);
  ASSERT_EQ(s.per_segment.size(), 3u);
  EXPECT_NEAR(s.per_segment[1].Ratio(), 1.0, 1e-9);
  EXPECT_DOUBLE_EQ(s.per_segment[2].covered_px, 0.0);
}

TEST(Segments2DEval, OccludedEdgesAreExcluded) {
  // Second ridge at y = 75 hidden behind something 40 m closer.
  const std::vector<sim::TrueEdge> truth = {Edge(-10, 0, 10, 0, sim::EdgeKind::kRidge),
                                            Edge(-10, 5, 10, 5, sim::EdgeKind::kRidge)};
  cv::Mat depth(200, 200, CV_32F, cv::Scalar(100.0f));
  depth.rowRange(60, 90).setTo(60.0f);
  const Segment2DScores s =
      EvaluateSegments2D(eval_test::NadirTestCamera(), eval_test::NadirTestPose(), truth,
                         DepthMapVisibility(depth), {Seg(50, 100, 150, 100)});
  EXPECT_DOUBLE_EQ(s.per_edge[1].length_px, 0.0);
  EXPECT_NEAR(s.per_edge[0].length_px, 100.0, 1.0);
  EXPECT_DOUBLE_EQ(s.Recall(), 1.0);
  // Half hidden: only the visible half is counted.
  depth.setTo(100.0f);
  depth(cv::Rect(0, 60, 100, 30)).setTo(60.0f);
  const Segment2DScores h =
      EvaluateSegments2D(eval_test::NadirTestCamera(), eval_test::NadirTestPose(), truth,
                         DepthMapVisibility(depth), {});
  EXPECT_NEAR(h.per_edge[1].length_px, 50.0, 1.5);
}

TEST(Segments2DEval, FaceBorderVisibleThroughTheProbeInside) {
  // An eave at y = 100 whose own pixel row shows the ground 10 m deeper
  // (the face ends there): the probe 1 px inside the face (row 98) sees it.
  const std::vector<sim::TrueEdge> truth = {Edge(-10, 0, 10, 0, sim::EdgeKind::kEave)};
  cv::Mat depth(200, 200, CV_32F, cv::Scalar(110.0f));
  depth.rowRange(0, 100).setTo(100.0f);
  const Segment2DScores s =
      EvaluateSegments2D(eval_test::NadirTestCamera(), eval_test::NadirTestPose(), truth,
                         DepthMapVisibility(depth), {Seg(50, 100, 150, 100)});
  EXPECT_NEAR(s.roof.length_px, 100.0, 1.0);
  // Nothing on either side agrees: hidden (e.g. under a tree).
  depth.setTo(std::numeric_limits<float>::infinity());
  EXPECT_DOUBLE_EQ(EvaluateSegments2D(eval_test::NadirTestCamera(), eval_test::NadirTestPose(),
                                      truth, DepthMapVisibility(depth), {Seg(50, 100, 150, 100)})
                       .roof.length_px,
                   0.0);
}

TEST(Segments2DEval, ShortAndOutsideEdgesAreNotCounted) {
  // 2 m = 10 px long: below 15 px. The second lies outside the image.
  const std::vector<sim::TrueEdge> truth = {Edge(0, 0, 2, 0, sim::EdgeKind::kRidge),
                                            Edge(30, 0, 40, 0, sim::EdgeKind::kRidge)};
  const Segment2DScores s = EvaluateSegments2D(eval_test::NadirTestCamera(),
                                               eval_test::NadirTestPose(), truth, kAllVisible, {});
  EXPECT_DOUBLE_EQ(s.roof.length_px, 0.0);
  EXPECT_DOUBLE_EQ(s.Recall(), 0.0);
}

}  // namespace
}  // namespace eval
}  // namespace roofsweep
