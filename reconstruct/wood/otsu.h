// Otsu's threshold (Otsu, "A threshold selection method from gray-level histograms", IEEE Trans.
// Syst. Man Cybern. 9 (1979)): over a histogram of the values, the cut t that maximizes the
// between-class variance
//   sigma_B^2(t) = w_0(t) w_1(t) (mu_0(t) - mu_1(t))^2      (Otsu 1979, Eq. 18)
// where w_k are the class weights and mu_k the class means below and above t. The separability
// eta = sigma_B^2 / sigma_T^2 (Eq. 12, in [0, 1]) says how well two classes explain the spread.
#pragma once

#include <vector>

namespace ramus::wood {

struct OtsuThreshold {
  double threshold = 0;       // values above are the upper class
  double separability = 0;    // eta
  double upper_fraction = 0;  // share of the values above the threshold
};

// Over `bins` equal bins between the minimum and the maximum of `x`. A constant `x` gives
// separability 0 and a threshold at its value.
OtsuThreshold otsu_threshold(const std::vector<double>& x, int bins = 256);

}  // namespace ramus::wood
