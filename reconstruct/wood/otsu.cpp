#include "reconstruct/wood/otsu.h"

#include <algorithm>

namespace ramus::wood {

OtsuThreshold otsu_threshold(const std::vector<double>& x, int bins) {
  OtsuThreshold r;
  if (x.empty()) return r;
  const auto [lo_it, hi_it] = std::minmax_element(x.begin(), x.end());
  const double lo = *lo_it, hi = *hi_it;
  r.threshold = lo;
  if (!(hi > lo) || bins < 2) return r;
  std::vector<double> count(bins, 0.0);
  const double width = (hi - lo) / bins;
  for (double v : x) count[std::min(bins - 1, int((v - lo) / width))] += 1;
  const double n = double(x.size());
  double total_mean = 0;
  for (int b = 0; b < bins; ++b) total_mean += count[b] * (lo + (b + 0.5) * width);
  total_mean /= n;
  double total_var = 0;
  for (int b = 0; b < bins; ++b) {
    const double c = lo + (b + 0.5) * width;
    total_var += count[b] * (c - total_mean) * (c - total_mean);
  }
  total_var /= n;
  double w0 = 0, sum0 = 0, best = -1;
  for (int b = 0; b + 1 < bins; ++b) {
    w0 += count[b] / n;
    sum0 += count[b] / n * (lo + (b + 0.5) * width);
    const double w1 = 1 - w0;
    if (w0 <= 0 || w1 <= 0) continue;
    const double mu0 = sum0 / w0, mu1 = (total_mean - sum0) / w1;
    const double between = w0 * w1 * (mu0 - mu1) * (mu0 - mu1);
    if (between > best) {
      best = between;
      r.threshold = lo + (b + 1) * width;
      r.upper_fraction = w1;
    }
  }
  r.separability = total_var > 0 ? best / total_var : 0;
  return r;
}

}  // namespace ramus::wood
