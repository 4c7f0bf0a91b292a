#include "algorithms/sweep/points_of_interest.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace roofsweep {

ViewTexture PrepareViewTexture(const cv::Mat& image, const SweepOptions& options) {
  ViewTexture t;
  if (image.channels() == 3) {
    cv::cvtColor(image, t.grey, cv::COLOR_RGB2GRAY);
  } else {
    t.grey = image.clone();
  }
  if (t.grey.depth() != CV_32F) t.grey.convertTo(t.grey, CV_32F);
  cv::Mat blurred;
  if (options.poi_blur_sigma > 0) {
    cv::GaussianBlur(t.grey, blurred, cv::Size(0, 0), options.poi_blur_sigma);
  } else {
    blurred = t.grey;
  }
  cv::Mat grey8;
  blurred.convertTo(grey8, CV_8U, 255.0);
  cv::Canny(grey8, t.poi, options.poi_canny_low, options.poi_canny_high, 3, true);
  return t;
}

namespace {

// True when the open path from a to b (b excluded by `end_gap` px) crosses
// the segment s.
bool Crosses(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Segment2& s,
             double end_gap) {
  const Eigen::Vector2d r = b - a, q = s.second - s.first;
  const double denom = r.x() * q.y() - r.y() * q.x();
  if (std::abs(denom) < 1e-12) return false;  // parallel: never between point and line
  const Eigen::Vector2d w = s.first - a;
  const double t = (w.x() * q.y() - w.y() * q.x()) / denom;  // along a -> b
  const double u = (w.x() * r.y() - w.y() * r.x()) / denom;  // along s
  const double len = r.norm();
  const double t_max = len > end_gap ? 1.0 - end_gap / len : 0.0;
  return t >= 0 && t <= t_max && u >= 0 && u <= 1;
}

double DistanceToSegment(const Eigen::Vector2d& x, const Segment2& s) {
  const Eigen::Vector2d d = s.second - s.first;
  const double l2 = d.squaredNorm();
  const double t = l2 > 0 ? std::clamp((x - s.first).dot(d) / l2, 0.0, 1.0) : 0.0;
  return (s.first + t * d - x).norm();
}

}  // namespace

std::vector<BandPoint> BandPoints(const ViewTexture& texture, const Eigen::Vector2d& p0,
                                  const Eigen::Vector2d& p1, int image_side,
                                  const std::vector<Segment2>& blockers,
                                  const SweepOptions& options) {
  std::vector<BandPoint> out;
  const double length = (p1 - p0).norm();
  if (!(length > 2 * options.end_margin_px) || image_side == 0) return out;
  const Eigen::Vector2d u = (p1 - p0) / length;
  // Unit normal pointing to the requested side: cross(u, n) has its sign.
  const Eigen::Vector2d n = image_side * Eigen::Vector2d(-u.y(), u.x());
  const double w = options.band_width_px;
  const Eigen::Vector2d corners[4] = {p0, p1, p0 + w * n, p1 + w * n};
  double x0 = corners[0].x(), x1 = x0, y0 = corners[0].y(), y1 = y0;
  for (const auto& c : corners) {
    x0 = std::min(x0, c.x());
    x1 = std::max(x1, c.x());
    y0 = std::min(y0, c.y());
    y1 = std::max(y1, c.y());
  }
  const int cols = texture.poi.cols, rows = texture.poi.rows;
  const int c0 = std::max(0, static_cast<int>(std::floor(x0))),
            c1 = std::min(cols - 1, static_cast<int>(std::ceil(x1)));
  const int r0 = std::max(0, static_cast<int>(std::floor(y0))),
            r1 = std::min(rows - 1, static_cast<int>(std::ceil(y1)));
  // Like the line itself, other lines' edges are kept out of the windows:
  // whether they lie on the plane is for the geometric grouping to judge
  // (§4); the sweep measures the texture between them.
  const double keep_off = options.min_distance_px + options.ncc_radius;
  // Blockers near the band only.
  std::vector<Segment2> near;
  for (const auto& s : blockers) {
    if (std::max(s.first.x(), s.second.x()) < x0 || std::min(s.first.x(), s.second.x()) > x1 ||
        std::max(s.first.y(), s.second.y()) < y0 || std::min(s.first.y(), s.second.y()) > y1)
      continue;
    near.push_back(s);
  }
  // Per row only the columns where the row's pixel centres cross the band
  // (a slanted band's bounding box is mostly outside it); the exact test
  // below still decides.
  const Eigen::Vector2d band[4] = {p0, p1, p1 + w * n, p0 + w * n};
  for (int r = r0; r <= r1; ++r) {
    const double y = r + 0.5;
    double lo = x1, hi = x0;
    for (int e = 0; e < 4; ++e) {
      const Eigen::Vector2d& a = band[e];
      const Eigen::Vector2d& b = band[(e + 1) % 4];
      if ((a.y() - y) * (b.y() - y) > 0) continue;  // the edge does not reach the row
      // An edge lying on the row contributes both ends, any other its crossing.
      const double xa =
          a.y() == b.y() ? a.x() : a.x() + (b.x() - a.x()) * (y - a.y()) / (b.y() - a.y());
      const double xb = a.y() == b.y() ? b.x() : xa;
      lo = std::min({lo, xa, xb});
      hi = std::max({hi, xa, xb});
    }
    if (lo > hi) continue;
    const uint8_t* row = texture.poi.ptr<uint8_t>(r);
    const int from = std::max(c0, static_cast<int>(std::floor(lo - 0.5)) - 1);
    const int to = std::min(c1, static_cast<int>(std::ceil(hi - 0.5)) + 1);
    for (int c = from; c <= to; ++c) {
      if (!row[c]) continue;
      const Eigen::Vector2d x(c + 0.5, r + 0.5);
      const double t = (x - p0).dot(u), s = (x - p0).dot(n);
      if (t < options.end_margin_px || t > length - options.end_margin_px) continue;
      if (s < keep_off || s > w) continue;
      const Eigen::Vector2d foot = p0 + t * u;
      bool blocked = false;
      for (const auto& b : near) {
        if (Crosses(x, foot, b, 0.5) || DistanceToSegment(x, b) < keep_off) {
          blocked = true;
          break;
        }
      }
      if (!blocked) out.push_back({x, s});
    }
  }
  if (options.max_points > 0 && static_cast<int>(out.size()) > options.max_points) {
    std::vector<BandPoint> thinned;
    thinned.reserve(options.max_points);
    const double stride = static_cast<double>(out.size()) / options.max_points;
    for (int i = 0; i < options.max_points; ++i)
      thinned.push_back(out[static_cast<size_t>(i * stride)]);
    out.swap(thinned);
  }
  return out;
}

}  // namespace roofsweep
