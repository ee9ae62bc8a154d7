#include "reconstruct/wood/mixture.h"

#include <algorithm>
#include <cmath>

namespace ramus::wood {

namespace {

constexpr double kTwoPi = 6.283185307179586;

double log_normal(double x, double m, double v) {
  return -0.5 * (std::log(kTwoPi * v) + (x - m) * (x - m) / v);
}

}  // namespace

double Mixture2::posterior_high(double x) const {
  const double a = std::log(weight[0]) + log_normal(x, mean[0], variance[0]);
  const double b = std::log(weight[1]) + log_normal(x, mean[1], variance[1]);
  return 1.0 / (1.0 + std::exp(a - b));
}

double Mixture2::separation() const {
  return std::sqrt(2.0) * std::abs(mean[1] - mean[0]) / std::sqrt(variance[0] + variance[1]);
}

Mixture2 fit_mixture2(const std::vector<double>& x, int max_iterations, double tolerance) {
  Mixture2 m;
  const std::size_t n = x.size();
  if (n == 0) return m;
  std::vector<double> sorted = x;
  std::sort(sorted.begin(), sorted.end());
  double total = 0;
  for (double v : x) total += v;
  const double mean = total / double(n);
  double var = 0;
  for (double v : x) var += (v - mean) * (v - mean);
  var /= double(n);
  // A floor under the variances keeps a component from collapsing onto repeated values.
  const double floor = std::max(var * 1e-6, 1e-12);
  if (!(var > floor) || sorted.front() == sorted.back()) {
    m.mean[0] = m.mean[1] = mean;
    m.variance[0] = m.variance[1] = std::max(var, floor);
    return m;
  }
  m.mean[0] = sorted[n / 4];
  m.mean[1] = sorted[(3 * n) / 4];
  if (m.mean[1] <= m.mean[0]) m.mean[0] = sorted.front(), m.mean[1] = sorted.back();
  m.variance[0] = m.variance[1] = var / 4;
  double previous = -INFINITY;
  std::vector<double> g(n);
  for (int it = 0; it < max_iterations; ++it) {
    // E-step, with the log-likelihood of the current parameters.
    double ll = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double a = std::log(m.weight[0]) + log_normal(x[i], m.mean[0], m.variance[0]);
      const double b = std::log(m.weight[1]) + log_normal(x[i], m.mean[1], m.variance[1]);
      const double hi = std::max(a, b);
      const double lse = hi + std::log(std::exp(a - hi) + std::exp(b - hi));
      g[i] = std::exp(b - lse);
      ll += lse;
    }
    ll /= double(n);
    m.log_likelihood = ll;
    m.iterations = it + 1;
    if (ll - previous < tolerance) break;
    previous = ll;
    // M-step.
    double s1 = 0, sx1 = 0, sx0 = 0;
    for (std::size_t i = 0; i < n; ++i) {
      s1 += g[i];
      sx1 += g[i] * x[i];
      sx0 += (1 - g[i]) * x[i];
    }
    const double s0 = double(n) - s1;
    if (s0 < 1e-9 || s1 < 1e-9) break;  // one component took every sample
    m.weight[0] = s0 / double(n), m.weight[1] = s1 / double(n);
    m.mean[0] = sx0 / s0, m.mean[1] = sx1 / s1;
    double v0 = 0, v1 = 0;
    for (std::size_t i = 0; i < n; ++i) {
      v0 += (1 - g[i]) * (x[i] - m.mean[0]) * (x[i] - m.mean[0]);
      v1 += g[i] * (x[i] - m.mean[1]) * (x[i] - m.mean[1]);
    }
    m.variance[0] = std::max(v0 / s0, floor), m.variance[1] = std::max(v1 / s1, floor);
  }
  if (m.mean[0] > m.mean[1]) {
    std::swap(m.weight[0], m.weight[1]);
    std::swap(m.mean[0], m.mean[1]);
    std::swap(m.variance[0], m.variance[1]);
  }
  return m;
}

}  // namespace ramus::wood
