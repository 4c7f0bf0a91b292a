#pragma once

#include <Eigen/Core>
#include <string>

namespace roofsweep {

// Interior orientation of a frame camera.
//
// Pixel convention, used everywhere in roofsweep: x right, y down, origin at
// the top-left CORNER of the top-left pixel, so that pixel (0, 0) covers
// [0, 1) x [0, 1) and its centre is (0.5, 0.5). COLMAP and Pix4D use this
// convention; OpenSfM and the Oxford VGG sets put the origin at the centre of
// the top-left pixel and are shifted by +0.5 px on import.
//
// Distortion is Brown–Conrady on normalised coordinates in computer-vision
// camera axes (x right, y down, z forward), with OpenCV's coefficient names
// and order (k1, k2, p1, p2, k3): x_d = x (1 + k1 r² + k2 r⁴ + k3 r⁶)
// + 2 p1 x y + p2 (r² + 2 x²), y_d = y (…) + p1 (r² + 2 y²) + 2 p2 x y.
struct Camera {
  std::string id;
  int width = 0;   // pixels
  int height = 0;  // pixels
  double fx = 0;   // focal length, pixels
  double fy = 0;
  double cx = 0;  // principal point, pixels (corner origin)
  double cy = 0;
  double skew = 0;  // K(0, 1); non-zero only for decomposed P matrices
  double k1 = 0, k2 = 0, k3 = 0, p1 = 0, p2 = 0;
  double pixel_size_mm = 0;  // optional, 0 when unknown

  Eigen::Matrix3d K() const;
  bool HasDistortion() const;

  // Normalised (z = 1) coordinates to distorted normalised coordinates.
  Eigen::Vector2d Distort(const Eigen::Vector2d& undistorted) const;
  // Inverse of Distort by fixed-point iteration with a Newton polish; exact
  // to ~1e-12 for the distortions real lenses have.
  Eigen::Vector2d Undistort(const Eigen::Vector2d& distorted) const;

  // Ideal normalised coordinates to pixel coordinates (applies distortion).
  Eigen::Vector2d NormalizedToPixel(const Eigen::Vector2d& normalized) const;
  // Pixel coordinates to ideal normalised coordinates (removes distortion).
  Eigen::Vector2d PixelToNormalized(const Eigen::Vector2d& pixel) const;

  // Whether pixel p lies in the image, at least `margin` pixels inside its
  // frame (corner-origin convention: the frame is [0, width] x [0, height]).
  bool Contains(const Eigen::Vector2d& p, double margin = 0) const {
    return p.x() >= margin && p.y() >= margin && p.x() <= width - margin &&
           p.y() <= height - margin;
  }

  // Throws roofsweep::Error naming `where` when the camera cannot be used:
  // non-positive size or focal length, NaN or infinite parameters.
  void Validate(const std::string& where) const;
};

}  // namespace roofsweep
