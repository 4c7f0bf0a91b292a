#pragma once

#include <Eigen/Core>
#include <optional>

#include "algorithms/geometry/camera.h"
#include "algorithms/geometry/view.h"

namespace roofsweep {

// The homography induced by a world plane between a reference view and view
// i, on ideal (undistorted) pixel coordinates (Baillard & Zisserman 2000,
// §3.2, after Luong & Viéville 1996): H = A + a v^T. In the reference
// camera's own frame (P_ref = K_ref [I | 0]) view i is
// K_i [R_i R_ref^T | R_i (C_ref - C_i)], so with K_ref removed
// A = K_i R_i R_ref^T K_ref^-1 and a = K_i R_i (C_ref - C_i); with the plane
// (n_c, d_c) in reference camera coordinates, v = -K_ref^-T n_c / d_c.
// v is the same for every view i, and v . x = 1 / depth of the plane point
// seen at ideal reference pixel x (homogeneous, last coordinate 1).
struct PlaneHomography {
  Eigen::Matrix3d A = Eigen::Matrix3d::Identity();
  Eigen::Vector3d a = Eigen::Vector3d::Zero();
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  Eigen::Matrix3d H() const { return A + a * v.transpose(); }
};

// The part of H that does not depend on the plane (A, a).
PlaneHomography ViewPairHomography(const Camera& ref_camera, const Pose& ref_pose,
                                   const Camera& camera, const Pose& pose);

// v for the world plane (n, pi_4), n . X + pi_4 = 0, seen from the
// reference view. Empty when the plane passes through the reference centre.
std::optional<Eigen::Vector3d> PlaneVector(const Camera& ref_camera, const Pose& ref_pose,
                                           const Eigen::Vector4d& plane);

// Full homography from the reference view to view i for a world plane.
std::optional<PlaneHomography> HomographyThroughPlane(const Camera& ref_camera,
                                                      const Pose& ref_pose, const Camera& camera,
                                                      const Pose& pose,
                                                      const Eigen::Vector4d& plane);

// Ideal (undistorted) pixel of a measured pixel, and back: distortion is not
// linear, so the homography acts on ideal pixels K * undistort(K^-1 p).
Eigen::Vector2d IdealPixel(const Camera& camera, const Eigen::Vector2d& pixel);
Eigen::Vector2d MeasuredPixel(const Camera& camera, const Eigen::Vector2d& ideal);

}  // namespace roofsweep
