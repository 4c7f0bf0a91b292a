#include "algorithms/geometry/camera.h"

#include <gtest/gtest.h>

#include "algorithms/core/error.h"

namespace roofsweep {
namespace {

Camera Pix4dCamera() {
  // Pix4D DSC_0157 calibration (ecosystem-notes §3).
  Camera c;
  c.id = "pix4d";
  c.width = 7360;
  c.height = 4912;
  c.fx = c.fy = 7363.5185002395;
  c.cx = 3686.3371999683;
  c.cy = 2439.0408341264;
  c.k1 = -0.0900592106766;
  c.k2 = 0.1077397243574;
  c.k3 = -0.0125705498780;
  c.p1 = -0.00029570539858;
  c.p2 = -0.00027422056492;
  return c;
}

TEST(Camera, DistortUndistortRoundTripOverTheImage) {
  const Camera c = Pix4dCamera();
  double worst = 0;
  for (int y = 0; y <= c.height; y += 491) {
    for (int x = 0; x <= c.width; x += 736) {
      const Eigen::Vector2d px(x, y);
      const Eigen::Vector2d n = c.PixelToNormalized(px);
      worst = std::max(worst, (c.NormalizedToPixel(n) - px).norm());
    }
  }
  EXPECT_LT(worst, 1e-6);
}

TEST(Camera, DistortionFollowsOpenCvFormula) {
  Camera c = Pix4dCamera();
  const Eigen::Vector2d u(0.3, -0.2);
  const double r2 = 0.13;
  const double rad = 1 + c.k1 * r2 + c.k2 * r2 * r2 + c.k3 * r2 * r2 * r2;
  const Eigen::Vector2d d = c.Distort(u);
  EXPECT_NEAR(d.x(), 0.3 * rad + 2 * c.p1 * 0.3 * -0.2 + c.p2 * (r2 + 2 * 0.09), 1e-15);
  EXPECT_NEAR(d.y(), -0.2 * rad + c.p1 * (r2 + 2 * 0.04) + 2 * c.p2 * 0.3 * -0.2, 1e-15);
}

TEST(Camera, PrincipalPointMapsToOpticalAxis) {
  const Camera c = Pix4dCamera();
  EXPECT_LT(c.PixelToNormalized({c.cx, c.cy}).norm(), 1e-12);
}

TEST(Camera, ContainsTheFrameAndNotBeyondItsMargin) {
  Camera c;
  c.width = 100;
  c.height = 50;
  EXPECT_TRUE(c.Contains({0, 0}));  // the frame's corner belongs to the image
  EXPECT_TRUE(c.Contains({100, 50}));
  EXPECT_FALSE(c.Contains({100.5, 10}));
  EXPECT_FALSE(c.Contains({10, -0.1}));
  EXPECT_TRUE(c.Contains({10, 10}, 10));
  EXPECT_FALSE(c.Contains({9.9, 10}, 10));
  EXPECT_FALSE(c.Contains({50, 40.5}, 10));
}

TEST(Camera, ValidateRefusesZeroFocalAndNaN) {
  Camera c = Pix4dCamera();
  EXPECT_NO_THROW(c.Validate("x"));
  c.fx = 0;
  EXPECT_THROW(c.Validate("cams.txt:3"), Error);
  c = Pix4dCamera();
  c.k1 = std::nan("");
  EXPECT_THROW(c.Validate("x"), Error);
  c = Pix4dCamera();
  c.width = 0;
  EXPECT_THROW(c.Validate("x"), Error);
}

}  // namespace
}  // namespace roofsweep
