// A mixture of two one-dimensional Gaussians fitted by expectation-maximization (Dempster, Laird
// & Rubin, "Maximum likelihood from incomplete data via the EM algorithm", J. R. Stat. Soc. B 39
// (1977)); the unsupervised threshold of the wood/leaf separation, as in Vicari et al. 2019
// (Methods Ecol. Evol. 10), who classify leaf and wood with Gaussian mixtures over geometric
// features.
//
// For samples x_i and components k = 0, 1 with weight w_k, mean m_k and variance v_k:
//   E-step:  g_ik = w_k N(x_i; m_k, v_k) / sum_j w_j N(x_i; m_j, v_j)
//   M-step:  w_k = sum_i g_ik / n,  m_k = sum_i g_ik x_i / sum_i g_ik,
//            v_k = sum_i g_ik (x_i - m_k)^2 / sum_i g_ik
// iterated until the mean log-likelihood gains less than `tolerance`. Component 0 is the one
// with the lower mean.
#pragma once

#include <vector>

namespace ramus::wood {

struct Mixture2 {
  double weight[2] = {0.5, 0.5}, mean[2] = {0, 0}, variance[2] = {1, 1};
  double log_likelihood = 0;  // mean per sample
  int iterations = 0;

  // Posterior probability of component 1 at x.
  double posterior_high(double x) const;
  // Ashman's D = sqrt(2) |m_1 - m_0| / sqrt(v_0 + v_1): above 2 the components are clearly
  // separated (Ashman, Bird & Zepf, Astron. J. 108 (1994)).
  double separation() const;
};

// Fits the mixture to `x` (at least two distinct values; otherwise both components sit at the
// mean). Deterministic: starts from the lower and upper quartiles.
Mixture2 fit_mixture2(const std::vector<double>& x, int max_iterations = 200,
                      double tolerance = 1e-9);

}  // namespace ramus::wood
