#include "algorithms/matching/residual_test.h"

#include <algorithm>
#include <boost/math/distributions/chi_squared.hpp>

namespace roofsweep {
namespace {

int Dof(int observations) { return 2 * observations - 4; }

}  // namespace

ResidualNoise EstimateResidualNoise(const std::vector<LineFitResidual>& fits, int min_lines) {
  ResidualNoise out;
  std::vector<double> s2;
  for (const LineFitResidual& f : fits) {
    const int k = Dof(f.observations);
    if (k <= 0 || !(f.rms_px >= 0)) continue;
    const double normalised = 2.0 * f.observations * f.rms_px * f.rms_px / k;
    s2.push_back(normalised /
                 (boost::math::median(boost::math::chi_squared_distribution<double>(k)) / k));
  }
  out.lines = static_cast<int>(s2.size());
  if (out.lines < std::max(1, min_lines)) return out;
  std::nth_element(s2.begin(), s2.begin() + s2.size() / 2, s2.end());
  out.sigma_px = std::sqrt(s2[s2.size() / 2]);
  return out;
}

bool ResidualConsistent(const LineFitResidual& fit, double sigma_px, double alpha) {
  const int k = Dof(fit.observations);
  if (k <= 0 || !(sigma_px > 0) || !(alpha > 0)) return true;
  const double limit = sigma_px * sigma_px *
                       boost::math::quantile(boost::math::complement(
                           boost::math::chi_squared_distribution<double>(k), alpha));
  return 2.0 * fit.observations * fit.rms_px * fit.rms_px <= limit;
}

}  // namespace roofsweep
