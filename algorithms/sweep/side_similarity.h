#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <vector>

#include "algorithms/geometry/block.h"
#include "algorithms/sweep/half_plane_family.h"
#include "algorithms/sweep/plane_homography.h"
#include "algorithms/sweep/points_of_interest.h"
#include "algorithms/sweep/sweep_options.h"

namespace roofsweep {

// Sim(theta) of Baillard & Zisserman 2000, eq. (2), for one line side:
//   Sim(theta) = sum_i sum_x w(x) Cor+(x, H^i(theta) x)^2 / (n sum_x w(x)),
// over the n views i other than the reference and the active points of
// interest x of the reference, w(x) = 1 / max(1 px, distance to the line),
// Cor+ = max(0, NCC) on the grey images over a (2 r + 1)^2 window mapped
// through H^i exactly at its centre and edge midpoints, affinely in between.
// Anti-correlation is clamped to 0 (the paper squares Cor, which would
// reward a contrast-inverted match). Points that map outside view i or
// behind a camera score 0 there but keep their weight, so Sim stays in
// [0, 1] and continuous in theta.
class SideSimilarity {
 public:
  SideSimilarity(const Block& block, const std::vector<ViewTexture>& textures,
                 const HalfPlaneFamily& family, int reference_view,
                 const std::vector<int>& other_views, const std::vector<BandPoint>& points,
                 const SweepOptions& options);

  // Sim at theta (radians) over the active points and views. When
  // `per_point` is given it receives each point's mean Cor+^2 over the
  // active views; `per_view` receives each view's weighted mean Cor+^2 over
  // the active points (every view, active or not).
  double Evaluate(double theta, std::vector<double>* per_point = nullptr,
                  std::vector<double>* per_view = nullptr) const;
  // Cor+^2 of every usable point (row) in every view (column) at theta,
  // whatever is active; 0 where the window falls outside a view or does not
  // correlate. Reduce turns it into Evaluate's results under the active
  // points and views of the moment, exactly: several choices of them at one
  // angle then cost one pass over the images.
  std::vector<double> Correlations(double theta) const;
  double Reduce(const std::vector<double>& correlations, std::vector<double>* per_point = nullptr,
                std::vector<double>* per_view = nullptr) const;

  int PointCount() const { return static_cast<int>(points_.size()); }
  int ActiveCount() const;
  int ViewCount() const { return static_cast<int>(views_.size()); }
  // Restricts the sum to the points with active[i] true.
  void SetActive(const std::vector<bool>& active) { active_ = active; }
  // Restricts the sum to the views (in the constructor's order) with
  // active[i] true.
  void SetActiveViews(const std::vector<bool>& active) { active_views_ = active; }
  int ActiveViewCount() const;

 private:
  struct Point {
    std::vector<Eigen::Vector3d> window;  // ideal reference pixels, homogeneous
    std::vector<float> ref;               // zero-mean, unit-norm reference patch
    double weight = 0;
    bool usable = false;  // reference patch not flat
  };
  struct OtherView {
    int view = -1;
    PlaneHomography pair;  // A, a; v set per theta
    const Camera* camera = nullptr;
    const cv::Mat* grey = nullptr;
  };
  // Correlations of the usable points (every one, or the active ones) in
  // the views (every one, or the active ones); the rest stay 0.
  void Correlate(double theta, bool all_points, bool all_views, std::vector<double>* table) const;

  const Camera* ref_camera_;
  const Pose* ref_pose_;
  const HalfPlaneFamily family_;
  std::vector<Point> points_;
  std::vector<OtherView> views_;
  std::vector<bool> active_;
  std::vector<bool> active_views_;
  int window_size_;
  int radius_ = 0;
};

// Bilinear sample of a CV_32F image at array coordinates (pixel centre of
// (0, 0) at 0, 0) known to lie within [0, cols - 1] x [0, rows - 1] (up to
// rounding: the cell index is clamped, so it never reads outside). Inline
// because it is the sweep's and the verification's innermost operation.
inline float SampleBilinearInside(const cv::Mat& image, double x, double y) {
  const int x0 = std::clamp(static_cast<int>(x), 0, image.cols - 2);
  const int y0 = std::clamp(static_cast<int>(y), 0, image.rows - 2);
  const float fx = static_cast<float>(x - x0), fy = static_cast<float>(y - y0);
  const float* r0 = image.ptr<float>(y0) + x0;
  const float* r1 = image.ptr<float>(y0 + 1) + x0;
  return (1 - fy) * ((1 - fx) * r0[0] + fx * r0[1]) + fy * ((1 - fx) * r1[0] + fx * r1[1]);
}

// As above, but false outside [0, cols - 1] x [0, rows - 1].
inline bool SampleBilinear(const cv::Mat& image, double x, double y, float* value) {
  if (!(x >= 0 && y >= 0 && x <= image.cols - 1 && y <= image.rows - 1)) return false;
  *value = SampleBilinearInside(image, x, y);
  return true;
}

// A (2 r + 1)^2 correlation window (row-major, top-left first) mapped into
// another image exactly at its centre and edge midpoints and affinely in
// between: over a 7 px window at aerial distances the second-order terms
// of a homography or a camera projection stay far below 0.01 px, and
// mapping every pixel exactly was the sweep's innermost cost.
class AffineWindow {
 public:
  // Window indices of the five pixels to map exactly: centre, left, right,
  // top, bottom.
  static std::array<int, 5> Probes(int r);
  // `mapped`: the probes' measured pixel positions (pixel-centre convention
  // of the images, as Project returns them).
  AffineWindow(const std::array<Eigen::Vector2d, 5>& mapped, int r);
  // Bilinear samples of the whole window (CV_32F image) into `values`
  // ((2 r + 1)^2 of them); false when a pixel falls outside the image.
  bool Sample(const cv::Mat& image, float* values) const;

 private:
  int r_;
  Eigen::Vector2d origin_, dx_, dy_;
};

// sum(ref * (b - mean(b))) / |b - mean(b)| over n values: the normalised
// cross-correlation of a zero-mean, unit-norm reference patch with window
// b; 0 when b is flat. A reference that is only zero-mean gives the NCC
// times its norm.
double ZeroMeanCorrelation(const float* ref, const float* values, int n);

}  // namespace roofsweep
