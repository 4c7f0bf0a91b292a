#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "algorithms/edges/segment2d.h"

namespace roofsweep {

// The fused gradient of an image, one value per pixel (all CV_32F except
// `band`). The outermost row and column are 0: central differences need
// both neighbours.
struct GradientField {
  cv::Mat magnitude;  // fused gradient norm, intensity per pixel
  // A gradient vector of length `magnitude` in the fused direction. Its
  // sign is the one of the strongest band (the Di Zenzo eigenvector has
  // none), so it points from the darker to the brighter side of that band.
  cv::Mat gx, gy;
  cv::Mat band;  // CV_8U EdgeBand of the carrying band (kMax); empty otherwise
};

// Splits a CV_32FC3 (R, G, B) or CV_32FC1 image into planes, converting to
// grey first for kGrey (Rec. 601 luma, as cv::cvtColor). Grey input always
// gives a single plane.
std::vector<cv::Mat> GradientPlanes(const cv::Mat& image, GradientMethod method);

// Gaussian smoothing (separable, standard deviation `sigma`, none when
// sigma <= 0) of each plane, central differences, and fusion by `method`:
//   kMax:     the band with the largest |grad| (Scholze §2.1);
//   kDiZenzo: sqrt of the largest eigenvalue of D = JᵀJ, in closed form
//             for the symmetric 2x2 D (§2.2; no SVD needed);
//   kGrey:    the single plane's gradient.
// One plane always behaves like kGrey. Rows are processed with
// cv::parallel_for_, so the caller's cv::setNumThreads applies.
GradientField ComputeGradient(const std::vector<cv::Mat>& planes, GradientMethod method,
                              double sigma);

}  // namespace roofsweep
