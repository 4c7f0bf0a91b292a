#pragma once

#include <Eigen/Core>
#include <vector>

#include "algorithms/edges/edge_options.h"

namespace roofsweep {

using Points2 = std::vector<Eigen::Vector2d>;

// A line fitted by orthogonal regression (total least squares).
struct LineFit {
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  Eigen::Vector2d direction = Eigen::Vector2d::UnitX();  // unit
  double rms = 0;                                        // RMS orthogonal distance
  double max_deviation = 0;                              // largest orthogonal distance
  double t_min = 0, t_max = 0;  // extent of the points along `direction` from `centroid`

  Eigen::Vector2d Normal() const { return {direction.y(), -direction.x()}; }
  Eigen::Vector2d Start() const { return centroid + t_min * direction; }
  Eigen::Vector2d End() const { return centroid + t_max * direction; }
  double Length() const { return t_max - t_min; }
};

// Orthogonal regression through at least two points: the direction is the
// principal eigenvector of the 2x2 scatter matrix, in closed form.
LineFit FitLine(const Eigen::Vector2d* points, int count);
inline LineFit FitLine(const Points2& points) {
  return FitLine(points.data(), static_cast<int>(points.size()));
}

// True when the residuals of `points` about `fit` bend systematically: a
// parabola r(u) = a + b u + c u² over the normalised position u in [-1, 1]
// has sagitta |c| above `max_sagitta` and at least 3 standard errors, and
// explains at least `min_explained` of the residuals' sum of squares.
bool IsCurved(const Eigen::Vector2d* points, int count, const LineFit& fit, double max_sagitta,
              double min_explained);
inline bool IsCurved(const Points2& points, const LineFit& fit, double max_sagitta,
                     double min_explained) {
  return IsCurved(points.data(), static_cast<int>(points.size()), fit, max_sagitta, min_explained);
}

// Cuts a chain of ordered edge points into straight pieces, returned as
// index ranges [first, last) into `chain`:
//  1. at tangent discontinuities (the direction over `tangent_window`
//     points before and after a point turns by more than
//     `split_tangent_angle`; cut at the sharpest point of each such run);
//  2. recursively, at the point farthest from the chord, while the fitted
//     line leaves a point more than `fit_max_deviation` away or IsCurved.
// The cut point itself belongs to neither piece. Pieces with fewer than
// `min_support` points are dropped.
struct StraightRun {
  int first = 0, last = 0;  // [first, last) in the chain
  LineFit fit;
};
std::vector<StraightRun> SplitIntoStraightPieces(const Points2& chain, const EdgeOptions& options);

}  // namespace roofsweep
