#include "compiler/infer/skeleton/skeleton_grammar.h"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <optional>

#include "compiler/derive.h"
#include "compiler/grow.h"
#include "compiler/infer/skeleton/fidelity.h"
#include "compiler/pipeline.h"
#include "compiler/turtle.h"
#include "grammar/diagnostic.h"
#include "grammar/format.h"
#include "grammar/parser.h"
#include "grammar/source.h"

namespace ramus::skeleton_infer {

namespace {

// Widths and lengths are logged as log(max(x, kTiny)), as the grammar writes them.
constexpr double kTiny = 1e-9;

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

// What the grammar needs to know about one order group besides its clusters.
struct OrderStats {
  std::size_t internodes = 0, tips = 0;
  std::uint32_t max_axis_index = 0;  // the last internode of every axis is a tip
  std::vector<TipSample> hazard;     // depth, log width, log length and tip of every internode
  std::vector<double> tip_lengths;   // of the order's tips
};

// `clamp(normal(m, s), lo, hi)`, or the mean alone when the spread is nil.
std::string draw(const Fitted& f) {
  if (f.sd < 1e-6 || f.max - f.min < 1e-9) return grammar_number(f.mean);
  return "clamp(normal(" + grammar_number(f.mean) + ", " + grammar_number(f.sd) + "), " +
         grammar_number(f.min) + ", " + grammar_number(f.max) + ")";
}

// A log-normal ratio: exp of the clamped normal of the logarithms, or the constant ratio. A
// length ratio with a slope has its mean depend on the parent's log-length (regression).
std::string draw_ratio(const Fitted& f, const char* parent) {
  if (f.regression()) {
    const std::string mean = grammar_number(f.mean - f.slope * f.centre) + " + " +
                             grammar_number(f.slope) + " * log(max(" + parent + ", 1e-9))";
    return "exp(clamp(normal(" + mean + ", " + grammar_number(std::max(f.sd, 1e-6)) + "), " +
           grammar_number(f.min) + ", " + grammar_number(f.max) + "))";
  }
  if (f.atoms) {
    // Two exact ratios: floor(uniform(0, 1) + p) is 1 with probability p.
    const double r0 = std::exp(f.atom0), r1 = std::exp(f.atom1);
    if (f.atom_p <= 0 || std::abs(r1 - r0) < 1e-9) return grammar_number(r0);
    return "(" + grammar_number(r0) + " + " + grammar_number(r1 - r0) +
           " * floor(uniform(0, 1) + " + grammar_number(f.atom_p) + "))";
  }
  if (f.sd < 1e-6 || f.max - f.min < 1e-9) return grammar_number(std::exp(f.mean));
  return "exp(" + draw(f) + ")";
}

std::string draw_angle(const FittedAngle& f) {
  if (f.uniform) return "uniform(0, 360)";
  if (f.sd < 1e-6) return grammar_number(f.mean);
  return "normal(" + grammar_number(f.mean) + ", " + grammar_number(f.sd) + ")";
}

// The turtle turns of one child: level the frame, roll by phi, pitch down by theta.
std::string turn(const ChildDistribution& c) {
  return "$/(" + draw_angle(c.phi) + ")&(" + draw(c.theta) + ")";
}

// The observed range of internode lengths: a child's length is kept inside it, so that the
// product of many ratios cannot run away from what the tree shows.
struct LengthRange {
  double min = 0, max = 0;
};

// How an internode of length `len` is drawn. A reconstructed internode is a bent chain whose
// chord is shorter than its path (tortuosity tau = chord / path, 0.36 to 0.92 on the bundled
// scans); drawn straight with its path length, a regrown tree spreads up to 3.5 times wider.
// With tau < 1 it is drawn as two halves kinked by +-psi, psi = acos(tau), in a plane of random
// roll: the path length stays `len`, the chord becomes tau * len, and the heading at the end is
// the heading at the start (the pitches cancel; the roll is reset by the `$` of every child).
// Below this kink (tortuosity above cos 10 degrees = 0.985) an internode is drawn straight:
// the chord changes by under 1.5 percent, and the straight form keeps the grammar plain.
constexpr double kMinKink = 10;

// The axiom may not draw random numbers: it kinks in the plane of roll 0.
std::string segment(double kink_degrees, const std::string& len, bool random_roll = true) {
  if (kink_degrees < kMinKink) return "F(" + len + ")";
  const std::string k = grammar_number(kink_degrees);
  return (random_roll ? "/(uniform(0, 360))&(" : "&(") + k + ")F(" + len + " * 0.5)&(-" +
         grammar_number(2 * kink_degrees) + ")F(" + len + " * 0.5)&(" + k + ")";
}

std::string child(const ChildDistribution& d, const LengthRange& range, const std::string& rest) {
  return turn(d) + "N(clamp(l * " + draw_ratio(d.log_a, "l") + ", " + grammar_number(range.min) +
         ", " + grammar_number(range.max) + "), w * " + draw_ratio(d.log_b, "w") + ", " + rest +
         ")";
}

// `lateral_budget`: the axis budget drawn for a lateral child, empty without axis budgets (the
// module then has no parameter r); the continuation gets what is left of r after this internode.
// With `tips`, the cluster is a last branch node (RuleGroup::last): its continuation is the
// axis's tip and is drawn as one, of the length left, kept within the observed tip lengths.
std::string alternative(const RuleCluster& c, const LengthRange& range, double kink,
                        const std::string& lateral_budget, const LengthRange* tips = nullptr) {
  const bool budget = !lateral_budget.empty();
  std::string s = "!(w)" + segment(kink, "l");
  for (std::size_t j = 1; j < c.children.size(); ++j) {
    s += "[" +
         child(c.children[j], range,
               "o + 1, 0, d + 1" + (budget ? ", " + lateral_budget : std::string())) +
         "]";
  }
  if (c.children.empty()) return s;
  if (tips != nullptr && budget) {
    const ChildDistribution& t = c.children[0];
    return s + turn(t) + "!(w * " + draw_ratio(t.log_b, "w") + ")" +
           segment(kink, "clamp(r - l, " + grammar_number(tips->min) + ", " +
                             grammar_number(tips->max) + ")");
  }
  return s + child(c.children[0], range, budget ? "o, i + 1, d + 1, r - l" : "o, i + 1, d + 1");
}

// The draw of a lateral axis's length budget (AxisBudget), its log moved by `shift`.
std::string budget_draw(const AxisBudget& b, double shift) {
  std::string mean = grammar_number(b.c0 + shift);
  if (b.cl != 0) mean += " + " + grammar_number(b.cl) + " * log(max(l, 1e-9))";
  if (b.cw != 0) mean += " + " + grammar_number(b.cw) + " * log(max(w, 1e-9))";
  if (b.cd != 0) mean += " + " + grammar_number(b.cd) + " * d";
  const std::string lo = grammar_number(b.lo + shift), hi = grammar_number(b.hi + shift);
  if (b.sd < 1e-6 && b.cl == 0 && b.cw == 0 && b.cd == 0)  // one length: written as it is
    return grammar_number(std::exp(std::clamp(b.c0 + shift, b.lo + shift, b.hi + shift)));
  if (b.sd < 1e-6) return "exp(clamp(" + mean + ", " + lo + ", " + hi + "))";
  return "exp(clamp(normal(" + mean + ", " + grammar_number(b.sd) + "), " + lo + ", " + hi + "))";
}

// The draw of a lateral's budget: the mixture of LateralBudget, by one uniform draw. The shift
// moves only the branching axes: a single internode's length is observed as it is, while how far
// the axes branch is what the calibration corrects.
std::string budget_draw(const LateralBudget& b, double shift) {
  if (b.p_single <= 0) return budget_draw(b.branching, shift);
  if (b.p_single >= 1) return budget_draw(b.single, 0);
  return "(uniform(0, 1) < " + grammar_number(b.p_single) + " ? " + budget_draw(b.single, 0) +
         " : " + budget_draw(b.branching, shift) + ")";
}

// Where an axis ends. The budget r counts the internode of length l itself; T is the median
// length of the order's tips. The tip takes what is left of r (the fallback draws F(r)), so an
// axis is as long as its budget and its last internode as long as the input's tips, which
// differ from the inner internodes: a weeping tree's axes end in whips 5 times their parent's
// length, a conifer's in a twig, a pruned scan's in a cut. Each guard sits halfway between the
// two budgets it tells apart, so that the spread of the drawn lengths tips neither way:
//  - the internode carries more than a tip when r > l / 2 + T, halfway between r = T (it is
//    the tip) and r = l + T (one tip follows);
//  - with the last branch nodes of the axes grouped apart (RuleGroup::last), the other branch
//    nodes apply when r > (1 + next / 2) l + T, halfway between r = l + T and r = l + next l + T
//    (another internode of about `next` times l follows, `next` the median ratio of the order's
//    branching continuations), and the last ones below that.
std::string carries_guard(double tip) { return " && r > 0.5 * l + " + grammar_number(tip); }
std::string branching_guard(double next, double tip) {
  return " && r > " + grammar_number(1 + next / 2) + " * l + " + grammar_number(tip);
}

// AxisEnds::shared: an internode of length l continues its axis while the budget r leaves more
// than half of a next internode of l times `next`: r > l (1 + next / 2). `next` is the lower
// quartile of the order's continuation ratios, not the median: an order whose axes end in a
// long shoot (a weeping tree's whip, 6 times its parent) has ratios far above 1 in many of its
// continuations, and a threshold set by them would end its ordinary axes early.
std::string continue_guard(double next) {
  return " && r > " + grammar_number(1 + next / 2) + " * l";
}

// The lower quartile of `v` (not empty).
double lower_quartile(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 4), v.end());
  return v[v.size() / 4];
}

