#include "algorithms/matching/robust_estimate.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>

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

// Regularised so that flat colour regions (all pixels equal after
// quantisation) still have an invertible scatter.
void Regularise(Eigen::Matrix2d* cov) { *cov += Eigen::Matrix2d::Identity() * 1e-4; }

}  // namespace

// Distances in no order cost std::nth_element a mispredicted branch per
// element and round, and it ran in every C-step: two thirds of the
// estimator's time.
double SelectKth(std::vector<double>* values, std::vector<double>* buffer, int k) {
  double* src = values->data();
  double* dst = buffer->data();
  int n = static_cast<int>(values->size());
  while (n > 16) {
    double a = src[0], b = src[n / 2], c = src[n - 1];
    if (a > b) std::swap(a, b);
    if (b > c) std::swap(b, c);
    if (a > b) std::swap(a, b);
    const double pivot = b;  // median of three
    // Smaller values fill dst from the front, larger ones from the back;
    // every value is written to both ends and only the right one kept.
    int less = 0, greater = 0;
    for (int i = 0; i < n; ++i) {
      const double x = src[i];
      dst[less] = x;
      dst[n - 1 - greater] = x;
      less += x < pivot;
      greater += x > pivot;
    }
    if (k < less) {
      std::swap(src, dst);
      n = less;
    } else if (k >= n - greater) {
      k -= n - greater;
      double* part = dst + (n - greater);
      dst = src;
      src = part;
      n = greater;
    } else {
      return pivot;
    }
  }
  std::nth_element(src, src + k, src + n);
  return src[k];
}

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

