#include "algorithms/matching/robust_estimate.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

namespace roofsweep {
namespace {

// chi2(1) quantile 0.5 = 0.4549; consistency factor of the raw MCD scatter
// with h ~ n/2 for normal data: 1 / (P(chi2_3 <= q) / 0.5) with q = chi2_1(0.5).
constexpr double kChi2_1_975 = 5.0239;
constexpr double kChi2_2_975 = 7.3778;
constexpr double kChi2_2_50 = 1.3863;

struct MeanCov {
  Eigen::Vector2d mean;
  Eigen::Matrix2d cov;
};

MeanCov Estimate(const std::vector<Eigen::Vector2d>& pts, const std::vector<int>& idx) {
  MeanCov r{Eigen::Vector2d::Zero(), Eigen::Matrix2d::Zero()};
  for (int i : idx) r.mean += pts[i];
  r.mean /= static_cast<double>(idx.size());
  for (int i : idx) {
    const Eigen::Vector2d d = pts[i] - r.mean;
    r.cov += d * d.transpose();
  }
  r.cov /= std::max<double>(1.0, static_cast<double>(idx.size()) - 1.0);
  return r;
}

// Regularised so that flat colour regions (all pixels equal after
// quantisation) still have an invertible scatter.
void Regularise(Eigen::Matrix2d* cov) { *cov += Eigen::Matrix2d::Identity() * 1e-4; }

}  // namespace

Robust1D RobustMcd1D(std::vector<double> v) {
  Robust1D r;
  const int n = static_cast<int>(v.size());
  if (n == 0) return r;
  std::sort(v.begin(), v.end());
  if (n < 4) {
    r.location = v[n / 2];
    r.scale = n > 1 ? (v.back() - v.front()) / 2 : 0;
    r.used = n;
    return r;
  }
  const int h = n / 2 + 1;
  // Sliding window over the sorted values: the contiguous h-subset of least
  // variance is the exact univariate MCD.
  std::vector<double> prefix(n + 1, 0.0), prefix2(n + 1, 0.0);
  for (int i = 0; i < n; ++i) {
    prefix[i + 1] = prefix[i] + v[i];
    prefix2[i + 1] = prefix2[i] + v[i] * v[i];
  }
  double best = 1e300;
  int best_i = 0;
  for (int i = 0; i + h <= n; ++i) {
    const double s = prefix[i + h] - prefix[i];
    const double s2 = prefix2[i + h] - prefix2[i];
    const double var = s2 / h - (s / h) * (s / h);
    if (var < best) {
      best = var;
      best_i = i;
    }
  }
  const double mean = (prefix[best_i + h] - prefix[best_i]) / h;
  // Consistency: the variance of the central half of a normal is 0.1426 sigma².
  double sigma = std::sqrt(std::max(best, 0.0) / 0.1426);
  sigma = std::max(sigma, 1e-6);
  // Reweighting step.
  double s = 0, s2 = 0;
  int m = 0;
  for (double x : v) {
    if ((x - mean) * (x - mean) <= kChi2_1_975 * sigma * sigma) {
      s += x;
      s2 += x * x;
      ++m;
    }
  }
  r.location = s / m;
  const double var = m > 1 ? (s2 - s * s / m) / (m - 1) : 0.0;
  // Truncation at 97.5 % shrinks the variance by 0.8551 for normal data.
  r.scale = std::sqrt(std::max(var, 0.0) / 0.8551);
  r.scale = std::max(r.scale, 1e-6);
  r.used = m;
  return r;
}

Robust2D RobustMcd2D(const std::vector<Eigen::Vector2d>& pts, unsigned seed, int starts) {
  Robust2D out;
  const int n = static_cast<int>(pts.size());
  if (n < 5) return out;
  const int h = (n + 3) / 2;  // (n + p + 1) / 2 with p = 2
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> pick(0, n - 1);
  std::vector<double> d2(n);
  std::vector<int> order(n);
  double best_det = 1e300;
  MeanCov best{};

  auto c_steps = [&](MeanCov mc) {
    double det = 1e300;
    for (int it = 0; it < 20; ++it) {
      Regularise(&mc.cov);
      const Eigen::Matrix2d inv = mc.cov.inverse();
      for (int i = 0; i < n; ++i) {
        const Eigen::Vector2d d = pts[i] - mc.mean;
        d2[i] = d.dot(inv * d);
      }
      std::iota(order.begin(), order.end(), 0);
      std::nth_element(order.begin(), order.begin() + h, order.end(),
                       [&](int a, int b) { return d2[a] < d2[b] || (d2[a] == d2[b] && a < b); });
      order.resize(h);
      MeanCov next = Estimate(pts, order);
      order.resize(n);
      const double nd = next.cov.determinant();
      mc = next;
      if (nd >= det * (1 - 1e-9)) {
        det = nd;
        break;
      }
      det = nd;
    }
    return std::make_pair(det, mc);
  };

  for (int s = 0; s < starts; ++s) {
    std::vector<int> idx;
    while (static_cast<int>(idx.size()) < 3) {
      const int k = pick(rng);
      if (std::find(idx.begin(), idx.end(), k) == idx.end()) idx.push_back(k);
    }
    MeanCov mc = Estimate(pts, idx);
    const auto [det, refined] = c_steps(mc);
    if (det < best_det) {
      best_det = det;
      best = refined;
    }
  }
  // Consistency factor for the raw MCD scatter: median of the squared
  // distances should be the chi2(2) median.
  Regularise(&best.cov);
  {
    const Eigen::Matrix2d inv = best.cov.inverse();
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector2d d = pts[i] - best.mean;
      d2[i] = d.dot(inv * d);
    }
    std::vector<double> tmp = d2;
    std::nth_element(tmp.begin(), tmp.begin() + n / 2, tmp.end());
    const double f = std::max(tmp[n / 2] / kChi2_2_50, 1e-6);
    best.cov *= f;
    for (double& x : d2) x /= f;
  }
  std::vector<int> keep;
  for (int i = 0; i < n; ++i)
    if (d2[i] <= kChi2_2_975) keep.push_back(i);
  if (keep.size() < 3) return out;
  const MeanCov fin = Estimate(pts, keep);
  out.mean = fin.mean;
  // Truncation at 97.5 % of chi2(2) shrinks the scatter by 0.8724... for
  // normal data: E[d2 | d2 < q] / 2 = 1 - q e^{-q/2} / (2 (1 - e^{-q/2})).
  const double q = kChi2_2_975;
  const double shrink = 1 - q * std::exp(-q / 2) / (2 * (1 - std::exp(-q / 2)));
  out.cov = fin.cov / shrink;
  Regularise(&out.cov);
  out.inliers = static_cast<int>(keep.size());
  out.valid = true;
  return out;
}

}  // namespace roofsweep
