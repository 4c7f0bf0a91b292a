#include "algorithms/sweep/side_similarity.h"

#include <cmath>
#include <vector>

namespace roofsweep {

std::array<int, 5> AffineWindow::Probes(int r) {
  const int w = 2 * r + 1, c = (w * w) / 2;
  return {c, c - r, c + r, c - r * w, c + r * w};
}

AffineWindow::AffineWindow(const std::array<Eigen::Vector2d, 5>& q, int r) : r_(r) {
  dx_ = r > 0 ? Eigen::Vector2d((q[2] - q[1]) / (2.0 * r)) : Eigen::Vector2d(0, 0);
  dy_ = r > 0 ? Eigen::Vector2d((q[4] - q[3]) / (2.0 * r)) : Eigen::Vector2d(0, 0);
  // SampleBilinear puts pixel centres at integers.
  origin_ = q[0] - r * (dx_ + dy_) - Eigen::Vector2d(0.5, 0.5);
}

namespace {

// Per-thread tables of the window's pixel offsets and the scratch of the
// sampling, sized once per radius.
struct WindowScratch {
  int r = -1;
  std::vector<float> col, row, fx, fy;
  std::vector<int> offset;
  void Resize(int radius) {
    if (radius == r) return;
    r = radius;
    const int w = 2 * r + 1, n = w * w;
    col.resize(n), row.resize(n), fx.resize(n), fy.resize(n), offset.resize(n);
    for (int k = 0; k < n; ++k)
      col[k] = static_cast<float>(k % w), row[k] = static_cast<float>(k / w);
  }
};

}  // namespace

bool AffineWindow::Sample(const cv::Mat& image, float* values) const {
  // The window is an affine image of a square, so it lies inside the image
  // rectangle exactly when its four corners do; checking them once lets the
  // innermost loop sample without a bounds test per pixel.
  const double n = 2 * r_;
  for (const Eigen::Vector2d& c :
       {origin_, Eigen::Vector2d(origin_ + n * dx_), Eigen::Vector2d(origin_ + n * dy_),
        Eigen::Vector2d(origin_ + n * dy_ + n * dx_)})
    if (!(c.x() >= 0 && c.y() >= 0 && c.x() <= image.cols - 1 && c.y() <= image.rows - 1))
      return false;
  thread_local WindowScratch t;
  t.Resize(r_);
  const int size = static_cast<int>(t.col.size());
  // Positions relative to the origin's pixel stay within a few pixels, where
  // single precision resolves 1e-6 px. Cells and weights first, in a loop
  // the compiler vectorises, then the gather: a third faster than one loop
  // in double, and this is the innermost operation of the sweep and of the
  // verification.
  const int bx = static_cast<int>(origin_.x()), by = static_cast<int>(origin_.y());
  const float ox = static_cast<float>(origin_.x() - bx), oy = static_cast<float>(origin_.y() - by);
  const float dxx = static_cast<float>(dx_.x()), dxy = static_cast<float>(dx_.y());
  const float dyx = static_cast<float>(dy_.x()), dyy = static_cast<float>(dy_.y());
  // Cells relative to (bx, by), clamped so that the 2 x 2 neighbourhood is
  // inside (a position exactly on the last column or row, or a rounding
  // off the first, keeps a weight of 1 or about 0 beyond it).
  const int min_x = -bx, min_y = -by, max_x = image.cols - 2 - bx, max_y = image.rows - 2 - by;
  const int stride = static_cast<int>(image.step1());
  for (int k = 0; k < size; ++k) {
    const float x = ox + t.row[k] * dyx + t.col[k] * dxx;
    const float y = oy + t.row[k] * dyy + t.col[k] * dxy;
    // Floor: a position a rounding left of the origin's pixel is negative.
    int cx = static_cast<int>(x), cy = static_cast<int>(y);
    cx -= x < static_cast<float>(cx);
    cy -= y < static_cast<float>(cy);
    cx = cx < min_x ? min_x : (cx > max_x ? max_x : cx);
    cy = cy < min_y ? min_y : (cy > max_y ? max_y : cy);
    t.fx[k] = x - static_cast<float>(cx);
    t.fy[k] = y - static_cast<float>(cy);
    t.offset[k] = cy * stride + cx;
  }
  const float* origin = image.ptr<float>(by) + bx;
  for (int k = 0; k < size; ++k) {
    const float* r0 = origin + t.offset[k];
    const float* r1 = r0 + stride;
    const float fx = t.fx[k], fy = t.fy[k];
    values[k] = (1 - fy) * ((1 - fx) * r0[0] + fx * r0[1]) + fy * ((1 - fx) * r1[0] + fx * r1[1]);
  }
  return true;
}

double ZeroMeanCorrelation(const float* ref, const float* values, int n) {
  // Eigen vectorises these reductions; over a window of tens of values
  // single precision keeps the correlation to about 1e-6.
  const Eigen::Map<const Eigen::ArrayXf> a(ref, n), b(values, n);
  const float mean = b.sum() / static_cast<float>(n);
  const double dot = (a * (b - mean)).sum();
  const double ss = (b - mean).square().sum();
  return ss > 1e-12 ? dot / std::sqrt(ss) : 0.0;
}

SideSimilarity::SideSimilarity(const Block& block, const std::vector<ViewTexture>& textures,
                               const HalfPlaneFamily& family, int reference_view,
                               const std::vector<int>& other_views,
                               const std::vector<BandPoint>& points, const SweepOptions& options)
    : family_(family) {
  const View& ref = block.views.at(reference_view);
  ref_camera_ = &block.CameraOf(ref);
  ref_pose_ = &ref.pose;
  const cv::Mat& ref_grey = textures.at(reference_view).grey;
  const int r = std::max(0, options.ncc_radius);
  radius_ = r;
  window_size_ = (2 * r + 1) * (2 * r + 1);
  points_.reserve(points.size());
  for (const BandPoint& bp : points) {
    Point p;
    p.weight = 1.0 / std::max(1.0, bp.distance);
    p.ref.reserve(window_size_);
    p.window.reserve(window_size_);
    double sum = 0;
    bool inside = true;
    for (int dy = -r; dy <= r && inside; ++dy) {
      for (int dx = -r; dx <= r; ++dx) {
        const Eigen::Vector2d px = bp.pixel + Eigen::Vector2d(dx, dy);
        float value;
        if (!SampleBilinear(ref_grey, px.x() - 0.5, px.y() - 0.5, &value)) {
          inside = false;
          break;
        }
        p.ref.push_back(value);
        sum += value;
        const Eigen::Vector2d ideal = IdealPixel(*ref_camera_, px);
        p.window.emplace_back(ideal.x(), ideal.y(), 1.0);
      }
    }
    if (inside) {
      const double mean = sum / window_size_;
      double ss = 0;
      for (float& v : p.ref) {
        v = static_cast<float>(v - mean);
        ss += static_cast<double>(v) * v;
      }
      // A flat patch has no correlation to offer (grey levels of 1/255 per
      // pixel are the floor of an 8-bit sensor).
      if (ss > window_size_ * 1e-6) {
        const float inv = static_cast<float>(1.0 / std::sqrt(ss));
        for (float& v : p.ref) v *= inv;
        p.usable = true;
      }
    }
    points_.push_back(std::move(p));
  }
  active_.assign(points_.size(), true);
  for (int v : other_views) {
    const View& view = block.views.at(v);
    OtherView o;
    o.view = v;
    o.camera = &block.CameraOf(view);
    o.pair = ViewPairHomography(*ref_camera_, *ref_pose_, *o.camera, view.pose);
    o.grey = &textures.at(v).grey;
    views_.push_back(o);
  }
  active_views_.assign(views_.size(), true);
}

int SideSimilarity::ActiveViewCount() const {
  int n = 0;
  for (bool a : active_views_) n += a;
  return n;
}

int SideSimilarity::ActiveCount() const {
  int n = 0;
  for (size_t i = 0; i < points_.size(); ++i) n += active_[i] && points_[i].usable;
  return n;
}

void SideSimilarity::Correlate(double theta, bool all_points, bool all_views,
                               std::vector<double>* table) const {
  const size_t n_views = views_.size();
  table->assign(points_.size() * n_views, 0.0);
  const auto v = PlaneVector(*ref_camera_, *ref_pose_, family_.Plane(theta));
  if (!v || views_.empty()) return;
  std::vector<Eigen::Matrix3d> H;
  H.reserve(n_views);
  for (const OtherView& o : views_) H.push_back(o.pair.A + o.pair.a * v->transpose());
  const std::array<int, 5> probe = AffineWindow::Probes(radius_);
  std::vector<float> samples(window_size_);
  for (size_t pi = 0; pi < points_.size(); ++pi) {
    const Point& p = points_[pi];
    if (!p.usable || !(all_points || active_[pi])) continue;
    // The plane must be in front of the reference camera at this point.
    if (!(v->dot(p.window[window_size_ / 2]) > 0)) continue;
    for (size_t vi = 0; vi < n_views; ++vi) {
      if (!all_views && !active_views_[vi]) continue;
      const OtherView& o = views_[vi];
      // Exactly at five pixels, affinely in between (AffineWindow): this is
      // the sweep's innermost loop.
      std::array<Eigen::Vector2d, 5> q;
      bool inside = true;
      for (int j = 0; j < 5 && inside; ++j) {
        const Eigen::Vector3d y = H[vi] * p.window[probe[j]];
        inside = y.z() > 0;
        if (inside) q[j] = MeasuredPixel(*o.camera, y.head<2>() / y.z());
      }
      inside = inside && AffineWindow(q, radius_).Sample(*o.grey, samples.data());
      if (!inside) continue;
      const double cor = ZeroMeanCorrelation(p.ref.data(), samples.data(), window_size_);
      if (cor > 0) (*table)[pi * n_views + vi] = cor * cor;
    }
  }
}

std::vector<double> SideSimilarity::Correlations(double theta) const {
  std::vector<double> table;
  Correlate(theta, true, true, &table);
  return table;
}

double SideSimilarity::Evaluate(double theta, std::vector<double>* per_point,
                                std::vector<double>* per_view) const {
  std::vector<double> table;
  Correlate(theta, false, per_view != nullptr, &table);
  return Reduce(table, per_point, per_view);
}

double SideSimilarity::Reduce(const std::vector<double>& table, std::vector<double>* per_point,
                              std::vector<double>* per_view) const {
  if (per_point) per_point->assign(points_.size(), 0.0);
  if (per_view) per_view->assign(views_.size(), 0.0);
  const size_t n_views = views_.size();
  const int n_active_views = ActiveViewCount();
  std::vector<double> view_sum(n_views, 0.0);
  double numerator = 0, weights = 0;
  for (size_t pi = 0; pi < points_.size(); ++pi) {
    const Point& p = points_[pi];
    if (!active_[pi] || !p.usable) continue;
    weights += p.weight;
    double point_sum = 0;
    for (size_t vi = 0; vi < n_views; ++vi) {
      const double c = table[pi * n_views + vi];
      view_sum[vi] += p.weight * c;
      if (active_views_[vi]) point_sum += c;
    }
    numerator += p.weight * point_sum;
    if (per_point && n_active_views > 0) (*per_point)[pi] = point_sum / n_active_views;
  }
  if (!(weights > 0)) return 0.0;
  if (per_view)
    for (size_t vi = 0; vi < n_views; ++vi) (*per_view)[vi] = view_sum[vi] / weights;
  if (n_active_views == 0) return 0.0;
  return numerator / (weights * n_active_views);
}

}  // namespace roofsweep
