#include "algorithms/edges/synthetic_images.h"

#include <cmath>
#include <opencv2/imgproc.hpp>

namespace roofsweep::testing {

cv::Mat RenderRegions(cv::Size size, const std::function<int(double, double)>& region,
                      const std::vector<cv::Vec3f>& colours, int supersample) {
  cv::Mat image(size, CV_32FC3);
  const int s = std::max(1, supersample);
  const float weight = 1.f / static_cast<float>(s * s);
  for (int y = 0; y < size.height; ++y) {
    for (int x = 0; x < size.width; ++x) {
      cv::Vec3f sum(0, 0, 0);
      for (int j = 0; j < s; ++j) {
        for (int i = 0; i < s; ++i) {
          sum += colours[region(x + (i + 0.5) / s, y + (j + 0.5) / s)];
        }
      }
      image.at<cv::Vec3f>(y, x) = sum * weight;
    }
  }
  return image;
}

cv::Mat RenderHalfPlanes(cv::Size size, const Eigen::Vector2d& point, double angle_deg,
                         const cv::Vec3f& left, const cv::Vec3f& right, int supersample) {
  const double a = angle_deg * M_PI / 180.0;
  const Eigen::Vector2d n(std::sin(a), -std::cos(a));  // (d.y, -d.x)
  return RenderRegions(
      size, [&](double x, double y) { return (Eigen::Vector2d(x, y) - point).dot(n) > 0 ? 0 : 1; },
      {left, right}, supersample);
}

void AddNoise(cv::Mat& image, double sigma, std::uint64_t seed) {
  cv::RNG rng(seed);
  cv::Mat noise(image.size(), image.type());
  rng.fill(noise, cv::RNG::NORMAL, 0.0, sigma);
  image += noise;
}

namespace {

cv::Scalar Rgb8(cv::RNG& rng, int lo, int hi) {
  return cv::Scalar(rng.uniform(lo, hi), rng.uniform(lo, hi), rng.uniform(lo, hi));
}

cv::Scalar Shade(const cv::Scalar& c, double f) {
  return cv::Scalar(std::min(255.0, c[0] * f), std::min(255.0, c[1] * f),
                    std::min(255.0, c[2] * f));
}

std::vector<cv::Point> Quad(const cv::Point2d& c, const cv::Point2d& u, const cv::Point2d& v,
                            double a0, double a1, double b0, double b1) {
  // Fixed-point vertices (4 fractional bits) keep the polygon sub-pixel.
  auto p = [&](double a, double b) {
    const cv::Point2d q = c + u * a + v * b;
    return cv::Point(static_cast<int>(std::lround(q.x * 16)),
                     static_cast<int>(std::lround(q.y * 16)));
  };
  return {p(a0, b0), p(a1, b0), p(a1, b1), p(a0, b1)};
}

}  // namespace

cv::Mat RenderRoofScene(cv::Size size, std::uint64_t seed) {
  cv::RNG rng(seed);
  // Ground: smooth low-frequency variation plus fine texture.
  cv::Mat low(std::max(2, size.height / 64), std::max(2, size.width / 64), CV_8UC3);
  rng.fill(low, cv::RNG::UNIFORM, cv::Scalar(70, 90, 60), cv::Scalar(120, 140, 100));
  cv::Mat canvas;
  cv::resize(low, canvas, size, 0, 0, cv::INTER_CUBIC);
  cv::Mat fine(size, CV_8UC3);
  rng.fill(fine, cv::RNG::NORMAL, cv::Scalar::all(0), cv::Scalar::all(6));
  cv::GaussianBlur(fine, fine, cv::Size(5, 5), 1.2);
  cv::add(canvas, fine, canvas);

  const int shift = 4;
  const double area = static_cast<double>(size.area());
  // Roads: long straight bands.
  for (int k = 0; k < static_cast<int>(area / 400000) + 2; ++k) {
    const cv::Point2d c(rng.uniform(0.0, 1.0 * size.width), rng.uniform(0.0, 1.0 * size.height));
    const double a = rng.uniform(0.0, M_PI);
    const cv::Point2d u(std::cos(a), std::sin(a)), v(-std::sin(a), std::cos(a));
    const double half = rng.uniform(6.0, 12.0);
    cv::fillConvexPoly(canvas, Quad(c, u, v, -3000, 3000, -half, half), Rgb8(rng, 100, 140),
                       cv::LINE_AA, shift);
  }
  // Buildings: rotated rectangles with gable (two shaded faces) or flat roofs.
  const int buildings = static_cast<int>(area / 12000);
  for (int k = 0; k < buildings; ++k) {
    const cv::Point2d c(rng.uniform(0.0, 1.0 * size.width), rng.uniform(0.0, 1.0 * size.height));
    const double a = rng.uniform(0.0, M_PI);
    const cv::Point2d u(std::cos(a), std::sin(a)), v(-std::sin(a), std::cos(a));
    const double len = rng.uniform(12.0, 45.0);
    const double wid = rng.uniform(8.0, 22.0);
    const cv::Scalar roof = Rgb8(rng, 60, 220);
    if (rng.uniform(0, 4) == 0) {
      cv::fillConvexPoly(canvas, Quad(c, u, v, -len, len, -wid, wid), roof, cv::LINE_AA, shift);
    } else {
      const double sun = rng.uniform(0.55, 0.85);
      cv::fillConvexPoly(canvas, Quad(c, u, v, -len, len, -wid, 0), roof, cv::LINE_AA, shift);
      cv::fillConvexPoly(canvas, Quad(c, u, v, -len, len, 0, wid), Shade(roof, sun), cv::LINE_AA,
                         shift);
    }
    // A dormer or chimney now and then.
    if (rng.uniform(0, 3) == 0) {
      cv::fillConvexPoly(canvas, Quad(c, u, v, len * 0.2, len * 0.2 + 4, -wid * 0.6, -wid * 0.3),
                         Shade(roof, 0.5), cv::LINE_AA, shift);
    }
  }
  // Trees: soft round blobs.
  for (int k = 0; k < buildings / 2; ++k) {
    const cv::Point c(rng.uniform(0, size.width), rng.uniform(0, size.height));
    cv::circle(canvas, c, rng.uniform(3, 9), cv::Scalar(40, rng.uniform(70, 110), 35), cv::FILLED,
               cv::LINE_AA);
  }
  cv::Mat image;
  canvas.convertTo(image, CV_32FC3, 1.0 / 255.0);
  AddNoise(image, 1.5 / 255.0, seed + 1);
  // Quantise to 8 bits as a camera does.
  cv::Mat bytes;
  image.convertTo(bytes, CV_8UC3, 255.0);
  bytes.convertTo(image, CV_32FC3, 1.0 / 255.0);
  return image;
}

}  // namespace roofsweep::testing
