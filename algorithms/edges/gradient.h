#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "algorithms/edges/segment2d.h"

namespace roofsweep {

// The fused gradient of an image: the smoothed planes, the gradient
// magnitude and its nearer axis. The gradient vectors are not stored but
// recomputed where needed (GradientRow, GradientAt): that costs less than
// writing and reading two more float images.
struct GradientField {
  cv::Mat magnitude;  // CV_32F fused gradient norm, intensity per pixel; 0 on the outermost rows
                      // and columns
  // CV_8U, 1 where the gradient is nearer the x axis (|gx| >= |gy|), else 0
  // (and on the outermost rows and columns): the axis along which
  // DetectEdgePoints compares magnitudes.
  cv::Mat horizontal;
  std::vector<cv::Mat> smoothed;                 // the smoothed CV_32F planes (1 or 3)
  GradientMethod method = GradientMethod::kMax;  // kGrey for one plane
};

// The fused gradient vectors of row y (0 < y < rows - 1) into gx[1 .. cols - 2]
// and gy[...], and the magnitude into m when not null. A vector has length
// `magnitude` in the fused direction; its sign is the one of the strongest
// band (the Di Zenzo eigenvector has none), so it points from the darker to
// the brighter side of that band.
void GradientRow(const GradientField& gradient, int y, float* m, float* gx, float* gy);

// The fused gradient at pixel (x, y), 0 < x < cols - 1, 0 < y < rows - 1,
// equal to GradientRow's there, with the band that carries it (see
// CarryingBand): for edge points, a small share of the pixels.
struct GradientVector {
  float gx = 0, gy = 0;
  EdgeBand band = EdgeBand::kFused;
};
GradientVector GradientAt(const GradientField& gradient, int x, int y);
// GradientAt at columns xs[0 .. n - 1] of row y, into out[0 .. n - 1].
void GradientAtColumns(const GradientField& gradient, int y, const int* xs, int n,
                       GradientVector* out);

// The band that carries the gradient at pixel (x, y), 0 < x < cols - 1,
// 0 < y < rows - 1: for kMax on colour the band with the largest gradient
// norm (ties to the lower band, as in the fusion), kFused for Di Zenzo,
// kGrey for one plane. Recomputed from the smoothed planes, because only
// edge points need it and a per-pixel band image would cost more than it
// saves.
EdgeBand CarryingBand(const GradientField& gradient, int x, int y);

// Splits a CV_32FC3 (R, G, B) or CV_32FC1 image into new planes,
// converting to grey first for kGrey (Rec. 601 luma, as cv::cvtColor). Grey
// input always gives a single plane (a copy).
std::vector<cv::Mat> GradientPlanes(const cv::Mat& image, GradientMethod method);

// Gaussian smoothing (separable, standard deviation `sigma`, none when
// sigma <= 0) of each plane, in place (the planes are consumed), central
// differences, and fusion by `method`:
//   kMax:     the band with the largest |grad| (Scholze §2.1);
//   kDiZenzo: sqrt of the largest eigenvalue of D = JᵀJ, in closed form
//             for the symmetric 2x2 D (§2.2; no SVD needed);
//   kGrey:    the single plane's gradient.
// One plane always behaves like kGrey. Rows are processed with
// cv::parallel_for_, so the caller's cv::setNumThreads applies.
GradientField ComputeGradient(std::vector<cv::Mat> planes, GradientMethod method, double sigma);

}  // namespace roofsweep
