#include "algorithms/edges/gradient.h"

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "algorithms/core/error.h"

namespace roofsweep {
namespace {

cv::Mat Smooth(const cv::Mat& plane, double sigma) {
  if (sigma <= 0) return plane;
  // ±3 sigma holds 99.7 % of the kernel; OpenCV's own choice (±4 sigma for
  // float) costs a third more for no visible change in the edges.
  const int radius = std::max(1, static_cast<int>(std::ceil(3.0 * sigma)));
  cv::Mat out;
  cv::GaussianBlur(plane, out, cv::Size(2 * radius + 1, 2 * radius + 1), sigma, sigma,
                   cv::BORDER_REPLICATE);
  return out;
}

struct RowPointers {
  const float* up;
  const float* mid;
  const float* down;
};

void GreyRows(const cv::Mat& p, GradientField& g, int y0, int y1) {
  const int w = p.cols;
  for (int y = y0; y < y1; ++y) {
    const float* up = p.ptr<float>(y - 1);
    const float* mid = p.ptr<float>(y);
    const float* down = p.ptr<float>(y + 1);
    float* m = g.magnitude.ptr<float>(y);
    float* gx = g.gx.ptr<float>(y);
    float* gy = g.gy.ptr<float>(y);
    for (int x = 1; x < w - 1; ++x) {
      const float dx = 0.5f * (mid[x + 1] - mid[x - 1]);
      const float dy = 0.5f * (down[x] - up[x]);
      gx[x] = dx;
      gy[x] = dy;
      m[x] = std::sqrt(dx * dx + dy * dy);
    }
  }
}

void ColourRows(const std::vector<cv::Mat>& planes, GradientMethod method, GradientField& g, int y0,
                int y1) {
  const int w = planes[0].cols;
  const bool dizenzo = method == GradientMethod::kDiZenzo;
  for (int y = y0; y < y1; ++y) {
    RowPointers r[3];
    for (int b = 0; b < 3; ++b) {
      r[b] = {planes[b].ptr<float>(y - 1), planes[b].ptr<float>(y), planes[b].ptr<float>(y + 1)};
    }
    float* m = g.magnitude.ptr<float>(y);
    float* gxo = g.gx.ptr<float>(y);
    float* gyo = g.gy.ptr<float>(y);
    uchar* bo = dizenzo ? nullptr : g.band.ptr<uchar>(y);
    // Branch-free selects so that the compiler vectorises the loop.
    for (int x = 1; x < w - 1; ++x) {
      const float dx0 = 0.5f * (r[0].mid[x + 1] - r[0].mid[x - 1]);
      const float dy0 = 0.5f * (r[0].down[x] - r[0].up[x]);
      const float dx1 = 0.5f * (r[1].mid[x + 1] - r[1].mid[x - 1]);
      const float dy1 = 0.5f * (r[1].down[x] - r[1].up[x]);
      const float dx2 = 0.5f * (r[2].mid[x + 1] - r[2].mid[x - 1]);
      const float dy2 = 0.5f * (r[2].down[x] - r[2].up[x]);
      const float n0 = dx0 * dx0 + dy0 * dy0;
      const float n1 = dx1 * dx1 + dy1 * dy1;
      const float n2 = dx2 * dx2 + dy2 * dy2;
      const bool one = n1 > n0;
      float best = one ? n1 : n0;
      float bx = one ? dx1 : dx0;
      float by = one ? dy1 : dy0;
      int bb = one ? 1 : 0;
      const bool two = n2 > best;
      best = two ? n2 : best;
      bx = two ? dx2 : bx;
      by = two ? dy2 : by;
      bb = two ? 2 : bb;
      if (!dizenzo) {
        m[x] = std::sqrt(best);
        gxo[x] = bx;
        gyo[x] = by;
        bo[x] = static_cast<uchar>(bb);
        continue;
      }
      // D = JᵀJ = [a b; b c]; largest eigenvalue and its eigenvector.
      const float a = dx0 * dx0 + dx1 * dx1 + dx2 * dx2;
      const float bxy = dx0 * dy0 + dx1 * dy1 + dx2 * dy2;
      const float c = dy0 * dy0 + dy1 * dy1 + dy2 * dy2;
      const float half = 0.5f * (a - c);
      const float lambda = 0.5f * (a + c) + std::sqrt(half * half + bxy * bxy);
      // (lambda - c, b) and (b, lambda - a) are both eigenvectors; take the
      // longer one, the other vanishes when D is nearly diagonal.
      float ex = a >= c ? lambda - c : bxy;
      float ey = a >= c ? bxy : lambda - a;
      const float en = std::sqrt(ex * ex + ey * ey);
      const float mag = std::sqrt(lambda);
      const float scale = en > 0 ? mag / en : 0.f;
      const float sign = ex * bx + ey * by < 0 ? -scale : scale;
      m[x] = mag;
      gxo[x] = ex * sign;
      gyo[x] = ey * sign;
    }
  }
}

}  // namespace

std::vector<cv::Mat> GradientPlanes(const cv::Mat& image, GradientMethod method) {
  std::vector<cv::Mat> planes;
  if (image.channels() == 1) {
    planes.push_back(image);
  } else if (method == GradientMethod::kGrey) {
    cv::Mat grey;
    cv::cvtColor(image, grey, cv::COLOR_RGB2GRAY);
    planes.push_back(grey);
  } else {
    cv::split(image, planes);
  }
  return planes;
}

GradientField ComputeGradient(const std::vector<cv::Mat>& planes, GradientMethod method,
                              double sigma) {
  if (planes.empty() || (planes.size() != 1 && planes.size() != 3) ||
      planes[0].type() != CV_32FC1 || (planes.size() == 3 && method == GradientMethod::kGrey)) {
    throw Error("ComputeGradient: expected 1 or 3 CV_32F planes (1 for the grey method)");
  }
  const int w = planes[0].cols;
  const int h = planes[0].rows;
  std::vector<cv::Mat> smooth;
  smooth.reserve(planes.size());
  for (const cv::Mat& p : planes) smooth.push_back(Smooth(p, sigma));

  GradientField g;
  g.magnitude = cv::Mat::zeros(h, w, CV_32F);
  g.gx = cv::Mat::zeros(h, w, CV_32F);
  g.gy = cv::Mat::zeros(h, w, CV_32F);
  const bool colour = smooth.size() == 3;
  if (colour && method == GradientMethod::kMax) g.band = cv::Mat::zeros(h, w, CV_8U);
  if (w < 3 || h < 3) return g;

  cv::parallel_for_(cv::Range(1, h - 1), [&](const cv::Range& rows) {
    if (colour) {
      ColourRows(smooth, method, g, rows.start, rows.end);
    } else {
      GreyRows(smooth[0], g, rows.start, rows.end);
    }
  });
  return g;
}

}  // namespace roofsweep
