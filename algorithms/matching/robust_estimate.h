#pragma once

#include <Eigen/Core>
#include <vector>

namespace roofsweep {

// Robust location and scatter by the Minimum Covariance Determinant
// (Rousseeuw & Van Driessen 1999, FAST-MCD). Scholze et al. (2000) use the
// Minimum Volume Ellipsoid; MCD has the same 50 % breakdown point, is
// statistically more efficient and its C-steps are cheap and deterministic,
// so it is used for both the L* outliers and the a*-b* distribution. Written
// here because neither Eigen nor OpenCV has an MCD estimator.

struct Robust1D {
  double location = 0;
  double scale = 0;  // consistent standard deviation for normal data
  int used = 0;      // observations
};

// Exact univariate MCD: the half-sample (h = n/2 + 1) of least variance,
// consistency-corrected and reweighted at 2.5 sigma.
Robust1D RobustMcd1D(std::vector<double> values);

struct Robust2D {
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  Eigen::Matrix2d cov = Eigen::Matrix2d::Identity();
  int inliers = 0;  // points with weight 1 in the reweighting step
  bool valid = false;
};

// FAST-MCD for 2D points: `starts` random 3-point subsets (deterministic for
// `seed`) refined by C-steps, the best h-subset reweighted with the 0.975
// chi2(2) cut. Needs at least 5 points; fewer give valid = false.
Robust2D RobustMcd2D(const std::vector<Eigen::Vector2d>& points, unsigned seed = 1,
                     int starts = 20);

// The k-th smallest (0-based) of `values`, the value std::nth_element
// would place at k, by quickselect with a branch-free three-way partition
// into `buffer`. Both are overwritten; the buffer needs as many elements.
double SelectKth(std::vector<double>* values, std::vector<double>* buffer, int k);

}  // namespace roofsweep
