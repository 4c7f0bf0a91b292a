#include "algorithms/edges/gradient.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <opencv2/imgproc.hpp>

#include "algorithms/core/error.h"
#include "algorithms/core/vector_clones.h"

namespace roofsweep {
namespace {

void SmoothInPlace(cv::Mat& plane, double sigma) {
  if (sigma <= 0) return;
  // ±3 sigma holds 99.7 % of the kernel; OpenCV's own choice (±4 sigma for
  // float) costs a third more for no visible change in the edges.
  const int radius = std::max(1, static_cast<int>(std::ceil(3.0 * sigma)));
  cv::GaussianBlur(plane, plane, cv::Size(2 * radius + 1, 2 * radius + 1), sigma, sigma,
                   cv::BORDER_REPLICATE);
}

// The fused gradient at one pixel from the central differences of its
// bands. Row kernels and GradientAt share these, so that a gradient
// recomputed at one pixel equals the one of its row to the bit. They are
// branch-free (selects, not ifs) so that GCC vectorises the row loops.
struct PixelGradient {
  float m, gx, gy;
  int band;  // 0..2, the strongest band (ties to the lower one)
};

inline PixelGradient GreyPixel(float dx, float dy) {
  return {std::sqrt(dx * dx + dy * dy), dx, dy, 0};
}

// The band with the largest squared norm (ties to the lower band): its
// squared norm in m, its gradient, its index.
inline PixelGradient StrongestBand(float dx0, float dy0, float dx1, float dy1, float dx2,
                                   float dy2) {
  const float n0 = dx0 * dx0 + dy0 * dy0;
  const float n1 = dx1 * dx1 + dy1 * dy1;
  const float n2 = dx2 * dx2 + dy2 * dy2;
  const bool one = n1 > n0;
  float best = one ? n1 : n0;
  float bx = one ? dx1 : dx0;
  float by = one ? dy1 : dy0;
  const bool two = n2 > best;
  best = two ? n2 : best;
  bx = two ? dx2 : bx;
  by = two ? dy2 : by;
  return {best, bx, by, two ? 2 : (one ? 1 : 0)};
}

inline PixelGradient MaxPixel(float dx0, float dy0, float dx1, float dy1, float dx2, float dy2) {
  PixelGradient p = StrongestBand(dx0, dy0, dx1, dy1, dx2, dy2);
  p.m = std::sqrt(p.m);
  return p;
}

inline PixelGradient DiZenzoPixel(float dx0, float dy0, float dx1, float dy1, float dx2,
                                  float dy2) {
  // Strongest band, for the sign of the eigenvector.
  const PixelGradient strongest = StrongestBand(dx0, dy0, dx1, dy1, dx2, dy2);
  const float bx = strongest.gx, by = strongest.gy;
  // D = JᵀJ = [a b; b c]; largest eigenvalue and its eigenvector.
  const float a = dx0 * dx0 + dx1 * dx1 + dx2 * dx2;
  const float bxy = dx0 * dy0 + dx1 * dy1 + dx2 * dy2;
  const float c = dy0 * dy0 + dy1 * dy1 + dy2 * dy2;
  const float half = 0.5f * (a - c);
  const float lambda = 0.5f * (a + c) + std::sqrt(half * half + bxy * bxy);
  // (lambda - c, b) and (b, lambda - a) are both eigenvectors; take the
  // longer one, the other vanishes when D is nearly diagonal.
  const bool wide = a >= c;
  const float ex = wide ? lambda - c : bxy;
  const float ey = wide ? bxy : lambda - a;
  const float en2 = ex * ex + ey * ey;
  const float mag = std::sqrt(lambda);
  // ex = ey = 0 when D = 0, so any positive floor gives the 0 vector there.
  const float scale = mag / std::sqrt(std::max(en2, 1e-30f));
  const float sign = ex * bx + ey * by < 0 ? -scale : scale;
  return {mag, ex * sign, ey * sign, 0};
}

// Rows y-1, y, y+1 of the bands.
struct BandRows {
  const float* u[3];
  const float* c[3];
  const float* d[3];
};

BandRows RowsAt(const std::vector<cv::Mat>& planes, int y) {
  BandRows r{};
  for (size_t b = 0; b < planes.size(); ++b) {
    r.u[b] = planes[b].ptr<float>(y - 1);
    r.c[b] = planes[b].ptr<float>(y);
    r.d[b] = planes[b].ptr<float>(y + 1);
  }
  return r;
}

// Per-row kernels on raw, non-aliasing pointers: that (and -fno-math-errno
// for sqrt, see CMakeLists.txt) lets GCC vectorise them.
RS_VECTOR_CLONES void GreyRow(const float* __restrict up, const float* __restrict mid,
                              const float* __restrict down, float* __restrict m,
                              float* __restrict gx, float* __restrict gy, int w) {
  for (int x = 1; x < w - 1; ++x) {
    const PixelGradient p = GreyPixel(0.5f * (mid[x + 1] - mid[x - 1]), 0.5f * (down[x] - up[x]));
    m[x] = p.m;
    gx[x] = p.gx;
    gy[x] = p.gy;
  }
}

template <PixelGradient (*Fuse)(float, float, float, float, float, float)>
RS_VECTOR_CLONES void ColourRow(const float* __restrict u0, const float* __restrict c0,
                                const float* __restrict d0, const float* __restrict u1,
                                const float* __restrict c1, const float* __restrict d1,
                                const float* __restrict u2, const float* __restrict c2,
                                const float* __restrict d2, float* __restrict m,
                                float* __restrict gx, float* __restrict gy, int w) {
  for (int x = 1; x < w - 1; ++x) {
    const PixelGradient p =
        Fuse(0.5f * (c0[x + 1] - c0[x - 1]), 0.5f * (d0[x] - u0[x]), 0.5f * (c1[x + 1] - c1[x - 1]),
             0.5f * (d1[x] - u1[x]), 0.5f * (c2[x + 1] - c2[x - 1]), 0.5f * (d2[x] - u2[x]));
    m[x] = p.m;
    gx[x] = p.gx;
    gy[x] = p.gy;
  }
}

RS_VECTOR_CLONES void HorizontalRow(const float* __restrict gx, const float* __restrict gy,
                                    std::uint8_t* __restrict out, int w) {
  for (int x = 1; x < w - 1; ++x) out[x] = std::fabs(gx[x]) >= std::fabs(gy[x]);
}

template <PixelGradient (*Fuse)(float, float, float, float, float, float), typename Out>
void ColourPixels(const BandRows& r, const int* xs, int n, Out out) {
  for (int i = 0; i < n; ++i) {
    const int x = xs[i];
    out(i, Fuse(0.5f * (r.c[0][x + 1] - r.c[0][x - 1]), 0.5f * (r.d[0][x] - r.u[0][x]),
                0.5f * (r.c[1][x + 1] - r.c[1][x - 1]), 0.5f * (r.d[1][x] - r.u[1][x]),
                0.5f * (r.c[2][x + 1] - r.c[2][x - 1]), 0.5f * (r.d[2][x] - r.u[2][x])));
  }
}

// The pixel gradients at columns xs of row y, handed to out(i, gradient).
template <typename Out>
void PixelsOfRow(const GradientField& g, int y, const int* xs, int n, Out out) {
  const BandRows r = RowsAt(g.smoothed, y);
  if (g.smoothed.size() == 1) {
    for (int i = 0; i < n; ++i) {
      const int x = xs[i];
      out(i, GreyPixel(0.5f * (r.c[0][x + 1] - r.c[0][x - 1]), 0.5f * (r.d[0][x] - r.u[0][x])));
    }
  } else if (g.method == GradientMethod::kDiZenzo) {
    ColourPixels<DiZenzoPixel>(r, xs, n, out);
  } else {
    ColourPixels<MaxPixel>(r, xs, n, out);
  }
}

}  // namespace

std::vector<cv::Mat> GradientPlanes(const cv::Mat& image, GradientMethod method) {
  std::vector<cv::Mat> planes;
  if (image.channels() == 1) {
    planes.push_back(image.clone());
  } else if (method == GradientMethod::kGrey) {
    cv::Mat grey;
    cv::cvtColor(image, grey, cv::COLOR_RGB2GRAY);
    planes.push_back(grey);
  } else {
    cv::split(image, planes);
  }
  return planes;
}

EdgeBand CarryingBand(const GradientField& g, int x, int y) { return GradientAt(g, x, y).band; }

void GradientAtColumns(const GradientField& g, int y, const int* xs, int n, GradientVector* out) {
  const EdgeBand fixed = g.smoothed.size() == 1                 ? EdgeBand::kGrey
                         : g.method == GradientMethod::kDiZenzo ? EdgeBand::kFused
                                                                : EdgeBand::kRed;
  const bool per_band = fixed == EdgeBand::kRed;
  PixelsOfRow(g, y, xs, n, [&](int i, const PixelGradient& p) {
    out[i] = {p.gx, p.gy, per_band ? static_cast<EdgeBand>(p.band) : fixed};
  });
}

GradientVector GradientAt(const GradientField& g, int x, int y) {
  GradientVector v;
  GradientAtColumns(g, y, &x, 1, &v);
  return v;
}

void GradientRow(const GradientField& g, int y, float* m, float* gx, float* gy) {
  const std::vector<cv::Mat>& planes = g.smoothed;
  const int w = planes[0].cols;
  // Scratch for the magnitude when the caller does not want it.
  thread_local std::vector<float> scratch;
  if (m == nullptr) {
    if (scratch.size() < static_cast<size_t>(w)) scratch.resize(w);
    m = scratch.data();
  }
  const BandRows r = RowsAt(planes, y);
  if (planes.size() == 1) {
    GreyRow(r.u[0], r.c[0], r.d[0], m, gx, gy, w);
  } else if (g.method == GradientMethod::kDiZenzo) {
    ColourRow<DiZenzoPixel>(r.u[0], r.c[0], r.d[0], r.u[1], r.c[1], r.d[1], r.u[2], r.c[2], r.d[2],
                            m, gx, gy, w);
  } else {
    ColourRow<MaxPixel>(r.u[0], r.c[0], r.d[0], r.u[1], r.c[1], r.d[1], r.u[2], r.c[2], r.d[2], m,
                        gx, gy, w);
  }
}

GradientField ComputeGradient(std::vector<cv::Mat> planes, GradientMethod method, double sigma) {
  if (planes.empty() || (planes.size() != 1 && planes.size() != 3) ||
      planes[0].type() != CV_32FC1 || (planes.size() == 3 && method == GradientMethod::kGrey)) {
    throw Error("ComputeGradient: expected 1 or 3 CV_32F planes (1 for the grey method)");
  }
  const int w = planes[0].cols;
  const int h = planes[0].rows;
  for (cv::Mat& p : planes) SmoothInPlace(p, sigma);

  GradientField g;
  g.method = planes.size() == 1 ? GradientMethod::kGrey : method;
  g.smoothed = std::move(planes);
  // Not zero-initialised: the rows below write every interior pixel, and
  // only the border needs zeros.
  g.magnitude.create(h, w, CV_32F);
  g.magnitude.row(0).setTo(0);
  g.magnitude.row(h - 1).setTo(0);
  g.magnitude.col(0).setTo(0);
  g.magnitude.col(w - 1).setTo(0);
  g.horizontal.create(h, w, CV_8U);
  g.horizontal.row(0).setTo(0);
  g.horizontal.row(h - 1).setTo(0);
  g.horizontal.col(0).setTo(0);
  g.horizontal.col(w - 1).setTo(0);
  if (w < 3 || h < 3) {
    g.magnitude.setTo(0);
    g.horizontal.setTo(0);
    return g;
  }
  cv::parallel_for_(cv::Range(1, h - 1), [&](const cv::Range& rows) {
    std::vector<float> gx(w), gy(w);
    for (int y = rows.start; y < rows.end; ++y) {
      GradientRow(g, y, g.magnitude.ptr<float>(y), gx.data(), gy.data());
      HorizontalRow(gx.data(), gy.data(), g.horizontal.ptr<std::uint8_t>(y), w);
    }
  });
  return g;
}

}  // namespace roofsweep
