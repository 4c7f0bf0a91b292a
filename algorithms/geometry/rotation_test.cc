#include "algorithms/geometry/rotation.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

namespace roofsweep {
namespace {

// Pix4D DSC_0157.JPG: the external OPK export and the world->camera matrix
// of the calibrated_camera_parameters file of the same project
// (../shared/docs/ecosystem-notes.md §3).
TEST(Opk, Pix4dTestVectorMatchesCcpMatrix) {
  Eigen::Matrix3d ccp;
  ccp << -0.49632901575943, 0.86794436424469, -0.01816834310427,  //
      0.86649900151927, 0.49400145706385, -0.07170802455020,      //
      -0.05326338781352, -0.05133362440616, -0.99726018196053;
  const Eigen::Matrix3d r_cv = PatbToCv(OpkToRotation(-2.946680, 3.053212, 119.804001));
  EXPECT_LT((r_cv - ccp).cwiseAbs().maxCoeff(), 1e-8) << r_cv;

  const Eigen::Vector3d opk = RotationToOpk(CvToPatb(ccp));
  EXPECT_NEAR(opk(0), -2.946680, 1e-6);
  EXPECT_NEAR(opk(1), 3.053212, 1e-6);
  EXPECT_NEAR(opk(2), 119.804001, 1e-6);
}

TEST(Opk, RoundTripOverRandomAngles) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> a(-179, 179), p(-89, 89);
  for (int i = 0; i < 1000; ++i) {
    const Eigen::Vector3d opk(a(rng), p(rng), a(rng));
    const Eigen::Matrix3d r = OpkToRotation(opk(0), opk(1), opk(2));
    EXPECT_NEAR(r.determinant(), 1.0, 1e-12);
    EXPECT_LT((RotationToOpk(r) - opk).cwiseAbs().maxCoeff(), 1e-9);
  }
}

TEST(Opk, NadirCameraLooksDown) {
  // omega = phi = kappa = 0: camera z (backwards) is world up, so the CV
  // optical axis (third row of R_cv) points down.
  const Eigen::Matrix3d r_cv = PatbToCv(OpkToRotation(0, 0, 0));
  EXPECT_NEAR(r_cv(2, 2), -1.0, 1e-15);
  EXPECT_NEAR(r_cv(0, 0), 1.0, 1e-15);   // image x is east
  EXPECT_NEAR(r_cv(1, 1), -1.0, 1e-15);  // image y (down) is south
}

TEST(Quaternion, RoundTripAndColmapToOpk) {
  std::mt19937 rng(3);
  std::normal_distribution<double> n;
  for (int i = 0; i < 200; ++i) {
    Eigen::Vector4d q(n(rng), n(rng), n(rng), n(rng));
    q.normalize();
    if (q(0) < 0) q = -q;
    const Eigen::Matrix3d r = QuaternionToRotation(q(0), q(1), q(2), q(3));
    EXPECT_LT((RotationToQuaternion(r) - q).cwiseAbs().maxCoeff(), 1e-12);
    // COLMAP (CV world->camera) -> OPK -> back.
    const Eigen::Vector3d opk = RotationToOpk(CvToPatb(r));
    const Eigen::Matrix3d back = PatbToCv(OpkToRotation(opk(0), opk(1), opk(2)));
    EXPECT_LT((back - r).cwiseAbs().maxCoeff(), 1e-9);
  }
}

TEST(AxisAngle, RoundTrip) {
  const Eigen::Vector3d v(1.13234, -0.34102, 0.54359);
  EXPECT_LT((RotationToAxisAngle(AxisAngleToRotation(v)) - v).norm(), 1e-12);
  EXPECT_TRUE(AxisAngleToRotation(Eigen::Vector3d::Zero()).isIdentity());
}

TEST(NearestRotation, RepairsNoise) {
  Eigen::Matrix3d r = OpkToRotation(10, 20, 30);
  Eigen::Matrix3d noisy = r;
  noisy(0, 1) += 1e-4;
  const Eigen::Matrix3d fixed = NearestRotation(noisy);
  EXPECT_NEAR(fixed.determinant(), 1.0, 1e-12);
  EXPECT_LT(RotationAngleDeg(fixed, r), 0.01);
}

}  // namespace
}  // namespace roofsweep
