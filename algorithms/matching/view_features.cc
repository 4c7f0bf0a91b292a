#include "algorithms/matching/view_features.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "algorithms/core/error.h"
#include "algorithms/matching/robust_estimate.h"

namespace roofsweep {

Eigen::Vector2d ViewFeatures::Distorted(const Eigen::Vector2d& ideal_px) const {
  const Eigen::Vector3d n = camera->K().inverse() * ideal_px.homogeneous();
  return camera->NormalizedToPixel(n.hnormalized());
}

Eigen::Vector2d ViewFeatures::Undistorted(const Eigen::Vector2d& image_px) const {
  const Eigen::Vector2d n = camera->PixelToNormalized(image_px);
  return (camera->K() * n.homogeneous()).hnormalized();
}

std::vector<Eigen::Vector2d> FlankingRegion(const cv::Mat& labels, const Segment2D& s, int id,
                                            int side, double offset, double width) {
  std::vector<Eigen::Vector2d> out;
  const double len = s.Length();
  if (len < 1) return out;
  const Eigen::Vector2d d = s.Direction();
  const Eigen::Vector2d n = s.LeftNormal() * static_cast<double>(side);
  const int cols = static_cast<int>(std::floor(len)) + 1;
  const int rows = std::max(1, static_cast<int>(std::lround(width)));
  auto pos = [&](int i, int j) {
    return Eigen::Vector2d(s.p0 + (std::min<double>(i, len)) * d + (offset + j + 0.5) * n);
  };
  auto contour = [&](int i, int j) {
    const Eigen::Vector2d p = pos(i, j);
    const int x = static_cast<int>(std::floor(p.x())), y = static_cast<int>(std::floor(p.y()));
    if (x < 0 || y < 0 || x >= labels.cols || y >= labels.rows) return true;
    const int l = labels.at<int>(y, x);
    return l >= 0 && l != id;
  };
  std::vector<char> prev(cols, 1), cur(cols, 0);
  for (int j = 0; j < rows; ++j) {
    bool any = false;
    for (int i = 0; i < cols; ++i) {
      bool ok = j == 0 || ((i == 0 || prev[i - 1]) && prev[i] && (i + 1 >= cols || prev[i + 1]));
      // Stop one cell before a neighbouring contour (the offset again).
      // Beyond the first row, prev[i] already says cell (i, j) is no
      // contour: it was looked ahead at from row j - 1.
      ok = ok && (j > 0 || !contour(i, j)) && !contour(i, j + 1);
      cur[i] = ok;
      if (ok) {
        out.push_back(pos(i, j));
        any = true;
      }
    }
    if (!any) break;
    std::swap(prev, cur);
  }
  return out;
}

SideColour RegionColour(const cv::Mat& lab, const std::vector<Eigen::Vector2d>& pixels,
                        const MatchOptions& options, unsigned seed) {
  SideColour sc;
  // A regular subsample of long regions: the L* band and the (a*, b*)
  // estimate below need a few hundred pixels, and sorting all of a long
  // segment's region was a tenth of the whole matching time.
  constexpr size_t kMaxPixels = 400;
  const size_t step =
      pixels.size() > kMaxPixels ? (pixels.size() + kMaxPixels - 1) / kMaxPixels : 1;
  std::vector<Eigen::Vector3f> v;
  v.reserve(pixels.size() / step + 1);
  for (size_t k = 0; k < pixels.size(); k += step) {
    const Eigen::Vector2d& p = pixels[k];
    const int x = static_cast<int>(std::floor(p.x())), y = static_cast<int>(std::floor(p.y()));
    if (x < 0 || y < 0 || x >= lab.cols || y >= lab.rows) continue;
    const cv::Vec3f c = lab.at<cv::Vec3f>(y, x);
    v.emplace_back(c[0], c[1], c[2]);
  }
  if (static_cast<int>(v.size()) < options.min_region_pixels) return sc;
  std::vector<double> l(v.size());
  for (size_t i = 0; i < v.size(); ++i) l[i] = v[i].x();
  const Robust1D rl = RobustMcd1D(l);
  // L* noise floor: 8-bit quantisation alone is ~0.2 L*.
  const double scale = std::max(rl.scale, 0.5);
  std::vector<Eigen::Vector2d> ab;
  for (const Eigen::Vector3f& c : v)
    if (std::abs(c.x() - rl.location) <= options.l_outlier_sigmas * scale)
      ab.emplace_back(c.y(), c.z());
  if (static_cast<int>(ab.size()) < options.min_region_pixels) return sc;
  // A regular subsample keeps the estimator cheap on long segments; the
  // tests cap n at max_test_pixels anyway.
  const size_t cap = 150;
  if (ab.size() > cap) {
    std::vector<Eigen::Vector2d> sub;
    sub.reserve(cap);
    for (size_t k = 0; k < cap; ++k) sub.push_back(ab[k * ab.size() / cap]);
    ab.swap(sub);
  }
  const Robust2D r = RobustMcd2D(ab, seed, 4);
  if (!r.valid) return sc;
  sc.valid = true;
  sc.n = r.inliers;
  sc.mean = r.mean;
  // Floor of the chroma scatter (quantisation, flat synthetic regions):
  // differences below ~0.3 a*/b* units are not colour differences.
  sc.cov = r.cov + Eigen::Matrix2d::Identity() * 0.09;
  sc.l_location = rl.location;
  sc.l_scale = scale;
  return sc;
}

ViewFeatures PrepareView(const Block& block, int view, const cv::Mat& image, Segments2D segments,
                         const MatchOptions& options, const ColourCorrection& correction) {
  if (image.empty() || (image.type() != CV_32FC3 && image.type() != CV_32FC1))
    throw Error("match: image of view " + block.views.at(view).name +
                " must be CV_32FC3 or CV_32FC1");
  ViewFeatures f;
  f.view = view;
  const View& v = block.views.at(view);
  f.camera = &block.CameraOf(v);
  f.distorted = f.camera->HasDistortion();
  f.pose = v.pose;
  f.P = ProjectionMatrix(*f.camera, v.pose);
  cv::Mat rgb;
  if (image.channels() == 1) {
    cv::cvtColor(image, rgb, cv::COLOR_GRAY2RGB);
  } else {
    rgb = image;
  }
  const ColourCorrectionTable table(image.channels() == 1 ? ColourCorrection{} : correction);
  // In row bands: no full-size clipped copy (each 48 MB temporary of a
  // 2048² view costs more in page faults than in arithmetic).
  f.lab.create(rgb.size(), CV_32FC3);
  constexpr int kBand = 64;
  const int bands = (rgb.rows + kBand - 1) / kBand;
  std::vector<float> chroma(bands, 0.f);  // max |a*|, |b*| per band
  tbb::parallel_for(0, bands, [&](int b) {
    const cv::Range rows(b * kBand, std::min(rgb.rows, (b + 1) * kBand));
    cv::Mat clipped(rows.size(), rgb.cols, CV_32FC3);
    for (int y = rows.start; y < rows.end; ++y)
      table.Apply(rgb.ptr<cv::Vec3f>(y), clipped.ptr<cv::Vec3f>(y - rows.start), rgb.cols);
    // A gain above 1 can push corrected values past 1.
    if (!table.Identity()) cv::min(cv::max(clipped, 0.0), 1.0, clipped);
    cv::Mat lab = f.lab.rowRange(rows);
    cv::cvtColor(clipped, lab, cv::COLOR_RGB2Lab);
    for (int y = 0; y < lab.rows; ++y) {
      const cv::Vec3f* px = lab.ptr<cv::Vec3f>(y);
      for (int x = 0; x < lab.cols; ++x)
        chroma[b] = std::max({chroma[b], std::abs(px[x][1]), std::abs(px[x][2])});
    }
  });
  f.grey = *std::max_element(chroma.begin(), chroma.end()) < 0.5f;
  {
    cv::Mat l0, gx, gy, l;
    cv::extractChannel(f.lab, l0, 0);
    cv::GaussianBlur(l0, l, cv::Size(0, 0), 1.0);
    cv::Sobel(l, gx, CV_32F, 1, 0, 3, 1.0 / 800.0);  // 1/8 Sobel norm, 1/100 L* range
    cv::Sobel(l, gy, CV_32F, 0, 1, 3, 1.0 / 800.0);
    cv::magnitude(gx, gy, f.gradient);
  }
  f.labels = RasterizeSegments(segments, f.lab.size());
  f.segments = std::move(segments);
  f.ideal = f.segments;
  for (Segment2D& s : f.ideal) {
    s.p0 = f.ToIdeal(s.p0);
    s.p1 = f.ToIdeal(s.p1);
  }
  f.index = std::make_unique<SegmentIndex>(f.ideal);
  f.sides.resize(f.segments.size());
  // Per segment as well as per view: views differ in their number of
  // segments by a factor of two, and with fewer cores than views the
  // largest one ends the stage alone. Each result depends only on its
  // segment (and seed), so the split does not change it.
  tbb::parallel_for(tbb::blocked_range<size_t>(0, f.segments.size(), 64),
                    [&](const tbb::blocked_range<size_t>& r) {
                      for (size_t i = r.begin(); i != r.end(); ++i) {
                        if (f.segments[i].Length() < options.min_length) continue;
                        for (int k = 0; k < 2; ++k) {
                          const auto px = FlankingRegion(
                              f.labels, f.segments[i], static_cast<int>(i), k == 0 ? 1 : -1,
                              options.region_offset, options.region_width);
                          f.sides[i][k] =
                              RegionColour(f.lab, px, options,
                                           options.seed * 7919u + static_cast<unsigned>(i * 2 + k));
                        }
                      }
                    });
  return f;
}

}  // namespace roofsweep