// The median of `v` (not empty).
double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
  return v[v.size() / 2];
}

// Observed frequencies as decimals with six places that sum to exactly 1 (largest remainder),
// as the checker requires of a stochastic production.
std::vector<std::string> probabilities(const std::vector<std::size_t>& counts) {
  constexpr std::int64_t kScale = 1'000'000;
  std::size_t total = 0;
  for (std::size_t c : counts) total += c;
  std::vector<std::int64_t> parts(counts.size());
  std::vector<std::pair<double, std::size_t>> remainders;
  std::int64_t used = 0;
  for (std::size_t i = 0; i < counts.size(); ++i) {
    const double exact = double(counts[i]) * double(kScale) / double(total);
    parts[i] = std::int64_t(std::floor(exact));
    used += parts[i];
    remainders.push_back({exact - double(parts[i]), i});
  }
  std::stable_sort(remainders.begin(), remainders.end(),
                   [](const auto& x, const auto& y) { return x.first > y.first; });
  for (std::size_t k = 0; used < kScale; ++k, ++used)
    ++parts[remainders[k % remainders.size()].second];
  std::vector<std::string> out;
  for (std::int64_t p : parts) {
    if (p == kScale) {
      out.push_back("1");
      continue;
    }
    char buf[32];
    std::snprintf(buf, sizeof buf, "0.%06lld", static_cast<long long>(p));
    std::string s = buf;
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
    out.push_back(s);
  }
  return out;
}

