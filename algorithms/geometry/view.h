#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "algorithms/geometry/camera.h"

namespace roofsweep {

using Matrix34d = Eigen::Matrix<double, 3, 4>;

// Exterior orientation in the block's local frame, computer-vision axes:
// x_cam = R (X - C), camera x right, y down, z forward.
struct Pose {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();  // world -> camera
  Eigen::Vector3d C = Eigen::Vector3d::Zero();      // projection centre, world

  Eigen::Vector3d ToCamera(const Eigen::Vector3d& world) const { return R * (world - C); }
  // Unit vector of the optical axis in world coordinates.
  Eigen::Vector3d ViewingDirection() const { return R.row(2).transpose(); }
  Eigen::Vector3d Translation() const { return -R * C; }
};

// One oriented image of a block.
struct View {
  std::string name;        // unique in the block (image file stem)
  std::string image_path;  // as resolved by io (absolute, or relative to cwd)
  int camera = -1;         // index into Block::cameras
  Pose pose;
};

struct Ray {
  Eigen::Vector3d origin;
  Eigen::Vector3d direction;  // unit length
};

// P = K [R | -R C]; the pinhole part only (distortion is not linear).
Matrix34d ProjectionMatrix(const Camera& camera, const Pose& pose);

// World point to pixel, distortion applied. Empty when the point is not in
// front of the camera.
std::optional<Eigen::Vector2d> Project(const Camera& camera, const Pose& pose,
                                       const Eigen::Vector3d& world);

// Pixel to the world ray through it (distortion removed).
Ray BackProject(const Camera& camera, const Pose& pose, const Eigen::Vector2d& pixel);

// Intersection of a ray with the plane z = height, if it meets it in front.
std::optional<Eigen::Vector3d> IntersectHorizontalPlane(const Ray& ray, double height);

// Intersection of a ray with the plane n . X + d = 0 (n unit), if it meets
// it in front and at |cos| >= min_incidence between the ray and n: rays
// grazing a plane place the point badly.
std::optional<Eigen::Vector3d> IntersectPlane(const Ray& ray, const Eigen::Vector4d& plane,
                                              double min_incidence = 1e-12);

// Splits P into K (positive diagonal, K(2,2) = 1), a rotation R (det +1) and
// the centre C, by RQ decomposition. The overall sign of P is chosen so that
// points with positive depth are in front.
void DecomposeProjection(const Matrix34d& P, Eigen::Matrix3d* K, Eigen::Matrix3d* R,
                         Eigen::Vector3d* C);

}  // namespace roofsweep
