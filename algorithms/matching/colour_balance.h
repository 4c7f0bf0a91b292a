#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <vector>

#include "algorithms/geometry/block.h"

namespace roofsweep {

// Per-view radiometric correction in linear RGB: corrected = gain * value +
// offset per channel (identity by default).
struct ColourCorrection {
  Eigen::Vector3d gain = Eigen::Vector3d::Ones();
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
  bool Identity() const { return (gain.array() == 1.0).all() && (offset.array() == 0.0).all(); }
};

// Relative colour balance of a block (an addition to Scholze et al. 2000,
// who rely on CIE L*a*b* alone): images of different flight lines differ by
// a per-channel gain (calibration, exposure) under a common atmospheric
// offset, which shifts a*, b* by a colour-dependent amount of about one unit,
// far beyond what the chromatic tests forgive. For every pair of views the
// same ground footprint (mapped through the ground plane) is sampled in both
// images; the quantiles of each channel (linearised sRGB) of the two samples
// are matched by an affine map (relative radiometric normalisation as in
// mosaicking), and one gain and offset per view and channel are solved for
// by least squares over all pairs (mean gain 1, mean offset 0; a weak prior
// towards the identity keeps unconnected views fixed). Estimated from the
// images only. Empty images, grey images, an unknown ground or fewer than two
// views give identity corrections.
std::vector<ColourCorrection> EstimateColourBalance(const Block& block,
                                                    const std::vector<cv::Mat>& images);

// A correction as per-channel lookup tables over the encoded range, to
// apply it row by row where the image is converted anyway (PrepareView)
// rather than into a copy of the whole image.
class ColourCorrectionTable {
 public:
  explicit ColourCorrectionTable(const ColourCorrection& correction);
  bool Identity() const { return identity_; }
  // Corrects n pixels (R, G, B in [0, 1]; inputs are clamped to it first).
  void Apply(const cv::Vec3f* in, cv::Vec3f* out, int n) const;

 private:
  bool identity_ = true;
  std::vector<float> lut_[3];
};

// Applies a correction to an sRGB-encoded CV_32FC3 image in [0, 1] (returns
// a new image; grey images and identity corrections come back unchanged).
cv::Mat ApplyColourCorrection(const cv::Mat& image, const ColourCorrection& correction);

// The sRGB transfer function and its inverse (IEC 61966-2-1), [0, 1].
double SrgbToLinear(double encoded);
double LinearToSrgb(double linear);

}  // namespace roofsweep