std::size_t count_alternatives(const std::vector<RuleGroup>& groups) {
  std::size_t n = 1;  // the fallback production
  for (const RuleGroup& g : groups) n += g.clusters.size();
  return n;
}

// Meets the rule budget: fewer clusters in the group with the most, then drop the rarest
// branching groups (their weight goes to the rest of their order).
void fit_budget(const BranchRules& rules, std::vector<RuleGroup>& groups,
                const GrammarOptions& options) {
  const auto budget = std::size_t(std::max(options.max_rules, 2));
  while (count_alternatives(groups) > budget) {
    auto most = std::max_element(groups.begin(), groups.end(), [](const auto& x, const auto& y) {
      return x.clusters.size() < y.clusters.size();
    });
    if (most->clusters.size() > 1) {
      recluster_group(rules, *most, int(most->clusters.size()) - 1, options.cluster);
      continue;
    }
    auto rarest = groups.end();
    for (auto it = groups.begin(); it != groups.end(); ++it) {
      if (it->arity == 0) continue;
      if (rarest == groups.end() || it->count < rarest->count) rarest = it;
    }
    if (rarest == groups.end()) break;
    groups.erase(rarest);
  }
}

// With axis budgets the calibration's shift s (more tips as it grows) moves every log budget by
// -s / kBudgetShiftScale: at most a factor e^3 either way.
constexpr double kBudgetShiftScale = 10;

// A calibration growth with more modules than this is taken as far too long.
constexpr std::uint64_t kMaxCalibrationModules = 20'000'000;

// Grows `text` with seeds 1..n and hands every tree to `use`; false when a growth goes over
// kMaxCalibrationModules (far too long).
template <class Use>
bool grow_seeds(const std::string& text, int seeds, const Use& use) {
  for (int k = 1; k <= seeds; ++k) {
    GrowOptions o;
    o.seed = std::uint64_t(k);
    SourceManager sources;
    DiagnosticSink sink;
    try {
      const ir::Grammar g = lower_text("inferred.ramus", text, o, sources, sink);
      DeriveOptions d;
      d.max_modules = kMaxCalibrationModules;
      TurtleOptions t;
      t.seed = g.settings.seed;
      t.steps = g.settings.derive;
      use(interpret(g, derive(g, d), t));
    } catch (const DeriveError&) {
      return false;
    } catch (const std::exception& e) {
      throw InferError(std::string("internal error: the inferred grammar does not grow: ") +
                       e.what());
    }
  }
  return true;
}

// Mean total length of trees grown from `text` with seeds 1..n.
double mean_grown_length(const std::string& text, int seeds) {
  double sum = 0;
  if (!grow_seeds(text, seeds, [&](const Skeleton& s) { sum += s.total_length(); }))
    return std::numeric_limits<double>::infinity();
  return sum / double(seeds);
}