namespace {

// Mean and scatter of the points whose index `take` marks, in index order
// (a fixed summation order: the result does not depend on how the subset
// was found).
MeanCov EstimateMarked(const std::vector<Eigen::Vector2d>& pts, const std::vector<char>& take) {
  // Weights of 0 or 1 instead of a branch: about half the points are
  // marked, in no pattern a branch predictor could learn, and adding an
  // exact zero leaves every sum as it was.
  const int n = static_cast<int>(pts.size());
  double mx = 0, my = 0;
  int m = 0;
  for (int i = 0; i < n; ++i) {
    const double w = take[i];
    mx += w * pts[i].x();
    my += w * pts[i].y();
    m += take[i];
  }
  MeanCov r{Eigen::Vector2d::Zero(), Eigen::Matrix2d::Zero()};
  r.mean << mx, my;
  r.mean /= static_cast<double>(m);
  double sxx = 0, sxy = 0, syy = 0;
  for (int i = 0; i < n; ++i) {
    const double w = take[i];
    const double dx = pts[i].x() - r.mean.x(), dy = pts[i].y() - r.mean.y();
    sxx += w * (dx * dx);
    sxy += w * (dx * dy);
    syy += w * (dy * dy);
  }
  const double f = 1.0 / std::max(1.0, static_cast<double>(m) - 1.0);
  r.cov << sxx * f, sxy * f, sxy * f, syy * f;
  return r;
}

// Squared Mahalanobis distances under `mc` (2x2 inverse written out: this
// is the inner loop of every C-step).
void Distances(const std::vector<Eigen::Vector2d>& pts, const MeanCov& mc,
               std::vector<double>* d2) {
  const double det = mc.cov(0, 0) * mc.cov(1, 1) - mc.cov(0, 1) * mc.cov(1, 0);
  const double a = mc.cov(1, 1) / det, b = -mc.cov(0, 1) / det, c = mc.cov(0, 0) / det;
  const int n = static_cast<int>(pts.size());
  for (int i = 0; i < n; ++i) {
    const double dx = pts[i].x() - mc.mean.x(), dy = pts[i].y() - mc.mean.y();
    (*d2)[i] = a * dx * dx + 2 * b * dx * dy + c * dy * dy;
  }
}

// Marks the h points of smallest distance, ties going to the lower index.
void MarkSmallest(const std::vector<double>& d2, int h, std::vector<double>* scratch,
                  std::vector<double>* buffer, std::vector<char>* take) {
  *scratch = d2;
  buffer->resize(d2.size());
  const double t = SelectKth(scratch, buffer, h - 1);
  const int n = static_cast<int>(d2.size());
  int m = 0;
  for (int i = 0; i < n; ++i) {
    (*take)[i] = d2[i] < t;
    m += (*take)[i];
  }
  for (int i = 0; i < n && m < h; ++i)
    if (d2[i] == t) {
      (*take)[i] = 1;
      ++m;
    }
}

// Starts refined to convergence after their first two C-steps.
constexpr size_t kConverged = 2;

// splitmix64: the starts only need a cheap, well-mixed, seeded choice
// (std::mt19937's 2.5 kB state cost more to seed than a C-step).
uint64_t SplitMix(uint64_t* state) {
  uint64_t z = (*state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

}  // namespace

Robust2D RobustMcd2D(const std::vector<Eigen::Vector2d>& pts, unsigned seed, int starts) {
  Robust2D out;
  const int n = static_cast<int>(pts.size());
  if (n < 5) return out;
  const int h = (n + 3) / 2;  // (n + p + 1) / 2 with p = 2
  uint64_t rng = seed;
  std::vector<double> d2(n), scratch, buffer;
  std::vector<char> take(n);
  double best_det = 1e300;
  MeanCov best{};

  // C-steps from `mc`, at most `steps`; the scatter's determinant never
  // increases, and equal determinants mean convergence.
  auto c_steps = [&](MeanCov mc, int steps) {
    double det = 1e300;
    for (int it = 0; it < steps; ++it) {
      Regularise(&mc.cov);
      Distances(pts, mc, &d2);
      MarkSmallest(d2, h, &scratch, &buffer, &take);
      const MeanCov next = EstimateMarked(pts, take);
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

  // FAST-MCD's schedule (Rousseeuw & Van Driessen 1999, sec. 3.2): two
  // C-steps from every start, then only the best ones to convergence.
  std::vector<std::pair<double, MeanCov>> started;
  for (int s = 0; s < starts; ++s) {
    std::vector<int> idx;
    while (static_cast<int>(idx.size()) < 3) {
      const int k = static_cast<int>(SplitMix(&rng) % static_cast<uint64_t>(n));
      if (std::find(idx.begin(), idx.end(), k) == idx.end()) idx.push_back(k);
    }
    std::fill(take.begin(), take.end(), 0);
    for (int k : idx) take[k] = 1;
    started.push_back(c_steps(EstimateMarked(pts, take), 2));
  }
  std::stable_sort(started.begin(), started.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  started.resize(std::min<size_t>(started.size(), kConverged));
  for (const auto& start : started) {
    const auto [det, refined] = c_steps(start.second, 20);
    if (det < best_det) {
      best_det = det;
      best = refined;
    }
  }
  // Consistency factor for the raw MCD scatter: median of the squared
  // distances should be the chi2(2) median.
  Regularise(&best.cov);
  Distances(pts, best, &d2);
  {
    scratch = d2;
    std::nth_element(scratch.begin(), scratch.begin() + n / 2, scratch.end());
    const double f = std::max(scratch[n / 2] / kChi2_2_50, 1e-6);
    best.cov *= f;
    for (double& x : d2) x /= f;
  }
  int kept = 0;
  for (int i = 0; i < n; ++i) {
    take[i] = d2[i] <= kChi2_2_975;
    kept += take[i];
  }
  if (kept < 3) return out;
  const MeanCov fin = EstimateMarked(pts, take);
  out.mean = fin.mean;
  // Truncation at 97.5 % of chi2(2) shrinks the scatter by 0.8724... for
  // normal data: E[d2 | d2 < q] / 2 = 1 - q e^{-q/2} / (2 (1 - e^{-q/2})).
  const double q = kChi2_2_975;
  const double shrink = 1 - q * std::exp(-q / 2) / (2 * (1 - std::exp(-q / 2)));
  out.cov = fin.cov / shrink;
  Regularise(&out.cov);
  out.inliers = kept;
  out.valid = true;
  return out;
}

}  // namespace roofsweep
