#include "algorithms/matching/colour_balance.h"

#include <tbb/parallel_for.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <mutex>

#include "algorithms/geometry/view.h"

namespace roofsweep {

double SrgbToLinear(double v) {
  v = std::clamp(v, 0.0, 1.0);
  return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

double LinearToSrgb(double v) {
  v = std::clamp(v, 0.0, 1.0);
  return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}

namespace {

// Enough common samples for a stable median.
constexpr size_t kMinSamples = 2000;
// About this many samples per image side (a grid in the first view).
constexpr int kGrid = 256;
// Darker samples (linear G) are mostly noise and shadow.
constexpr double kMinLinear = 0.02;

double GroundHeight(const Block& block) {
  if (block.ground.height) return *block.ground.height;
  if (block.ground.grid) {
    std::vector<float> z;
    for (float v : block.ground.grid->z)
      if (std::isfinite(v)) z.push_back(v);
    if (!z.empty()) {
      std::nth_element(z.begin(), z.begin() + z.size() / 2, z.end());
      return z[z.size() / 2];
    }
  }
  return std::nan("");
}

double Median(std::vector<double>& v) {
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

struct PairChroma {
  int i = -1, j = -1;
  // Median over the common footprint of log(R/G)_i - log(R/G)_j and the same
  // for B: the relative chroma gains of the two views.
  double r = 0, b = 0;
  size_t samples = 0;
  bool valid = false;
};

PairChroma SamplePair(const Block& block, const std::vector<cv::Mat>& images, int i, int j,
                      double z0) {
  PairChroma pc;
  pc.i = i;
  pc.j = j;
  const View& vi = block.views[i];
  const View& vj = block.views[j];
  const Camera& ci = block.CameraOf(vi);
  const Camera& cj = block.CameraOf(vj);
  const cv::Mat& a = images[i];
  const cv::Mat& b = images[j];
  std::vector<double> dr, db;
  const int kStep = std::max(1, std::min(a.rows, a.cols) / kGrid);
  for (int y = kStep / 2; y < a.rows; y += kStep)
    for (int x = kStep / 2; x < a.cols; x += kStep) {
      const Ray ray = BackProject(ci, vi.pose, Eigen::Vector2d(x + 0.5, y + 0.5));
      const auto X = IntersectHorizontalPlane(ray, z0);
      if (!X) continue;
      const auto p = Project(cj, vj.pose, *X);
      if (!p) continue;
      const int u = static_cast<int>(std::floor(p->x())), v = static_cast<int>(std::floor(p->y()));
      if (u < 0 || v < 0 || u >= b.cols || v >= b.rows) continue;
      const cv::Vec3f ca = a.at<cv::Vec3f>(y, x), cb = b.at<cv::Vec3f>(v, u);
      double la[3], lb[3];
      bool ok = true;
      for (int c = 0; c < 3; ++c) {
        la[c] = SrgbToLinear(ca[c]);
        lb[c] = SrgbToLinear(cb[c]);
        ok = ok && la[c] >= kMinLinear && lb[c] >= kMinLinear && ca[c] < 0.99f && cb[c] < 0.99f;
      }
      if (!ok) continue;
      dr.push_back(std::log(la[0] / la[1]) - std::log(lb[0] / lb[1]));
      db.push_back(std::log(la[2] / la[1]) - std::log(lb[2] / lb[1]));
    }
  pc.samples = dr.size();
  if (dr.size() < kMinSamples) return pc;
  pc.r = Median(dr);
  pc.b = Median(db);
  pc.valid = true;
  return pc;
}

}  // namespace

std::vector<ColourCorrection> EstimateColourBalance(const Block& block,
                                                    const std::vector<cv::Mat>& images) {
  const int nv = static_cast<int>(block.views.size());
  std::vector<ColourCorrection> out(nv);
  if (nv < 2 || static_cast<int>(images.size()) != nv) return out;
  for (const cv::Mat& im : images)
    if (im.empty() || im.type() != CV_32FC3) return out;
  const double z0 = GroundHeight(block);
  if (!std::isfinite(z0)) return out;

  std::vector<std::pair<int, int>> pairs;
  for (int i = 0; i < nv; ++i)
    for (int j = i + 1; j < nv; ++j)
      if ((block.views[i].pose.C - block.views[j].pose.C).norm() > 0) pairs.emplace_back(i, j);
  std::vector<PairChroma> pc(pairs.size());
  tbb::parallel_for(size_t{0}, pairs.size(), [&](size_t k) {
    pc[k] = SamplePair(block, images, pairs[k].first, pairs[k].second, z0);
  });
  // Log chroma gains x_v (R/G, then B/G) with x_i - x_j = measured, weighted
  // by the samples, their sum zero (gauge), a weak prior towards zero
  // keeping views without overlap unchanged.
  int rows = 0;
  for (const PairChroma& p : pc) rows += p.valid;
  if (rows == 0) return out;
  for (int ch = 0; ch < 2; ++ch) {
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(rows + nv + 1, nv);
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(A.rows());
    int r = 0;
    for (const PairChroma& p : pc) {
      if (!p.valid) continue;
      const double w = std::sqrt(static_cast<double>(p.samples));
      A(r, p.i) = w;
      A(r, p.j) = -w;
      rhs(r) = w * (ch == 0 ? p.r : p.b);
      ++r;
    }
    for (int v = 0; v < nv; ++v, ++r) A(r, v) = 1.0;
    for (int v = 0; v < nv; ++v) A(r, v) = 100.0;
    const Eigen::VectorXd x = A.colPivHouseholderQr().solve(rhs);
    for (int v = 0; v < nv; ++v) {
      // Implausible corrections (> 30 %) are left out rather than applied.
      if (!(std::abs(x(v)) < 0.3)) continue;
      out[v].gain[ch == 0 ? 0 : 2] = std::exp(-x(v));
    }
  }
  return out;
}

// 8-bit sources hold 256 levels; 4096 entries keep float inputs within
// 1e-3.
constexpr int kLut = 4096;

ColourCorrectionTable::ColourCorrectionTable(const ColourCorrection& k) : identity_(k.Identity()) {
  if (identity_) return;
  for (int c = 0; c < 3; ++c) {
    lut_[c].resize(kLut + 1);
    for (int t = 0; t <= kLut; ++t)
      lut_[c][t] = static_cast<float>(
          LinearToSrgb(k.gain[c] * SrgbToLinear(static_cast<double>(t) / kLut) + k.offset[c]));
  }
}

void ColourCorrectionTable::Apply(const cv::Vec3f* in, cv::Vec3f* out, int n) const {
  for (int x = 0; x < n; ++x)
    for (int c = 0; c < 3; ++c) {
      const float v = std::clamp(in[x][c], 0.f, 1.f);
      if (identity_) {
        out[x][c] = v;
        continue;
      }
      const float t = v * kLut;
      const int t0 = std::min(static_cast<int>(t), kLut - 1);
      const float f = t - t0;
      out[x][c] = lut_[c][t0] + f * (lut_[c][t0 + 1] - lut_[c][t0]);
    }
}

cv::Mat ApplyColourCorrection(const cv::Mat& image, const ColourCorrection& k) {
  if (image.type() != CV_32FC3 || k.Identity()) return image;
  const ColourCorrectionTable table(k);
  cv::Mat out(image.size(), CV_32FC3);
  tbb::parallel_for(0, image.rows, [&](int y) {
    table.Apply(image.ptr<cv::Vec3f>(y), out.ptr<cv::Vec3f>(y), image.cols);
  });
  return out;
}

}  // namespace roofsweep
