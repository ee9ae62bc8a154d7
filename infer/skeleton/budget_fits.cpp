// Fitting the skeleton grammar's termination models: the tip hazard (logistic regression by
// Newton-Raphson) and the axis length budgets (least squares with BIC subset selection).
#include "infer/skeleton/budget_fits.h"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace ramus::skeleton_infer {

namespace {

// Solves the symmetric positive definite system a x = b (normal equations, a Newton step) by
// Eigen's LDL^T; false when a pivot is not above `min_pivot` or the solution is not finite.
bool solve_normal_equations(const Eigen::MatrixXd& a, const Eigen::VectorXd& b, double min_pivot,
                            Eigen::VectorXd& x) {
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(a);
  if (ldlt.info() != Eigen::Success || !(ldlt.vectorD().cwiseAbs().minCoeff() > min_pivot))
    return false;
  x = ldlt.solve(b);
  return x.allFinite();
}

}  // namespace

TipHazard fit_tip_hazard(const std::vector<double>& depth, const std::vector<double>& is_tip) {
  std::vector<TipSample> samples(depth.size());
  for (std::size_t k = 0; k < depth.size(); ++k) samples[k] = {depth[k], 0, is_tip[k]};
  return fit_tip_hazard(samples);
}

TipHazard fit_tip_hazard(const std::vector<TipSample>& samples) {
  // Newton-Raphson (IRLS) on the log-likelihood of p(x) = 1 / (1 + exp(-(c . x))) with
  // x = (1, d, log w) and a small ridge penalty, which keeps the fit finite when a feature
  // separates tips perfectly (a grammar whose tips are exactly the internodes below a width, or
  // all at the last step). The features are centred and scaled to unit spread for the fit (the
  // ridge then weighs them alike) and the coefficients mapped back.
  constexpr double kRidge = 1e-3;
  constexpr std::size_t kDim = 4;
  TipHazard h;
  const std::size_t n = samples.size();
  if (n == 0) return h;
  std::array<double, kDim> centre{}, scale{1, 1, 1, 1};
  auto raw = [](const TipSample& s) {
    return std::array<double, kDim>{1, s.depth, s.log_width, s.log_length};
  };
  for (const TipSample& s : samples) {
    const auto x = raw(s);
    for (std::size_t j = 1; j < kDim; ++j) centre[j] += x[j] / double(n);
  }
  for (std::size_t j = 1; j < kDim; ++j) {
    double var = 0;
    for (const TipSample& s : samples) var += std::pow(raw(s)[j] - centre[j], 2) / double(n);
    scale[j] = var > 1e-12 ? std::sqrt(var) : 0;  // a constant feature is left out
  }
  std::vector<std::array<double, kDim>> x(n);
  double tips = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const auto r = raw(samples[k]);
    x[k][0] = 1;
    for (std::size_t j = 1; j < kDim; ++j)
      x[k][j] = scale[j] > 0 ? (r[j] - centre[j]) / scale[j] : 0;
    tips += samples[k].tip;
  }
  const double mean = std::clamp(tips / double(n), 1e-6, 1 - 1e-6);
  Eigen::Vector4d c(std::log(mean / (1 - mean)), 0, 0, 0);
  for (int it = 0; it < 200; ++it) {
    Eigen::Matrix4d hessian = kRidge * Eigen::Matrix4d::Identity();
    Eigen::Vector4d gradient = -kRidge * c;
    for (std::size_t k = 0; k < n; ++k) {
      const Eigen::Map<const Eigen::Vector4d> xk(x[k].data());
      const double p = 1 / (1 + std::exp(-std::clamp(c.dot(xk), -40.0, 40.0)));
      gradient += (samples[k].tip - p) * xk;
      hessian += p * (1 - p) * xk * xk.transpose();
    }
    Eigen::VectorXd step;
    if (!solve_normal_equations(hessian, gradient, 1e-300, step)) break;
    c += step;
    if (!(step.cwiseAbs().sum() >= 1e-10)) break;
  }
  h.beta = scale[1] > 0 ? c[1] / scale[1] : 0;
  h.gamma = scale[2] > 0 ? c[2] / scale[2] : 0;
  h.delta = scale[3] > 0 ? c[3] / scale[3] : 0;
  h.alpha = c[0] - h.beta * centre[1] - h.gamma * centre[2] - h.delta * centre[3];
  for (std::size_t k = 0; k < n; ++k) {
    const double z = c.dot(Eigen::Map<const Eigen::Vector4d>(x[k].data()));
    const double p = std::clamp(1 / (1 + std::exp(-std::clamp(z, -40.0, 40.0))), 1e-12, 1 - 1e-12);
    h.log_likelihood += samples[k].tip > 0.5 ? std::log(p) : std::log(1 - p);
  }
  return h;
}

