#include "algorithms/sweep/plane_homography.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>

#include "algorithms/sweep/half_plane_family.h"

namespace roofsweep {
namespace {

Camera TestCamera(double f, double cx, double cy) {
  Camera c;
  c.width = 1000;
  c.height = 800;
  c.fx = f;
  c.fy = f * 1.01;
  c.cx = cx;
  c.cy = cy;
  return c;
}

Pose TiltedPose(const Eigen::Vector3d& C, double ax, double ay) {
  Pose p;
  const Eigen::Matrix3d nadir = Eigen::Vector3d(1, -1, -1).asDiagonal();
  p.R = (Eigen::AngleAxisd(ax, Eigen::Vector3d::UnitX()) *
         Eigen::AngleAxisd(ay, Eigen::Vector3d::UnitY()))
            .toRotationMatrix() *
        nadir;
  p.C = C;
  return p;
}

// H x_ref must equal the direct projection of the plane point for every
// plane of a line's family and every view pair.
TEST(PlaneHomography, MatchesDirectProjectionThroughPlane) {
  const Camera ref_cam = TestCamera(1200, 480, 410), cam = TestCamera(900, 520, 390);
  const Pose ref_pose = TiltedPose({-10, 3, 120}, 0.05, -0.08);
  const Pose pose = TiltedPose({25, -6, 115}, -0.1, 0.2);
  const Segment3 line{{-4, 1, 12}, {5, 3, 13}};
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> U(-1, 1);
  for (int side : {1, -1}) {
    const auto f = HalfPlaneFamily::Make(line, side);
    ASSERT_TRUE(f);
    for (double deg = -75; deg <= 75; deg += 15) {
      const double theta = deg * M_PI / 180;
      const auto h = HomographyThroughPlane(ref_cam, ref_pose, cam, pose, f->Plane(theta));
      ASSERT_TRUE(h);
      const Eigen::Matrix3d H = h->H();
      for (int i = 0; i < 20; ++i) {
        const Eigen::Vector3d X =
            line.At(0.5 + 0.5 * U(rng)) + (2 + 2 * U(rng)) * f->Direction(theta);
        const auto xr = Project(ref_cam, ref_pose, X), xi = Project(cam, pose, X);
        ASSERT_TRUE(xr && xi);
        const Eigen::Vector3d y = H * Eigen::Vector3d(xr->x(), xr->y(), 1);
        EXPECT_NEAR((y.head<2>() / y.z() - *xi).norm(), 0, 1e-6);
        // v . x is the inverse depth in the reference view.
        EXPECT_NEAR(h->v.dot(Eigen::Vector3d(xr->x(), xr->y(), 1)), 1.0 / ref_pose.ToCamera(X).z(),
                    1e-12);
        EXPECT_GT(y.z(), 0);
      }
    }
  }
}

// With lens distortion the homography acts on ideal pixels.
TEST(PlaneHomography, IdealPixelsAccountForDistortion) {
  Camera ref_cam = TestCamera(1000, 500, 400), cam = TestCamera(1000, 500, 400);
  ref_cam.k1 = -0.08;
  ref_cam.k2 = 0.01;
  ref_cam.p1 = 0.001;
  cam.k1 = 0.05;
  cam.p2 = -0.0008;
  const Pose ref_pose = TiltedPose({0, 0, 100}, 0.02, 0.0);
  const Pose pose = TiltedPose({20, 5, 100}, 0.0, -0.03);
  const Eigen::Vector4d plane(0.2, -0.1, 0.97, -10);
  const auto h = HomographyThroughPlane(ref_cam, ref_pose, cam, pose, plane);
  ASSERT_TRUE(h);
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> U(-30, 30);
  for (int i = 0; i < 50; ++i) {
    // A point on the plane.
    Eigen::Vector3d X(U(rng), U(rng), 0);
    X.z() = -(plane.x() * X.x() + plane.y() * X.y() + plane(3)) / plane.z();
    const auto xr = Project(ref_cam, ref_pose, X), xi = Project(cam, pose, X);
    ASSERT_TRUE(xr && xi);
    const Eigen::Vector2d ideal = IdealPixel(ref_cam, *xr);
    const Eigen::Vector3d y = h->H() * Eigen::Vector3d(ideal.x(), ideal.y(), 1);
    EXPECT_NEAR((MeasuredPixel(cam, y.head<2>() / y.z()) - *xi).norm(), 0, 1e-6);
  }
}

TEST(PlaneHomography, PlaneThroughReferenceCentreIsRejected) {
  const Camera cam = TestCamera(1000, 500, 400);
  const Pose pose = TiltedPose({0, 0, 100}, 0, 0);
  EXPECT_FALSE(PlaneVector(cam, pose, Eigen::Vector4d(1, 0, 0, 0)));
}

}  // namespace
}  // namespace roofsweep
