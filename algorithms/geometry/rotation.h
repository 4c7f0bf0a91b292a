#pragma once

#include <Eigen/Core>

namespace roofsweep {

// Photogrammetric (PATB) convention, as in Pix4D, Metashape and orthority:
// camera axes x right, y up, z backwards (the camera looks along -z);
// R = Rx(omega) Ry(phi) Rz(kappa) maps camera to world; angles in degrees.
Eigen::Matrix3d OpkToRotation(double omega_deg, double phi_deg, double kappa_deg);
// Inverse of OpkToRotation: (omega, phi, kappa) in degrees.
Eigen::Vector3d RotationToOpk(const Eigen::Matrix3d& camera_to_world_patb);

// PATB camera-to-world to computer-vision world-to-camera (x right, y down,
// z forward; OpenCV, COLMAP, OpenSfM): R_cv = diag(1, -1, -1) R_patbᵀ.
Eigen::Matrix3d PatbToCv(const Eigen::Matrix3d& camera_to_world_patb);
Eigen::Matrix3d CvToPatb(const Eigen::Matrix3d& world_to_camera_cv);

// Hamilton quaternion, w first (COLMAP).
Eigen::Matrix3d QuaternionToRotation(double w, double x, double y, double z);
Eigen::Vector4d RotationToQuaternion(const Eigen::Matrix3d& r);  // (w, x, y, z), w >= 0

// Rodrigues axis-angle vector (OpenSfM).
Eigen::Matrix3d AxisAngleToRotation(const Eigen::Vector3d& axis_angle);
Eigen::Vector3d RotationToAxisAngle(const Eigen::Matrix3d& r);

// Nearest rotation matrix (polar decomposition by SVD), det = +1.
Eigen::Matrix3d NearestRotation(const Eigen::Matrix3d& m);

// Angle between two rotations in degrees.
double RotationAngleDeg(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b);

}  // namespace roofsweep