AxisBudget fit_axis_budget(const std::vector<BudgetSample>& samples) {
  // Least squares on the centred features for every subset of {log l, log w, d}; the subset of
  // largest BIC, -n ln(RSS / n) - p ln n with p = the terms, the intercept and the spread.
  AxisBudget best;
  const std::size_t n = samples.size();
  best.samples = n;
  if (n == 0) return best;
  constexpr std::size_t kDim = 3;
  auto raw = [](const BudgetSample& s) {
    return std::array<double, kDim>{s.log_length, s.log_width, s.depth};
  };
  std::array<double, kDim> centre{};
  double ymean = 0;
  best.lo = best.hi = samples[0].log_axis;
  for (const BudgetSample& s : samples) {
    for (std::size_t j = 0; j < kDim; ++j) centre[j] += raw(s)[j] / double(n);
    ymean += s.log_axis / double(n);
    best.lo = std::min(best.lo, s.log_axis);
    best.hi = std::max(best.hi, s.log_axis);
  }
  double best_score = -std::numeric_limits<double>::infinity();
  for (unsigned mask = 0; mask < (1u << kDim); ++mask) {
    std::array<std::size_t, kDim> used{};
    std::size_t k = 0;
    for (std::size_t j = 0; j < kDim; ++j)
      if (mask & (1u << j)) used[k++] = j;
    if (n < k + 3) continue;  // too few axes to fit these terms and judge them
    // Normal equations (X^T X + ridge) c = X^T y on centred features.
    Eigen::MatrixXd xtx = Eigen::MatrixXd::Zero(Eigen::Index(k), Eigen::Index(k));
    Eigen::VectorXd xty = Eigen::VectorXd::Zero(Eigen::Index(k));
    for (const BudgetSample& s : samples) {
      const auto x = raw(s);
      for (std::size_t a = 0; a < k; ++a) {
        for (std::size_t b = 0; b < k; ++b)
          xtx(Eigen::Index(a), Eigen::Index(b)) +=
              (x[used[a]] - centre[used[a]]) * (x[used[b]] - centre[used[b]]);
        xty(Eigen::Index(a)) += (x[used[a]] - centre[used[a]]) * (s.log_axis - ymean);
      }
    }
    xtx.diagonal() += 1e-9 * (Eigen::VectorXd::Ones(Eigen::Index(k)) + xtx.diagonal());
    Eigen::VectorXd solution;
    // A singular system (a constant feature): the subset without it is tried too.
    if (k > 0 && !solve_normal_equations(xtx, xty, 1e-12, solution)) continue;
    std::array<double, kDim> c{};
    for (std::size_t a = 0; a < k; ++a) c[used[a]] = solution(Eigen::Index(a));
    double rss = 0;
    for (const BudgetSample& s : samples) {
      const auto x = raw(s);
      double e = s.log_axis - ymean;
      for (std::size_t j = 0; j < kDim; ++j) e -= c[j] * (x[j] - centre[j]);
      rss += e * e;
    }
    const double score = -double(n) * std::log(std::max(rss / double(n), 1e-12)) -
                         double(k + 2) * std::log(double(n));
    if (score > best_score) {
      best_score = score;
      best.cl = c[0], best.cw = c[1], best.cd = c[2];
      best.c0 = ymean - c[0] * centre[0] - c[1] * centre[1] - c[2] * centre[2];
      best.sd = std::sqrt(rss / double(std::max<std::size_t>(n - k - 1, 1)));
    }
  }
  if (best_score == -std::numeric_limits<double>::infinity()) best.c0 = ymean;  // n < 3
  return best;
}

LateralBudget fit_lateral_budget(const std::vector<BudgetSample>& samples) {
  std::vector<BudgetSample> single, branching;
  for (const BudgetSample& s : samples) (s.single ? single : branching).push_back(s);
  LateralBudget b;
  if (samples.empty()) return b;
  b.p_single = double(single.size()) / double(samples.size());
  if (!branching.empty()) b.branching = fit_axis_budget(branching);
  if (!single.empty()) b.single = fit_axis_budget(single);
  return b;
}

}  // namespace ramus::skeleton_infer
