#include "algorithms/sweep/colour_breaks.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "algorithms/buildings/convex_polygon2.h"
#include "algorithms/core/error.h"
#include "algorithms/geometry/view.h"
#include "algorithms/sweep/plane_fit.h"

namespace roofsweep {
namespace {

constexpr double kDeg = M_PI / 180.0;

struct Sample {
  double t = 0;    // down the fall line
  int column = 0;  // along the face, in steps of the spacing from its start
  cv::Vec3f lab;
};

// The median of `v` (reordered).
float Median(std::vector<float>* v) {
  const auto mid = v->begin() + v->size() / 2;
  std::nth_element(v->begin(), mid, v->end());
  return *mid;
}

// Median of each L*a*b* channel over `idx`.
cv::Vec3f MedianLab(const std::vector<Sample>& s, const std::vector<int>& idx,
                    std::vector<float>* work) {
  cv::Vec3f m;
  for (int c = 0; c < 3; ++c) {
    work->clear();
    for (int i : idx) work->push_back(s[i].lab[c]);
    m[c] = Median(work);
  }
  return m;
}

cv::Vec3f MeanLab(const std::vector<Sample>& s, const std::vector<int>& idx) {
  cv::Vec3f m(0, 0, 0);
  for (int i : idx) m += s[i].lab;
  return m * (1.0f / static_cast<float>(idx.size()));
}

// Half the finest ground sample distance at `x` over the colour views that
// see it; 0 when none does.
double HalfPixelOnGround(const Block& block, const std::vector<cv::Mat>& images,
                         const Eigen::Vector3d& x) {
  double best = 0;
  for (size_t v = 0; v < block.views.size(); ++v) {
    if (images[v].channels() != 3) continue;
    const View& view = block.views[v];
    const Camera& cam = block.CameraOf(view);
    const auto px = Project(cam, view.pose, x);
    if (!px || px->x() < 0 || px->y() < 0 || px->x() > cam.width || px->y() > cam.height) continue;
    const double half = 0.5 * view.pose.ToCamera(x).z() / std::max(cam.fx, cam.fy);
    if (half > 0 && (best == 0 || half < best)) best = half;
  }
  return best;
}

// The samples of one patch on the plane, `spacing` apart, coloured by the
// median over the views that see them: `columns` columns along the face
// from u0, rows down it from t0.
std::vector<Sample> ColourSamples(const Block& block, const std::vector<cv::Mat>& images,
                                  const RoofPlaneHypothesis& p, const Eigen::Vector2d& across,
                                  const Eigen::Vector2d& fall, double u0, int columns, double t0,
                                  int rows, double spacing, const ColourBreakOptions& o) {
  std::vector<Sample> samples;
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < columns; ++i)
    for (int j = 0; j < rows; ++j) {
      const double u = u0 + (i + 0.5) * spacing, t = t0 + (j + 0.5) * spacing;
      const Eigen::Vector2d x = u * across + t * fall;
      if (!InsideConvex(p.patch, x)) continue;
      samples.push_back({t, i, {}});
      points.emplace_back(x.x(), x.y(), PlaneZ(p.plane, x.x(), x.y()));
    }
  // All (sample, view) colours of the patch go through one conversion.
  std::vector<int> owner;
  std::vector<cv::Vec3f> values;
  for (size_t v = 0; v < block.views.size(); ++v) {
    const cv::Mat& img = images[v];
    if (img.channels() != 3) continue;
    const View& view = block.views[v];
    const Camera& cam = block.CameraOf(view);
    for (size_t k = 0; k < points.size(); ++k) {
      const auto px = Project(cam, view.pose, points[k]);
      if (!px) continue;
      // Array coordinates: the centre of pixel (0, 0) at (0, 0).
      const double x = px->x() - 0.5, y = px->y() - 0.5;
      if (!(x >= 0 && y >= 0 && x < img.cols - 1 && y < img.rows - 1)) continue;
      const int xi = static_cast<int>(x), yi = static_cast<int>(y);
      const float fx = static_cast<float>(x - xi), fy = static_cast<float>(y - yi);
      const cv::Vec3f* r0 = img.ptr<cv::Vec3f>(yi) + xi;
      const cv::Vec3f* r1 = img.ptr<cv::Vec3f>(yi + 1) + xi;
      values.push_back((1 - fy) * ((1 - fx) * r0[0] + fx * r0[1]) +
                       fy * ((1 - fx) * r1[0] + fx * r1[1]));
      owner.push_back(static_cast<int>(k));
    }
  }
  if (values.empty()) return {};
  cv::Mat in(static_cast<int>(values.size()), 1, CV_32FC3, values.data()), lab;
  cv::cvtColor(cv::min(cv::max(in, 0.0), 1.0), lab, cv::COLOR_RGB2Lab);
  std::vector<std::vector<cv::Vec3f>> per(samples.size());
  for (size_t m = 0; m < owner.size(); ++m)
    per[owner[m]].push_back(lab.at<cv::Vec3f>(static_cast<int>(m)));
  std::vector<Sample> out;
  std::vector<float> work;
  for (size_t k = 0; k < samples.size(); ++k) {
    const auto& c = per[k];
    if (static_cast<int>(c.size()) < o.min_views) continue;
    Sample s = samples[k];
    for (int ch = 0; ch < 3; ++ch) {
      work.clear();
      for (const auto& x : c) work.push_back(x[ch]);
      s.lab[ch] = Median(&work);
    }
    out.push_back(s);
  }
  return out;
}

std::vector<std::array<Eigen::Vector2d, 2>> BreaksOf(const Block& block,
                                                     const std::vector<cv::Mat>& images,
                                                     const RoofPlaneHypothesis& p,
                                                     const ColourBreakOptions& o) {
  const Eigen::Vector2d g = p.plane.head<2>();
  if (p.patch.size() < 3 || g.norm() < std::sin(o.min_slope_deg * kDeg)) return {};
  const Eigen::Vector2d fall = g.normalized(), across(-fall.y(), fall.x());
  double u0 = 1e300, u1 = -1e300, t0 = 1e300, t1 = -1e300;
  for (const auto& q : p.patch) {
    u0 = std::min(u0, q.dot(across)), u1 = std::max(u1, q.dot(across));
    t0 = std::min(t0, q.dot(fall)), t1 = std::max(t1, q.dot(fall));
  }
  if (u1 - u0 < 2 * o.min_side_m) return {};
  // Samples closer than half a pixel add nothing but time: at the fixed
  // spacing a block of 6 m pixels took 3600 samples per pixel, and this
  // step 11 s for no break (orthority's NGI block).
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  for (const auto& q : p.patch) centre += q;
  centre /= static_cast<double>(p.patch.size());
  const double half_pixel = HalfPixelOnGround(
      block, images,
      Eigen::Vector3d(centre.x(), centre.y(), PlaneZ(p.plane, centre.x(), centre.y())));
  if (half_pixel == 0) return {};
  const double spacing = std::max(o.spacing_m, half_pixel);
  const int ncol = static_cast<int>((u1 - u0) / spacing) + 1;
  const int nrow = static_cast<int>((t1 - t0) / spacing) + 1;
  const std::vector<Sample> s =
      ColourSamples(block, images, p, across, fall, u0, ncol, t0, nrow, spacing, o);
  if (s.empty()) return {};
  std::vector<std::vector<int>> column(ncol);
  for (size_t k = 0; k < s.size(); ++k) column[s[k].column].push_back(static_cast<int>(k));
  const int half_gap = static_cast<int>(std::lround(0.5 * o.gap_m / spacing));
  const int win = std::max(1, static_cast<int>(std::lround(o.window_m / spacing)));
  const int side = static_cast<int>(std::lround(o.min_side_m / spacing));
  const int bands = std::max(1, o.depth_bands);
  // score[c]: the smallest colour difference over the depth bands of a
  // break between columns c - 1 and c; 0 where none can be judged. The
  // medians keep it from a chimney or a dormer in a window, but they stay
  // on one colour until half a window lies beyond the seam, so the score
  // is flat for a window's width around it: the difference of the means,
  // which peaks at the seam, places the break (sharp[c]).
  std::vector<double> sharp(ncol, 0.0);
  std::vector<double> score(ncol, 0.0);
  std::vector<double> t_lo(ncol, 0.0), t_hi(ncol, 0.0);
  std::vector<int> left, right;
  std::vector<float> work;
  for (int c = side; c <= ncol - side; ++c) {
    std::vector<int> near;
    for (int k = c - half_gap - win; k < c + half_gap + win; ++k)
      if (k >= 0 && k < ncol && (k < c - half_gap || k >= c + half_gap))
        near.insert(near.end(), column[k].begin(), column[k].end());
    if (near.empty()) continue;
    double lo = 1e300, hi = -1e300;
    for (int k : near) lo = std::min(lo, s[k].t), hi = std::max(hi, s[k].t);
    if (hi - lo < o.min_depth_m) continue;
    double worst = 1e300, worst_mean = 1e300;
    for (int b = 0; b < bands && worst > 0; ++b) {
      const double b0 = lo + (hi - lo) * b / bands, b1 = lo + (hi - lo) * (b + 1) / bands;
      left.clear(), right.clear();
      for (int k : near)
        if (s[k].t >= b0 && s[k].t <= b1) (s[k].column < c ? left : right).push_back(k);
      if (static_cast<int>(left.size()) < o.min_samples ||
          static_cast<int>(right.size()) < o.min_samples) {
        worst = 0;
        break;
      }
      const cv::Vec3f a = MedianLab(s, left, &work), d = MedianLab(s, right, &work);
      worst = std::min(worst, static_cast<double>(cv::norm(a - d)));
      worst_mean =
          std::min(worst_mean, static_cast<double>(cv::norm(MeanLab(s, left) - MeanLab(s, right))));
    }
    score[c] = worst;
    sharp[c] = worst > 0 ? worst_mean : 0.0;
    t_lo[c] = lo, t_hi[c] = hi;
  }
  // The strongest breaks first, each keeping min_side_m clear of the others.
  std::vector<int> order(ncol);
  for (int c = 0; c < ncol; ++c) order[c] = c;
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return score[a] > score[b]; });
  std::vector<int> chosen;
  for (int c : order) {
    if (score[c] < o.min_delta_e) break;
    int at = c;
    for (int k = std::max(0, c - win); k <= std::min(ncol - 1, c + win); ++k)
      if (sharp[k] > sharp[at]) at = k;
    bool clear = true;
    for (int k : chosen) clear = clear && std::abs(k - at) >= side;
    if (clear) chosen.push_back(at);
  }
  std::sort(chosen.begin(), chosen.end());
  std::vector<std::array<Eigen::Vector2d, 2>> out;
  for (int c : chosen) {
    const double u = u0 + c * spacing;
    out.push_back({u * across + t_lo[c] * fall, u * across + t_hi[c] * fall});
  }
  return out;
}

}  // namespace

std::vector<std::vector<std::array<Eigen::Vector2d, 2>>> FindColourBreaks(
    const Block& block, const std::vector<cv::Mat>& images,
    const std::vector<RoofPlaneHypothesis>& planes, const ColourBreakOptions& o) {
  if (!(o.spacing_m > 0) || !(o.window_m > 0) || o.depth_bands < 1)
    throw Error("ColourBreakOptions: spacing_m and window_m must be > 0, depth_bands >= 1");
  if (images.size() != block.views.size())
    throw Error("FindColourBreaks: one image per view expected");
  std::vector<std::vector<std::array<Eigen::Vector2d, 2>>> out(planes.size());
  tbb::parallel_for(size_t{0}, planes.size(),
                    [&](size_t i) { out[i] = BreaksOf(block, images, planes[i], o); });
  return out;
}

}  // namespace roofsweep
