#pragma once

#include <vector>

#include "algorithms/matching/view_features.h"

namespace roofsweep {

// Likelihood-ratio statistics of Scholze et al. (2000), §3.3, for two
// flanking regions. n is the smaller pixel count, capped at `max_n` (see
// MatchOptions::max_test_pixels). Both are made symmetric in the two
// regions (the paper takes S from the first view): the mean test uses the
// pooled covariance, the covariance test averages both directions.
// eq. (5): t = n (x - x')ᵀ S⁻¹ (x - x'), chi2 with 2 dof under H0.
double MeanStatistic(const SideColour& a, const SideColour& b, int max_n);
// eq. (6): t = n tr(U) - n ln|U| - n p, U = S'⁻¹ S, chi2 with 3 dof.
double CovStatistic(const SideColour& a, const SideColour& b, int max_n);

struct ChromaticThresholds {
  double mean = 0, cov = 0;
  int samples = 0;  // statistics the medians were taken over
};

// Automatic initialisation (§3.3): the statistics of all side pairs of
// ~10 random segments and their geometric candidates, those significant at
// 0.001 dropped (obviously wrong), the median of the rest times `factor`.
// `pairs` are (mean, cov) statistics of such side pairs.
ChromaticThresholds InitThresholds(const std::vector<std::pair<double, double>>& pairs,
                                   double factor);

// True when the side pair passes both tests.
inline bool SidesCompatible(const SideColour& a, const SideColour& b, const ChromaticThresholds& t,
                            int max_n) {
  return a.valid && b.valid && MeanStatistic(a, b, max_n) <= t.mean &&
         CovStatistic(a, b, max_n) <= t.cov;
}

}  // namespace roofsweep
