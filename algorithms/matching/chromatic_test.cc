#include "algorithms/matching/chromatic_test.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace roofsweep {
namespace {
constexpr double kChi2_2_999 = 13.816;
constexpr double kChi2_3_999 = 16.266;

double Median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

double OneWay(const Eigen::Matrix2d& s, const Eigen::Matrix2d& s_other, double n) {
  const Eigen::Matrix2d u = s_other.inverse() * s;
  const double det = u.determinant();
  if (!(det > 0)) return 1e300;
  return n * u.trace() - n * std::log(det) - n * 2.0;
}
}  // namespace

double MeanStatistic(const SideColour& a, const SideColour& b, int max_n) {
  const double n = std::min({a.n, b.n, max_n});
  const Eigen::Matrix2d s = 0.5 * (a.cov + b.cov);
  const Eigen::Vector2d d = a.mean - b.mean;
  return n * d.dot(s.inverse() * d);
}

double CovStatistic(const SideColour& a, const SideColour& b, int max_n) {
  const double n = std::min({a.n, b.n, max_n});
  return 0.5 * (OneWay(a.cov, b.cov, n) + OneWay(b.cov, a.cov, n));
}

ChromaticThresholds InitThresholds(const std::vector<std::pair<double, double>>& pairs,
                                   double factor) {
  std::vector<double> m, c;
  for (const auto& [tm, tc] : pairs) {
    m.push_back(tm);
    c.push_back(tc);
  }
  ChromaticThresholds t;
  t.samples = static_cast<int>(pairs.size());
  // Too few samples: the chi2 0.001 quantiles times the factor.
  t.mean = factor * (m.size() >= 5 ? Median(m) : kChi2_2_999);
  t.cov = factor * (c.size() >= 5 ? Median(c) : kChi2_3_999);
  // Never stricter than the conventional 0.1 % level.
  t.mean = std::max(t.mean, kChi2_2_999);
  t.cov = std::max(t.cov, kChi2_3_999);
  return t;
}

}  // namespace roofsweep
