#include "algorithms/sweep/side_similarity.h"

#include <cmath>

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

bool AffineWindow::Sample(const cv::Mat& image, float* values, double* sum) const {
  *sum = 0;
  // The window is an affine image of a square, so it lies inside the image
  // rectangle exactly when its four corners do; checking them once lets the
  // innermost loop sample without a bounds test per pixel.
  const double n = 2 * r_;
  for (const Eigen::Vector2d& c :
       {origin_, Eigen::Vector2d(origin_ + n * dx_), Eigen::Vector2d(origin_ + n * dy_),
        Eigen::Vector2d(origin_ + n * dy_ + n * dx_)})
    if (!(c.x() >= 0 && c.y() >= 0 && c.x() <= image.cols - 1 && c.y() <= image.rows - 1))
      return false;
  for (int iy = 0, k = 0; iy <= 2 * r_; ++iy) {
    const Eigen::Vector2d row = origin_ + iy * dy_;
    for (int ix = 0; ix <= 2 * r_; ++ix, ++k) {
      const Eigen::Vector2d at = row + ix * dx_;
      values[k] = SampleBilinearInside(image, at.x(), at.y());
      *sum += values[k];
    }
  }
  return true;
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

double SideSimilarity::Evaluate(double theta, std::vector<double>* per_point,
                                std::vector<double>* per_view) const {
  if (per_point) per_point->assign(points_.size(), 0.0);
  if (per_view) per_view->assign(views_.size(), 0.0);
  const int n_active_views = ActiveViewCount();
  const auto v = PlaneVector(*ref_camera_, *ref_pose_, family_.Plane(theta));
  if (!v || views_.empty()) return 0.0;
  std::vector<Eigen::Matrix3d> H;
  H.reserve(views_.size());
  for (const OtherView& o : views_) H.push_back(o.pair.A + o.pair.a * v->transpose());
  std::vector<float> samples(window_size_);
  std::vector<double> view_sum(views_.size(), 0.0);
  double numerator = 0, weights = 0;
  for (size_t pi = 0; pi < points_.size(); ++pi) {
    const Point& p = points_[pi];
    if (!active_[pi] || !p.usable) continue;
    weights += p.weight;
    double point_sum = 0;
    // The plane must be in front of the reference camera at this point.
    if (!(v->dot(p.window[window_size_ / 2]) > 0)) continue;
    for (size_t vi = 0; vi < views_.size(); ++vi) {
      if (!per_view && !active_views_[vi]) continue;
      const OtherView& o = views_[vi];
      // Exactly at five pixels, affinely in between (AffineWindow): this is
      // the sweep's innermost loop.
      const std::array<int, 5> probe = AffineWindow::Probes(radius_);
      std::array<Eigen::Vector2d, 5> q;
      bool inside = true;
      for (int j = 0; j < 5 && inside; ++j) {
        const Eigen::Vector3d y = H[vi] * p.window[probe[j]];
        inside = y.z() > 0;
        if (inside) q[j] = MeasuredPixel(*o.camera, y.head<2>() / y.z());
      }
      double mean = 0;
      inside = inside && AffineWindow(q, radius_).Sample(*o.grey, samples.data(), &mean);
      if (!inside) continue;
      mean /= window_size_;
      double dot = 0, ss = 0;
      for (int k = 0; k < window_size_; ++k) {
        const double s = samples[k] - mean;
        dot += p.ref[k] * s;
        ss += s * s;
      }
      if (!(ss > 1e-12)) continue;
      const double cor = dot / std::sqrt(ss);
      if (!(cor > 0)) continue;
      view_sum[vi] += p.weight * cor * cor;
      if (active_views_[vi]) point_sum += cor * cor;
    }
    numerator += p.weight * point_sum;
    if (per_point && n_active_views > 0) (*per_point)[pi] = point_sum / n_active_views;
  }
  if (!(weights > 0)) return 0.0;
  if (per_view)
    for (size_t vi = 0; vi < views_.size(); ++vi) (*per_view)[vi] = view_sum[vi] / weights;
  if (n_active_views == 0) return 0.0;
  return numerator / (weights * n_active_views);
}

}  // namespace roofsweep
