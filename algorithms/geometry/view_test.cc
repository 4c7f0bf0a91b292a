#include "algorithms/geometry/view.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "algorithms/geometry/block.h"
#include "algorithms/geometry/rotation.h"

namespace roofsweep {
namespace {

Camera SimpleCamera() {
  Camera c;
  c.width = 2000;
  c.height = 1500;
  c.fx = c.fy = 2500;
  c.cx = 1000;
  c.cy = 750;
  return c;
}

TEST(View, ProjectAndBackProjectAgree) {
  Camera cam = SimpleCamera();
  cam.k1 = -0.05;
  cam.p2 = 1e-4;
  Pose pose;
  pose.R = PatbToCv(OpkToRotation(2, -3, 40));
  pose.C = {10, 20, 500};
  const Eigen::Vector2d px(321.5, 1111.25);
  const Ray ray = BackProject(cam, pose, px);
  const auto ground = IntersectHorizontalPlane(ray, 30.0);
  ASSERT_TRUE(ground);
  EXPECT_NEAR(ground->z(), 30.0, 1e-9);
  const auto back = Project(cam, pose, *ground);
  ASSERT_TRUE(back);
  EXPECT_LT((*back - px).norm(), 1e-6);
}

TEST(View, RayMeetsASlopedPlaneInFrontAndNotAtGrazingIncidence) {
  Ray ray{{0, 0, 100}, {0, 0, -1}};
  // z = 10 + x tan 30: the normal is 30 degrees off vertical.
  const double s = std::sin(M_PI / 6), c = std::cos(M_PI / 6);
  const Eigen::Vector4d plane(-s, 0, c, -10 * c);
  const auto hit = IntersectPlane(ray, plane);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(plane.head<3>().dot(*hit) + plane[3], 0, 1e-9);
  EXPECT_NEAR(hit->z(), 10, 1e-9);
  EXPECT_TRUE(IntersectPlane(ray, plane, 0.8));   // cos 30 = 0.87
  EXPECT_FALSE(IntersectPlane(ray, plane, 0.9));  // too grazing
  ray.direction = -ray.direction;                 // the plane lies behind
  EXPECT_FALSE(IntersectPlane(ray, plane));
}

TEST(View, PointBehindCameraDoesNotProject) {
  Pose pose;
  pose.R = PatbToCv(OpkToRotation(0, 0, 0));
  pose.C = {0, 0, 100};
  EXPECT_FALSE(Project(SimpleCamera(), pose, {0, 0, 200}));
  EXPECT_TRUE(Project(SimpleCamera(), pose, {0, 0, 0}));
}

TEST(View, ProjectionMatrixMatchesProjectWithoutDistortion) {
  const Camera cam = SimpleCamera();
  Pose pose;
  pose.R = PatbToCv(OpkToRotation(5, 1, -60));
  pose.C = {-3, 4, 300};
  const Matrix34d P = ProjectionMatrix(cam, pose);
  const Eigen::Vector3d X(12, -7, 2);
  const Eigen::Vector3d h = P * X.homogeneous();
  EXPECT_LT((h.hnormalized() - *Project(cam, pose, X)).norm(), 1e-9);
}

TEST(View, DecomposeProjectionRecoversKRC) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 50; ++i) {
    Camera cam = SimpleCamera();
    cam.skew = 3.0 * u(rng);
    cam.fy = 2400 + 100 * u(rng);
    Pose pose;
    pose.R = AxisAngleToRotation(Eigen::Vector3d(u(rng), u(rng), u(rng)) * 2);
    pose.C = Eigen::Vector3d(u(rng), u(rng), u(rng)) * 100;
    const double scale = (i % 2 ? -1 : 1) * (1 + std::abs(u(rng)));
    Eigen::Matrix3d K, R;
    Eigen::Vector3d C;
    DecomposeProjection(scale * ProjectionMatrix(cam, pose), &K, &R, &C);
    EXPECT_LT((K - cam.K()).cwiseAbs().maxCoeff(), 1e-6);
    EXPECT_LT((R - pose.R).cwiseAbs().maxCoeff(), 1e-9);
    EXPECT_LT((C - pose.C).norm(), 1e-7);
  }
}

TEST(GroundModel, GridBilinearAndFallback) {
  GroundModel g;
  EXPECT_FALSE(g.Known());
  EXPECT_TRUE(std::isnan(g.HeightAt(0, 0)));
  g.height = 5;
  EXPECT_DOUBLE_EQ(g.HeightAt(0, 0), 5);
  GroundModel::Grid grid;
  grid.x0 = 0;
  grid.y0 = 2;
  grid.dx = grid.dy = 1;
  grid.rows = 2;
  grid.cols = 2;
  grid.z = {10, 20, 30, 40};  // row 0 is north (y in [1, 2])
  g.grid = grid;
  EXPECT_DOUBLE_EQ(g.HeightAt(0.5, 1.5), 10);
  EXPECT_DOUBLE_EQ(g.HeightAt(1.5, 0.5), 40);
  EXPECT_DOUBLE_EQ(g.HeightAt(1.0, 1.0), 25);
}

// The ground as a plane: the DTM's own plane on a hillside (a level plane
// at the centre's height would be 0.6 m off at 6 m), level and exactly
// (0, 0, 1, -h) on a constant height, NaN where nothing is known.
TEST(GroundModel, PlaneAtFollowsTheSlope) {
  GroundModel g;
  EXPECT_TRUE(std::isnan(g.PlaneAt(0, 0, 5)[3]));
  g.height = 7;
  EXPECT_EQ(g.PlaneAt(3, 4, 5), Eigen::Vector4d(0, 0, 1, -7));
  GroundModel::Grid grid;
  grid.x0 = -20;
  grid.y0 = 20;
  grid.dx = grid.dy = 1;
  grid.rows = grid.cols = 40;
  for (int r = 0; r < grid.rows; ++r)
    for (int c = 0; c < grid.cols; ++c) {
      const double x = grid.x0 + c + 0.5, y = grid.y0 - r - 0.5;
      grid.z.push_back(static_cast<float>(100 + 0.1 * x - 0.05 * y));
    }
  g.grid = grid;
  const Eigen::Vector4d p = g.PlaneAt(2, -3, 6);
  EXPECT_GT(p[2], 0);
  EXPECT_NEAR(p.head<3>().norm(), 1, 1e-12);
  for (const Eigen::Vector2d& q : {Eigen::Vector2d(2, -3), Eigen::Vector2d(8, -3),
                                   Eigen::Vector2d(-4, 3), Eigen::Vector2d(10, -9)}) {
    const double z = -(p[0] * q.x() + p[1] * q.y() + p[3]) / p[2];
    EXPECT_NEAR(z, g.HeightAt(q.x(), q.y()), 1e-4) << q.transpose();
  }
}

}  // namespace
}  // namespace roofsweep
