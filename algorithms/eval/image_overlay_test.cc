#include "algorithms/eval/image_overlay.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "algorithms/eval/test_models.h"

namespace roofsweep {
namespace {

using V = Eigen::Vector3d;

// Nadir camera 100 m above the ground, centred over the gable below.
Camera TestCamera() { return eval_test::NadirTestCamera(); }
Pose TestPose() { return eval_test::NadirTestPose(6, 4); }

// Gable 12 x 8 m, eaves 6 m, ridge along x 3 m higher.
CityModel GableModel() {
  CityModel m;
  m.buildings.push_back(eval_test::Gable("g", 0, 0, 12, 8, 0, 6, 3));
  return m;
}

// The image a camera would take of `model`'s roof: each roof face filled
// with its own colour over a uniform background, slightly blurred.
cv::Mat RenderRoofs(const CityModel& model, const std::vector<cv::Vec3f>& face_colours,
                    const cv::Vec3f& background) {
  const Camera cam = TestCamera();
  const Pose pose = TestPose();
  cv::Mat img(cam.height, cam.width, CV_32FC3,
              cv::Scalar(background[0], background[1], background[2]));
  size_t face = 0;
  for (const Surface& s : model.buildings[0].surfaces) {
    if (s.type != SurfaceType::kRoof) continue;
    std::vector<cv::Point> poly;
    for (const V& v : s.polygons[0].exterior) {
      const Eigen::Vector2d p = *Project(cam, pose, v);
      poly.emplace_back(static_cast<int>(std::lround((p.x() - 0.5) * 16)),
                        static_cast<int>(std::lround((p.y() - 0.5) * 16)));
    }
    const cv::Vec3f c = face_colours[face++ % face_colours.size()];
    cv::fillConvexPoly(img, poly, cv::Scalar(c[0], c[1], c[2]), cv::LINE_AA, 4);
  }
  cv::GaussianBlur(img, img, cv::Size(0, 0), 0.7);
  return img;
}

EdgeSupport Support(const CityModel& model, const cv::Mat& image, ImageOverlay* out = nullptr) {
  const ModelOccluder occluder(model);
  ImageOverlay o = OverlayModel(image, TestCamera(), TestPose(), ModelEdges(model),
                                static_cast<int>(model.buildings.size()), occluder);
  const EdgeSupport s = o.roof;
  if (out) *out = std::move(o);
  return s;
}

TEST(ImageOverlay, SharedEdgesCountOnceAndRoofEdgesAreRoof) {
  const std::vector<ModelEdge> edges = ModelEdges(GableModel());
  int roof = 0;
  for (const ModelEdge& e : edges) {
    roof += e.kind == ModelEdgeKind::kRoof;
    EXPECT_EQ(e.building, 0);
  }
  // Ground 4, wall corners 4; eaves 2, verges 4 and the ridge on the roof.
  EXPECT_EQ(edges.size(), 15u);
  EXPECT_EQ(roof, 7);
}

TEST(ImageOverlay, TheTrueModelLiesOnTheImageEdgesAndAShiftedOneDoesNot) {
  const CityModel model = GableModel();
  // Two faces of one tile colour, shaded apart, over a darker ground.
  const cv::Mat img =
      RenderRoofs(model, {{0.62f, 0.30f, 0.22f}, {0.45f, 0.22f, 0.16f}}, {0.25f, 0.28f, 0.22f});
  ImageOverlay o;
  const EdgeSupport truth = Support(model, img, &o);
  // Eaves 2 x 12 m at 500/94 px/m, the ridge 12 m at 500/91 px/m and
  // four verges of 4 m in plan between them: 280 px.
  EXPECT_NEAR(truth.visible_px, 280, 3);
  EXPECT_EQ(truth.hidden_px, 0);
  EXPECT_GE(truth.Fraction(), 0.95);
  ASSERT_EQ(o.per_building.size(), 1u);
  EXPECT_DOUBLE_EQ(o.per_building[0].visible_px, truth.visible_px);

  // 1 m (5 px) off in x and y: no edge lies on its image edge any more.
  const CityModel shifted =
      eval_test::Transformed(model, [](const V& v) { return V(v + V(1, 1, 0)); });
  EXPECT_LT(Support(shifted, img).Fraction(), 0.15);
  // 1 m off in x only: the eaves and the ridge still lie on theirs.
  const double along_x =
      Support(eval_test::Transformed(model, [](const V& v) { return V(v + V(1, 0, 0)); }), img)
          .Fraction();
  EXPECT_GT(along_x, 0.4);
  EXPECT_LT(along_x, 0.8);
}

TEST(ImageOverlay, AnEdgeSeenOnlyAsAChangeOfHueIsSupported) {
  // Rec. 601 luma of all three colours within 0.01 of 0.45: a grey image
  // would show no edge at all.
  const cv::Vec3f red(0.80f, 0.30f, 0.32f), orange(0.62f, 0.40f, 0.25f), green(0.30f, 0.55f, 0.36f);
  const auto luma = [](const cv::Vec3f& c) { return 0.299 * c[0] + 0.587 * c[1] + 0.114 * c[2]; };
  ASSERT_NEAR(luma(red), luma(green), 0.01);
  ASSERT_NEAR(luma(orange), luma(green), 0.01);
  const CityModel model = GableModel();
  EXPECT_GE(Support(model, RenderRoofs(model, {red, orange}, green)).Fraction(), 0.9);
}

TEST(ImageOverlay, DrawsSupportedEdgesGreenAndNothingWithoutDraw) {
  const CityModel model = GableModel();
  const cv::Mat img =
      RenderRoofs(model, {{0.6f, 0.3f, 0.2f}, {0.45f, 0.2f, 0.15f}}, {0.2f, 0.25f, 0.2f});
  ImageOverlay o;
  Support(model, img, &o);
  ASSERT_EQ(o.drawing.type(), CV_8UC3);
  ASSERT_EQ(o.drawing.size(), img.size());
  // The middle of the south eave (y = 0, x = 6, z = 6).
  const Eigen::Vector2d p = *Project(TestCamera(), TestPose(), V(6, 0, 6));
  const cv::Vec3b c = o.drawing.at<cv::Vec3b>(static_cast<int>(p.y()), static_cast<int>(p.x()));
  EXPECT_GT(c[1], 150);  // green
  EXPECT_LT(c[0], 100);

  const ModelOccluder occluder(model);
  const ImageOverlay none =
      OverlayModel(img, TestCamera(), TestPose(), ModelEdges(model), 1, occluder, {}, false);
  EXPECT_TRUE(none.drawing.empty());
  EXPECT_DOUBLE_EQ(none.roof.supported_px, o.roof.supported_px);
}

TEST(ImageOverlay, TheModelHidesWhatLiesBehindItsOwnFaces) {
  CityModel m;
  m.buildings.push_back(eval_test::Box("b", 0, 0, 10, 8, 0, 6));
  const ModelOccluder occluder(m);
  const V above(5, 4, 100);
  EXPECT_TRUE(occluder.Visible(above, V(5, 4, 6)));   // on the roof
  EXPECT_TRUE(occluder.Visible(above, V(0, 0, 6)));   // a roof corner
  EXPECT_FALSE(occluder.Visible(above, V(5, 4, 0)));  // the ground under it
  EXPECT_TRUE(occluder.Visible(above, V(20, 4, 0)));  // the ground beside it
  // Seen low from the east, the west wall's foot lies behind the building.
  EXPECT_FALSE(occluder.Visible(V(60, 4, 10), V(0, 4, 0.5)));
  EXPECT_TRUE(occluder.Visible(V(60, 4, 10), V(10, 4, 0.5)));
}

}  // namespace
}  // namespace roofsweep