// Calibration against the input: the intercept shift of every tip hazard for which the trees the
// grammar grows have, over `calibration_seeds` seeds, the input tree's total length. Without it
// the regrown length is off by up to 3x: the hazard is fitted per internode, but the regrown tree
// compounds its errors (ratios drawn independently, tips of a scan hidden by occlusion). The
// mean length falls as the shift grows (more tips), so the shift is found by bisection on
// [-kMaxShift, kMaxShift] in the log of the length ratio.
template <class Write>
double calibrate_tip_shift(const Write& write, double target, const GrammarOptions& options) {
  constexpr double kMaxShift = 30;
  constexpr int kSteps = 12;
  if (!(target > 0)) return 0;
  auto error = [&](double shift) {
    const double grown = mean_grown_length(write(shift), options.calibration_seeds);
    return std::log(std::max(grown, 1e-12) / target);
  };
  double lo = -kMaxShift, hi = kMaxShift;
  if (error(lo) <= 0) return lo;  // even with fewer tips the grammar grows too little
  if (error(hi) >= 0) return hi;
  for (int it = 0; it < kSteps; ++it) {
    const double mid = (lo + hi) / 2;
    (error(mid) > 0 ? lo : hi) = mid;
  }
  return (lo + hi) / 2;
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

std::string grammar_number(double v) {
  if (!std::isfinite(v)) return "0";
  if (std::abs(v) < 1e-9) return "0";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  std::string s = buf;
  // "%g" may write "1e+02"; the language reads "1e+02" too, but fixed notation reads better.
  if (s.find('e') != std::string::npos && std::abs(v) >= 1e-4 && std::abs(v) < 1e15) {
    std::snprintf(buf, sizeof buf, "%.6f", v);
    s = buf;
    while (!s.empty() && s.back() == '0') s.pop_back();
    if (!s.empty() && s.back() == '.') s.pop_back();
  }
  return s;
}

namespace {

// grown_distance against the input's measures, taken once for every candidate.
double grown_distance(const std::string& text, const Distributions& input, int seeds) {
  Distributions grown;
  if (!grow_seeds(text, seeds, [&](const Skeleton& s) { measure(s, grown); }))
    return std::numeric_limits<double>::infinity();
  if (input.trees == 0 || grown.trees == 0) return std::numeric_limits<double>::infinity();
  double distance = 0;
  for (const MeasureComparison& c : compare(input, grown)) {
    switch (c.measure) {
      case Measure::BranchLength:
      case Measure::BranchingAngle:
      case Measure::BranchOrder:
        distance += c.ks;
        break;
      case Measure::TotalLength:
      case Measure::CrownExtent:
      case Measure::Height:
        distance += std::abs(std::log(std::max(c.mean_b, 1e-12) / std::max(c.mean_a, 1e-12)));
        break;
      default:
        break;
    }
  }
  return distance;
}

}  // namespace

double grown_distance(const std::string& text, const Skeleton& skeleton, int seeds) {
  Distributions input;
  measure(skeleton, input);
  return grown_distance(text, input, seeds);
}

InferredGrammar infer_grammar(const Skeleton& skeleton, const GrammarOptions& options) {
  const BranchRules rules = extract_branch_rules(skeleton);
  using AxisEnds = GrammarOptions::AxisEnds;
  if (!options.axis_budget || options.axis_ends != AxisEnds::automatic ||
      options.calibration_seeds <= 0 || rules.internodes.empty())
    return infer_grammar(rules, options);
  // Model selection by simulation: the two ways of ending axes suit different trees (the own
  // tips fit a tree whose axes end in long shoots, the shared lengths fit sparse scans whose
  // few tips say little), and what decides is how close the grown trees come to the input.
  GrammarOptions o = options;
  o.axis_ends = AxisEnds::own;
  InferredGrammar own = infer_grammar(rules, o);
  o.axis_ends = AxisEnds::shared;
  InferredGrammar shared = infer_grammar(rules, o);
  Distributions input;
  measure(skeleton, input);
  const double d_own = grown_distance(own.text, input, options.calibration_seeds);
  const double d_shared = grown_distance(shared.text, input, options.calibration_seeds);
  InferredGrammar& best = d_shared < d_own ? shared : own;
  best.distance_own = d_own;
  best.distance_shared = d_shared;
  return std::move(best);
}

InferredGrammar infer_grammar(const BranchRules& extracted, const GrammarOptions& given) {
  GrammarOptions options = given;
  // AxisEnds::own: a tip takes what is left of its budget, and the last branch nodes of the
  // axes are a production of their own (see carries_guard and branching_guard).
  const bool own = options.axis_budget && options.axis_ends != GrammarOptions::AxisEnds::shared;
  options.cluster.branching_child_lengths = own;
  options.cluster.split_last = own;
  if (extracted.internodes.empty()) {
    throw InferError("the skeleton has no segment (a single node or none): nothing to infer");
  }
  InferredGrammar out;
  out.axis_ends = own ? GrammarOptions::AxisEnds::own : GrammarOptions::AxisEnds::shared;
  // Tortuosity of the internodes, length-weighted: the kink angle of `segment`.
  double chords = 0, paths = 0;
  for (const Internode& in : extracted.internodes) chords += in.chord, paths += in.length;
  const double tortuosity = paths > 0 ? std::clamp(chords / paths, 0.0, 1.0) : 1.0;
  const double kink = std::acos(tortuosity) * 57.29577951308232;  // degrees
  out.tortuosity = tortuosity;
  // Tropism (ABOP 2.2, tropism_fit.h): the turtle bends after every F, so per internode once
  // when it is drawn straight and twice when kinked; the rules' angles are measured from the
  // bent heading. A fit on fewer than kMinTropismPairs pairs, or one that explains almost none
  // of the variance, is not written.
  constexpr std::size_t kMinTropismPairs = 10;
  constexpr double kMinTropismR2 = 0.02;
  const int bends = kink < kMinKink ? 1 : 2;
  std::optional<BranchRules> bent;
  if (options.tropism) {
    out.tropism = fit_elasticity(extracted, bends, &out.tropism_by_order);
    if (out.tropism.pairs < kMinTropismPairs || out.tropism.r2 < kMinTropismR2 ||
        std::abs(out.tropism.elasticity) < 1e-4) {
      out.tropism.elasticity = 0;
    } else {
      bent = extracted;
      measure_from_bent_heading(*bent, out.tropism.elasticity, bends);
    }
  }
  const BranchRules& rules = bent ? *bent : extracted;
  out.internodes = rules.internodes.size();
  for (const NodeRule& r : rules.rules) out.branch_nodes += r.child_count >= 2 ? 1 : 0;

  const int max_order = options.cluster.max_order;
  std::map<std::uint16_t, OrderStats> stats;
  std::uint16_t deepest_order = 0;
  std::uint32_t deepest = 0;
  for (const Internode& in : rules.internodes) {
    OrderStats& s = stats[std::uint16_t(std::min<int>(in.order, max_order))];
    ++s.internodes;
    const bool tip = rules.rules[&in - rules.internodes.data()].child_count == 0;
    s.tips += tip ? 1 : 0;
    if (tip) s.tip_lengths.push_back(in.length);
    s.hazard.push_back({double(in.depth), std::log(std::max(2 * in.radius, kTiny)), tip ? 1.0 : 0.0,
                        std::log(std::max(in.length, kTiny))});
    s.max_axis_index = std::max(s.max_axis_index, in.axis_index);
    deepest_order = std::max(deepest_order, in.order);
    deepest = std::max(deepest, in.depth);
  }
  LengthRange lengths{rules.internodes[0].length, rules.internodes[0].length};
  for (const Internode& in : rules.internodes) {
    lengths.min = std::min(lengths.min, in.length);
    lengths.max = std::max(lengths.max, in.length);
  }
  out.derive = int(deepest);  // the axiom draws depth 0; step k expands depth k
  out.groups = cluster_rules(rules, options.cluster);
  fit_budget(rules, out.groups, options);

  // The axiom: the first internode of the tree with the most length (when the root forks, the
  // one carrying the most length above it: a reconstructed root often has short side branches
  // beside the trunk), turned from the turtle's initial frame like the real trunk.
  std::size_t tree = 0;
  for (std::size_t t = 1; t < rules.tree_length.size(); ++t) {
    if (rules.tree_length[t] > rules.tree_length[tree]) tree = t;
  }
  std::vector<double> carried(rules.internodes.size(), 0.0);  // length of internode + subtree
  for (std::size_t i = rules.internodes.size(); i-- > 0;) {
    carried[i] += rules.internodes[i].length;
    std::uint32_t p = rules.internodes[i].parent;
    if (p != kNone && p < i) {
      carried[p] += carried[i];
    } else {
      // Parents are extracted before their children; walk up if one is not.
      for (; p != kNone; p = rules.internodes[p].parent) carried[p] += rules.internodes[i].length;
    }
  }
  std::uint32_t trunk = rules.tree_first[tree];
  for (std::uint32_t i = trunk;
       i < rules.internodes.size() &&
       rules.internodes[i].tree == rules.internodes[rules.tree_first[tree]].tree;
       ++i) {
    const Internode& in = rules.internodes[i];
    if (in.parent == kNone && carried[i] > carried[trunk]) trunk = i;
  }
  const Internode& t0 = rules.internodes[trunk];
  double theta0 = 0, phi0 = 0;
  angle_and_azimuth(Vec3{0, 0, 1}, t0.direction, theta0, phi0);

  // Termination per order group: the logistic hazard of depth, and of log width and log length
  // too when that model is better by the Bayesian information criterion (a tree grown with a
  // width threshold has its tips where w falls, one whose axes end in a long shoot where l
  // jumps; on a scan the radii are often too noisy to tell).
  std::map<std::uint16_t, TipHazard> hazards;
  for (const auto& [order, st] : stats) {
    // Depth always; width and length each when the BIC (2 ln L - p ln n) prefers them.
    const double ln_n = std::log(double(std::max<std::size_t>(st.hazard.size(), 1)));
    double best_score = -std::numeric_limits<double>::infinity();
    for (int model = 0; model < 4; ++model) {
      std::vector<TipSample> samples = st.hazard;
      for (TipSample& t : samples) {
        if ((model & 1) == 0) t.log_width = 0;
        if ((model & 2) == 0) t.log_length = 0;
      }
      const TipHazard h = fit_tip_hazard(samples);
      const double params = 2 + (model & 1) + ((model & 2) >> 1);
      const double score = 2 * h.log_likelihood - params * ln_n;
      if (score > best_score) best_score = score, hazards[order] = h;
    }
  }

  // Axis budgets: `remaining[i]` is the length of internode i and of all that continue its axis.
  // A lateral's sample pairs its axis length with the internode carrying it; groups by the
  // lateral's order, a group with fewer than kMinBudgetAxes axes uses the fit over all laterals.
  constexpr std::size_t kMinBudgetAxes = 8;
  const std::size_t n_in = rules.internodes.size();
  std::vector<double> remaining(n_in, 0.0);
  std::map<std::uint16_t, LateralBudget> budgets;
  std::map<const RuleCluster*, LateralBudget> cluster_budgets;
  // The typical tip of an order (carries_guard): the median of the order's tips (the one tip
  // of a tree's trunk), of all tips for an order without any. The fallback keeps every tip
  // within the observed lengths.
  std::map<std::uint16_t, double> typical_tip;
  std::map<std::uint16_t, double> next_ratio;  // median ratio of the branching continuations
  LengthRange tip_range{lengths.max, lengths.min};
  LateralBudget pooled_budget;
  if (options.axis_budget) {
    std::vector<std::uint32_t> next(n_in, kNone);
    for (std::uint32_t i = 0; i < n_in; ++i) {
      const Internode& in = rules.internodes[i];
      if (in.continuation && in.parent != kNone) next[in.parent] = i;
    }
    std::vector<std::uint32_t> chain;
    for (std::uint32_t i = 0; i < n_in; ++i) {
      const Internode& in = rules.internodes[i];
      if (in.continuation && in.parent != kNone) continue;  // not an axis start
      chain.clear();
      for (std::uint32_t j = i; j != kNone && chain.size() <= n_in; j = next[j]) chain.push_back(j);
      double sum = 0;
      for (auto j = chain.rbegin(); j != chain.rend(); ++j)
        remaining[*j] = (sum += rules.internodes[*j].length);
    }
    std::map<std::uint16_t, std::vector<BudgetSample>> samples;
    std::vector<BudgetSample> all;
    for (std::uint32_t i = 0; i < n_in; ++i) {
      const Internode& in = rules.internodes[i];
      if (in.continuation || in.parent == kNone) continue;
      const Internode& p = rules.internodes[in.parent];
      const BudgetSample b{std::log(std::max(p.length, kTiny)),
                           std::log(std::max(2 * p.radius, kTiny)), double(p.depth),
                           std::log(std::max(remaining[i], kTiny)),
                           own && rules.rules[i].child_count == 0};
      samples[std::uint16_t(std::min<int>(in.order, max_order))].push_back(b);
      all.push_back(b);
    }
    pooled_budget = fit_lateral_budget(all);
    std::vector<double> all_tips;
    for (const auto& [order, st] : stats)
      all_tips.insert(all_tips.end(), st.tip_lengths.begin(), st.tip_lengths.end());
    for (double t : all_tips)
      tip_range.min = std::min(tip_range.min, t), tip_range.max = std::max(tip_range.max, t);
    std::map<std::uint16_t, std::vector<double>> ratios;
    for (const Internode& in : rules.internodes) {
      if (!in.continuation || in.parent == kNone) continue;
      if (own && rules.rules[&in - rules.internodes.data()].child_count == 0) continue;
      const double lp = rules.internodes[in.parent].length;
      if (lp > kTiny && in.length > kTiny)
        ratios[std::uint16_t(std::min<int>(in.order, max_order))].push_back(in.length / lp);
    }
    for (auto& [order, v] : ratios) next_ratio[order] = own ? median(v) : lower_quartile(v);
    for (const auto& [order, st] : stats) {
      if (!st.tip_lengths.empty()) {
        typical_tip[order] = median(st.tip_lengths);
      } else if (!all_tips.empty()) {
        typical_tip[order] = median(all_tips);
      }
    }
    for (const auto& [order, v] : samples)
      budgets[order] = v.size() >= kMinBudgetAxes ? fit_lateral_budget(v) : pooled_budget;
    // Per cluster: the laterals of its rules, when there are enough of them.
    for (const RuleGroup& g : out.groups) {
      for (const RuleCluster& c : g.clusters) {
        std::vector<BudgetSample> v;
        for (std::uint32_t m : c.members) {
          const NodeRule& rule = rules.rules[m];
          const Internode& p = rules.internodes[m];
          for (const ChildRule* ch = rules.begin(rule); ch != rules.end(rule); ++ch) {
            const Internode& in = rules.internodes[ch->internode];
            if (in.continuation) continue;
            v.push_back({std::log(std::max(p.length, kTiny)),
                         std::log(std::max(2 * p.radius, kTiny)), double(p.depth),
                         std::log(std::max(remaining[ch->internode], kTiny)),
                         own && rules.rules[ch->internode].child_count == 0});
          }
        }
        if (v.size() >= kMinBudgetAxes) cluster_budgets[&c] = fit_lateral_budget(v);
      }
    }
  }
  auto lateral_budget = [&](const RuleCluster& c, std::uint16_t parent_order, double shift) {
    if (!options.axis_budget) return std::string();
    // The calibration moves only the budgets of the finest laterals (the deepest order group):
    // they add length but little reach, while the reach of the coarser axes is the input's.
    if (std::min<int>(parent_order + 1, max_order) < std::min<int>(deepest_order, max_order))
      shift = 0;
    if (const auto own = cluster_budgets.find(&c); own != cluster_budgets.end())
      return budget_draw(own->second, shift);
    const auto it = budgets.find(std::uint16_t(std::min<int>(parent_order + 1, max_order)));
    return budget_draw(it != budgets.end() ? it->second : pooled_budget, shift);
  };

  // The grammar with every tip hazard's intercept, or every log axis budget, moved by `shift`
  // (see calibration below).
  auto write = [&](double shift) {
    std::string text;
    text += "// Inferred by `ramus infer --method skeleton`";
    if (!options.source_name.empty()) text += " from " + options.source_name;
    text += ": " + std::to_string(out.internodes) + " internodes, " +
            std::to_string(out.branch_nodes) + " branch nodes.\n";
    text +=
        "// N(l, w, o, i, d" + std::string(options.axis_budget ? ", r" : "") +
        "): an internode of length l and width w, branch order o, position i on its axis, depth "
        "d" +
        std::string(options.axis_budget ? ", r the length left to its axis (itself included)"
                                        : "") +
        ".\n";
    text += "lsystem " + options.system_name + " {\n";
    text += "  derive " + std::to_string(out.derive) + ";\n";
    text += "  seed " + std::to_string(options.cluster.seed) + ";\n";
    if (out.tropism.elasticity != 0) {
      // ABOP 2.2: e > 0 bends towards the ground, e < 0 away from it (written as a tropism
      // towards the sky with |e|: the same turn, since |H x T| is the same).
      const double e = out.tropism.elasticity;
      std::string fits;
      for (std::size_t o = 0; o < out.tropism_by_order.size(); ++o) {
        if (out.tropism_by_order[o].pairs < 3) continue;
        fits += (fits.empty() ? "" : ", ") + std::string("order ") + std::to_string(o) + " " +
                grammar_number(out.tropism_by_order[o].elasticity);
      }
      text += "  // gravitropism fitted on " + std::to_string(out.tropism.pairs) +
              " continuations (R^2 " + grammar_number(out.tropism.r2) + "; per order: " + fits +
              ")\n";
      text += std::string("  tropism 0, 0, ") + (e > 0 ? "-1" : "1") + ";\n";
      text += "  elasticity " + grammar_number(std::abs(e)) + ";\n";
    }
    // The first internode and its children as observed (absolute lengths and widths): the trunk's
    // base is often far longer than any later internode, and no ratio describes that jump.
    std::string axiom = "/(" + grammar_number(phi0) + ")&(" + grammar_number(theta0) + ")!(" +
                        grammar_number(2 * t0.radius) + ")" +
                        segment(kink, grammar_number(t0.length), false);
    const NodeRule& root_rule = rules.rules[trunk];
    std::string continuation;
    for (const ChildRule* c = rules.begin(root_rule); c != rules.end(root_rule); ++c) {
      const Internode& ci = rules.internodes[c->internode];
      const std::string call =
          "$/(" + grammar_number(c->phi) + ")&(" + grammar_number(c->theta) + ")N(" +
          grammar_number(ci.length) + ", " + grammar_number(2 * ci.radius) + ", " +
          std::to_string(ci.order) + ", " + std::to_string(ci.axis_index) + ", 1" +
          (options.axis_budget ? ", " + grammar_number(remaining[c->internode]) : std::string()) +
          ")";
      if (ci.continuation) {
        continuation = call;
      } else {
        axiom += "[" + call + "]";
      }
    }
    axiom += continuation;
    text += "  axiom " + axiom + ";\n";

    out.productions = 1;
    out.alternatives = 1;
    for (const auto& [order, st] : stats) {
      std::vector<const RuleGroup*> mine;
      for (const RuleGroup& g : out.groups) {
        if (g.order == order) mine.push_back(&g);
      }
      const bool branches =
          std::any_of(mine.begin(), mine.end(), [](const RuleGroup* g) { return g->arity > 0; });
      if (!branches || st.max_axis_index == 0) continue;  // the fallback draws its tips
      std::string guard;
      if (order < max_order) {
        guard = "o == " + std::to_string(order);
      } else {
        guard = "o >= " + std::to_string(order) + " && o <= " + std::to_string(deepest_order);
      }
      guard += " && i < " + std::to_string(st.max_axis_index);
      text += "  // order " + std::to_string(order) + (order == max_order ? " and above" : "") +
              ": " + std::to_string(st.internodes) + " internodes, longest axis " +
              std::to_string(st.max_axis_index + 1) + "\n";
      const std::string params = options.axis_budget ? "l, w, o, i, d, r" : "l, w, o, i, d";
      // Without axis budgets: tips by the logistic hazard of depth, log width and log length;
      // branching alternatives share the rest by their observed frequencies among the branch
      // nodes of the order. With them, the budget ends the axes, and the last branch nodes of
      // the axes (RuleGroup::last) have a production of their own.
      const RuleGroup* tip_group = nullptr;
      std::vector<const RuleGroup*> going, ending;
      for (const RuleGroup* g : mine) {
        if (g->arity == 0) {
          tip_group = g;
        } else {
          (g->last ? ending : going).push_back(g);
        }
      }
      if (options.axis_budget) tip_group = nullptr;
      const TipHazard& h = hazards.at(order);
      std::string z = grammar_number(h.alpha + shift) + " + " + grammar_number(h.beta) + " * d";
      if (h.gamma != 0) z += " + " + grammar_number(h.gamma) + " * log(max(w, 1e-9))";
      if (h.delta != 0) z += " + " + grammar_number(h.delta) + " * log(max(l, 1e-9))";
      auto production = [&](const std::vector<const RuleGroup*>& groups,
                            const std::string& budget_guard, bool ends) {
        text += "  N(" + params + ") : " + guard + budget_guard + " ->";
        std::vector<std::size_t> counts;
        for (const RuleGroup* g : groups)
          for (const RuleCluster& c : g->clusters) counts.push_back(c.count);
        const std::vector<std::string> probs = probabilities(counts);
        bool first = true;
        if (tip_group != nullptr) {
          text += " (1 / (1 + exp(clamp(-(" + z + "), -30, 30)))) !(w)" + segment(kink, "l");
          first = false;
          ++out.alternatives;
        }
        std::size_t k = 0;
        for (const RuleGroup* g : groups) {
          for (const RuleCluster& c : g->clusters) {
            text += first ? " " : " | ";
            const std::string& q = probs[k++];
            if (tip_group != nullptr) {
              text += "(" + q + " / (1 + exp(clamp(" + z + ", -30, 30)))) ";
            } else {
              text += "(" + q + ") ";
            }
            first = false;
            text +=
                alternative(c, lengths, kink, lateral_budget(c, order, -shift / kBudgetShiftScale),
                            ends ? &tip_range : nullptr);
            ++out.alternatives;
          }
        }
        text += ";\n";
        ++out.productions;
      };
      const double tip = typical_tip.count(order) != 0 ? typical_tip.at(order) : 0.0;
      const double next = next_ratio.count(order) != 0 ? next_ratio.at(order) : 1.0;
      if (!going.empty()) {
        std::string budget_guard;
        if (options.axis_budget && !own) {
          budget_guard = continue_guard(next);
        } else if (options.axis_budget) {
          budget_guard = ending.empty() ? carries_guard(tip) : branching_guard(next, tip);
        }
        production(going, budget_guard, false);
      }
      if (!ending.empty()) production(ending, carries_guard(tip), true);
    }
    text += options.axis_budget ? "  // tips: axes whose budget is spent or past their longest "
                                  "observed length, orders past the deepest\n"
                                : "  // tips: axes past their longest observed length, orders "
                                  "past the deepest\n";
    const std::string tip = own && tip_range.min <= tip_range.max
                                ? "clamp(r, " + grammar_number(tip_range.min) + ", " +
                                      grammar_number(tip_range.max) + ")"
                                : std::string("l");
    text += std::string("  N(") + (options.axis_budget ? "l, w, o, i, d, r" : "l, w, o, i, d") +
            ") -> !(w)" + segment(kink, tip) + ";\n";
    text += "}\n";
    return text;
  };

  std::string text = write(0);
  if (options.calibration_seeds > 0) {
    const double target = rules.tree_length[tree];
    const double shift = calibrate_tip_shift(write, target, options);
    text = write(shift);
    out.tip_shift = options.axis_budget ? -shift / kBudgetShiftScale : shift;
  }

  // Canonical layout: what `ramus fmt` would write.
  SourceManager sources;
  DiagnosticSink sink;
  const std::uint32_t id = sources.add("inferred.ramus", text);
  const ast::File file = parse(sources, id, sink);
  if (sink.has_errors()) throw InferError("internal error: the inferred grammar does not parse");
  out.text = format_file(file, sources);
  return out;
}

}  // namespace ramus::skeleton_infer
