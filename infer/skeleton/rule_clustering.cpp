#include "infer/skeleton/rule_clustering.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>

#include "core/rng.h"

namespace ramus::skeleton_infer {

namespace {

constexpr double kPiValue = 3.14159265358979323846;
constexpr double kRad = kPiValue / 180.0;
constexpr int kRestarts = 3;
constexpr int kIterations = 60;
constexpr std::size_t kFeaturesPerChild = 5;  // theta, cos phi, sin phi, log a, log b
// Fewer samples than this fit no length regression of their own (a cluster child with fewer
// uses the regression pooled over its group's clusters).
constexpr std::size_t kMinRegression = 8;

double squared_distance(const double* x, const double* c, std::size_t dim) {
  double s = 0;
  for (std::size_t j = 0; j < dim; ++j) s += (x[j] - c[j]) * (x[j] - c[j]);
  return s;
}

double safe_log(double v) { return std::log(std::clamp(v, 1e-3, 1e3)); }

// One k-means run from a k-means++ seeding drawn from `rng`.
std::vector<std::uint32_t> kmeans_once(const std::vector<double>& data, std::size_t n,
                                       std::size_t dim, int k, Rng rng, double& sse) {
  std::vector<double> centres(std::size_t(k) * dim);
  std::vector<double> d2(n, std::numeric_limits<double>::infinity());
  std::size_t pick = std::size_t(rng.below(n));
  for (int c = 0; c < k; ++c) {
    std::copy_n(data.data() + pick * dim, dim, centres.data() + std::size_t(c) * dim);
    double total = 0;
    for (std::size_t i = 0; i < n; ++i) {
      d2[i] = std::min(d2[i], squared_distance(data.data() + i * dim,
                                               centres.data() + std::size_t(c) * dim, dim));
      total += d2[i];
    }
    if (c + 1 == k) break;
    // k-means++: the next centre with probability proportional to D^2.
    double target = rng.uniform01() * total;
    pick = n - 1;
    for (std::size_t i = 0; i < n; ++i) {
      target -= d2[i];
      if (target < 0) {
        pick = i;
        break;
      }
    }
  }
  std::vector<std::uint32_t> labels(n, 0);
  std::vector<std::size_t> counts(static_cast<std::size_t>(k), 0);
  for (int it = 0; it < kIterations; ++it) {
    bool changed = it == 0;
    sse = 0;
    for (std::size_t i = 0; i < n; ++i) {
      double best = std::numeric_limits<double>::infinity();
      std::uint32_t lab = 0;
      for (int c = 0; c < k; ++c) {
        const double d =
            squared_distance(data.data() + i * dim, centres.data() + std::size_t(c) * dim, dim);
        if (d < best) best = d, lab = std::uint32_t(c);
      }
      if (labels[i] != lab) changed = true;
      labels[i] = lab;
      d2[i] = best;
      sse += best;
    }
    if (!changed) break;
    std::fill(centres.begin(), centres.end(), 0.0);
    std::fill(counts.begin(), counts.end(), 0);
    for (std::size_t i = 0; i < n; ++i) {
      ++counts[labels[i]];
      for (std::size_t j = 0; j < dim; ++j) centres[labels[i] * dim + j] += data[i * dim + j];
    }
    for (int c = 0; c < k; ++c) {
      if (counts[std::size_t(c)] == 0) {
        // An empty cluster takes the point farthest from its centre.
        const std::size_t far = std::size_t(std::max_element(d2.begin(), d2.end()) - d2.begin());
        std::copy_n(data.data() + far * dim, dim, centres.data() + std::size_t(c) * dim);
        d2[far] = 0;
        continue;
      }
      for (std::size_t j = 0; j < dim; ++j) {
        centres[std::size_t(c) * dim + j] /= double(counts[std::size_t(c)]);
      }
    }
  }
  return labels;
}

struct GroupData {
  std::vector<std::uint32_t> members;  // rule indices
  std::vector<double> features;        // standardized, members.size() x dim
  std::size_t dim = 0;
};

GroupData group_features(const BranchRules& rules, const RuleGroup& group,
                         const ClusterOptions& options) {
  GroupData g;
  for (const NodeRule& r : rules.rules) {
    const Internode& in = rules.internodes[r.internode];
    if (in.parent == kNone) continue;
    const auto order = std::uint16_t(std::min<int>(in.order, options.max_order));
    if (order != group.order || r.child_count != group.arity) continue;
    if (group.split && ends_axis(rules, r) != group.last) continue;
    g.members.push_back(r.internode);
  }
  g.dim = group.arity * kFeaturesPerChild;
  const std::size_t n = g.members.size();
  g.features.resize(n * g.dim);
  for (std::size_t i = 0; i < n; ++i) {
    const NodeRule& r = rules.rules[g.members[i]];
    double* f = g.features.data() + i * g.dim;
    for (const ChildRule* c = rules.begin(r); c != rules.end(r); ++c) {
      *f++ = c->theta;
      *f++ = std::cos(c->phi * kRad);
      *f++ = std::sin(c->phi * kRad);
      *f++ = safe_log(c->a);
      *f++ = safe_log(c->b);
    }
  }
  // Columns to unit variance, so that angles, ratios and directions weigh alike. The cosine and
  // sine of an azimuth are scaled together, to a total variance of one: scaled apart, a
  // concentrated azimuth (cos and sin then move together) would count twice and look like two
  // clusters to the spherical model BIC scores.
  std::vector<double> mean(g.dim, 0.0), var(g.dim, 0.0);
  for (std::size_t j = 0; j < g.dim; ++j) {
    for (std::size_t i = 0; i < n; ++i) mean[j] += g.features[i * g.dim + j];
    mean[j] /= double(std::max<std::size_t>(n, 1));
    for (std::size_t i = 0; i < n; ++i) {
      const double d = g.features[i * g.dim + j] - mean[j];
      var[j] += d * d;
    }
    var[j] = n > 1 ? var[j] / double(n - 1) : 0.0;
  }
  for (std::size_t j = 0; j < g.dim; ++j) {
    const std::size_t slot = j % kFeaturesPerChild;
    double v = var[j];
    if (slot == 1) v = var[j] + var[j + 1];  // cos phi with its sine
    if (slot == 2) v = var[j - 1] + var[j];
    const double sd = std::sqrt(v);
    for (std::size_t i = 0; i < n; ++i) {
      double& x = g.features[i * g.dim + j];
      x = sd > 1e-9 ? (x - mean[j]) / sd : 0.0;
    }
  }
  return g;
}

// The k in 1..kmax of best BIC on `data`; `gain` receives its BIC over k = 1.
int select_k(const std::vector<double>& data, std::size_t dim, int kmax, std::uint64_t seed,
             double& gain);

Fitted fit(const std::vector<double>& v) {
  Fitted f;
  if (v.empty()) return f;
  double s = 0;
  for (double x : v) s += x;
  f.mean = s / double(v.size());
  double var = 0;
  for (double x : v) var += (x - f.mean) * (x - f.mean);
  f.sd = v.size() > 1 ? std::sqrt(var / double(v.size() - 1)) : 0.0;
  f.min = *std::min_element(v.begin(), v.end());
  f.max = *std::max_element(v.begin(), v.end());
  return f;
}

FittedAngle fit_angle(const std::vector<double>& deg) {
  FittedAngle f;
  if (deg.empty()) return f;
  double c = 0, s = 0;
  for (double d : deg) c += std::cos(d * kRad), s += std::sin(d * kRad);
  c /= double(deg.size());
  s /= double(deg.size());
  const double r = std::sqrt(c * c + s * s);
  f.mean = std::atan2(s, c) / kRad;
  if (f.mean < 0) f.mean += 360;
  // R below 0.3 is a circular sd above ~89 degrees: the azimuths carry no preferred direction.
  f.uniform = deg.size() > 1 && r < 0.3;
  f.sd = r >= 1 ? 0.0 : std::sqrt(-2 * std::log(std::max(r, 1e-12))) / kRad;
  return f;
}

// log a = mean + slope (log l - centre) + noise: a ratio that shrinks for long parents and grows
// for short ones (regression towards the typical length) instead of a pure ratio, whose errors
// would compound from internode to internode. The slope is kept in [-1, 0]: -1 is a child
// length independent of the parent's, 0 the plain ratio of Eq. 4.11. (A second regressor, the
// parent's depth, was tried: it extrapolates badly on the few rules of a cluster and widened
// the regrown crowns.)
Fitted fit_log_ratio(const std::vector<double>& x, const std::vector<double>& y) {
  Fitted f = fit(y);
  const std::size_t n = y.size();
  if (n < kMinRegression) return f;
  double mx = 0;
  for (double v : x) mx += v;
  mx /= double(n);
  double sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < n; ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - f.mean);
  }
  if (sxx < 1e-12) return f;
  f.slope = std::clamp(sxy / sxx, -1.0, 0.0);
  f.centre = mx;
  double rss = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = y[i] - f.mean - f.slope * (x[i] - mx);
    rss += r * r;
  }
  f.sd = std::sqrt(rss / double(n - 2));
  return f;
}

// Marks `f` as a two-point distribution when its values sit on at most two exact points.
void fit_atoms(Fitted& f, const std::vector<double>& v) {
  if (v.size() < 5) return;
  std::map<long long, std::pair<std::size_t, double>> points;  // key: the value to 1e-6
  for (double x : v) {
    auto& p = points[std::llround(x * 1e6)];
    if (p.first++ == 0) p.second = x;
  }
  std::vector<std::pair<std::size_t, double>> by_count;
  for (const auto& [key, p] : points) by_count.push_back(p);
  std::stable_sort(by_count.begin(), by_count.end(),
                   [](const auto& x, const auto& y) { return x.first > y.first; });
  const double n = double(v.size());
  if (double(by_count[0].first) >= kAtomShare * n) {
    f.atoms = true;
    f.atom0 = f.atom1 = by_count[0].second;
    return;
  }
  if (by_count.size() >= 2 && double(by_count[0].first + by_count[1].first) >= kAtomShare * n) {
    f.atoms = true;
    f.atom0 = by_count[0].second;
    f.atom1 = by_count[1].second;
    f.atom_p = double(by_count[1].first) / double(by_count[0].first + by_count[1].first);
  }
}

// The (log parent length, log ratio) pairs of one child slot, all of them and those of the
// children that branch again (see ClusterOptions::branching_child_lengths).
struct LengthRatios {
  std::vector<double> loglen, a, branching_loglen, branching_a;
  void add(const BranchRules& rules, std::uint32_t parent, const ChildRule& c) {
    const double x = std::log(std::max(rules.internodes[parent].length, 1e-9));
    loglen.push_back(x);
    a.push_back(safe_log(c.a));
    if (rules.rules[c.internode].child_count > 0) {
      branching_loglen.push_back(x);
      branching_a.push_back(safe_log(c.a));
    }
  }
  bool use_branching(bool branching_only) const {
    return branching_only && branching_a.size() >= kMinBranchingLengths;
  }
  std::size_t fitted_count(bool branching_only) const {
    return use_branching(branching_only) ? branching_a.size() : a.size();
  }
  Fitted fit(bool branching_only) const {
    if (use_branching(branching_only)) return fit_log_ratio(branching_loglen, branching_a);
    return fit_log_ratio(loglen, a);
  }
};

// The length-ratio regression of the continuation (role 0) or of the laterals (role 1) of
// `members`, pooled over their clusters and lateral positions: what a cluster child with too
// few rules for its own regression uses.
Fitted pooled_length_ratio(const BranchRules& rules, const std::vector<std::uint32_t>& members,
                           int role, bool branching_only) {
  LengthRatios ratios;
  for (std::uint32_t m : members) {
    const NodeRule& r = rules.rules[m];
    for (const ChildRule* c = rules.begin(r); c != rules.end(r); ++c) {
      if ((c == rules.begin(r)) == (role == 0)) ratios.add(rules, m, *c);
    }
  }
  return ratios.fit(branching_only);
}

RuleCluster fit_cluster(const BranchRules& rules, const std::vector<std::uint32_t>& members,
                        std::uint32_t arity, const Fitted* pooled, bool branching_only) {
  RuleCluster cl;
  cl.count = members.size();
  cl.members = members;
  std::vector<double> th, ph, b;
  for (std::uint32_t j = 0; j < arity; ++j) {
    th.clear(), ph.clear(), b.clear();
    LengthRatios ratios;
    for (std::uint32_t m : members) {
      const ChildRule& c = rules.begin(rules.rules[m])[j];
      th.push_back(c.theta);
      ph.push_back(c.phi);
      ratios.add(rules, m, c);
      b.push_back(safe_log(c.b));
    }
    Fitted log_b = fit(b);
    fit_atoms(log_b, b);
    Fitted log_a = ratios.fit(branching_only);
    if (ratios.fitted_count(branching_only) < kMinRegression && pooled != nullptr &&
        pooled[j == 0 ? 0 : 1].regression())
      log_a = pooled[j == 0 ? 0 : 1];
    cl.children.push_back({fit(th), log_a, log_b, fit_angle(ph)});
  }
  return cl;
}

void fit_group(const BranchRules& rules, RuleGroup& group, const GroupData& g,
               const std::vector<std::uint32_t>& labels, int k, bool branching_only) {
  group.clusters.clear();
  std::vector<std::vector<std::uint32_t>> members(std::size_t(std::max(k, 1)));
  for (std::size_t i = 0; i < g.members.size(); ++i) {
    members[labels.empty() ? 0 : labels[i]].push_back(g.members[i]);
  }
  const Fitted pooled[2] = {pooled_length_ratio(rules, g.members, 0, branching_only),
                            pooled_length_ratio(rules, g.members, 1, branching_only)};
  for (const auto& m : members) {
    if (!m.empty())
      group.clusters.push_back(fit_cluster(rules, m, group.arity, pooled, branching_only));
  }
  // Most frequent first, so the written grammar reads from the common case down.
  std::stable_sort(group.clusters.begin(), group.clusters.end(),
                   [](const RuleCluster& x, const RuleCluster& y) { return x.count > y.count; });
}

}  // namespace

std::vector<std::uint32_t> kmeans(const std::vector<double>& data, std::size_t dim, int k,
                                  std::uint64_t seed, double& sse) {
  const std::size_t n = dim == 0 ? 0 : data.size() / dim;
  sse = 0;
  if (n == 0 || k <= 1) {
    std::vector<std::uint32_t> labels(n, 0);
    std::vector<double> mean(dim, 0.0);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < dim; ++j) mean[j] += data[i * dim + j] / double(n);
    for (std::size_t i = 0; i < n; ++i)
      sse += squared_distance(data.data() + i * dim, mean.data(), dim);
    return labels;
  }
  k = int(std::min<std::size_t>(std::size_t(k), n));
  std::vector<std::uint32_t> best;
  double best_sse = std::numeric_limits<double>::infinity();
  for (int r = 0; r < kRestarts; ++r) {
    double s = 0;
    auto labels =
        kmeans_once(data, n, dim, k, Rng::stream(seed, std::uint64_t(k), std::uint64_t(r)), s);
    if (s < best_sse) best_sse = s, best = std::move(labels);
  }
  sse = best_sse;
  return best;
}

// Pelleg & Moore (2000), X-means: identical spherical Gaussians with the pooled variance
// sigma^2 = SSE / (d (n - k)); log-likelihood sum_c n_c ln(n_c / n) - n d / 2 ln(2 pi sigma^2)
// - d (n - k) / 2, penalized by (k d + k) / 2 ln n (centres, mixing weights and the variance).
double kmeans_bic(const std::vector<double>& data, std::size_t dim,
                  const std::vector<std::uint32_t>& labels, int k) {
  const std::size_t n = labels.size();
  if (n <= std::size_t(k) || dim == 0) return -std::numeric_limits<double>::infinity();
  const auto kk = std::size_t(k);
  std::vector<double> sum(kk * dim, 0.0);
  std::vector<std::size_t> counts(kk, 0);
  for (std::size_t i = 0; i < n; ++i) {
    ++counts[labels[i]];
    for (std::size_t j = 0; j < dim; ++j) sum[labels[i] * dim + j] += data[i * dim + j];
  }
  double sse = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t c = labels[i];
    for (std::size_t j = 0; j < dim; ++j) {
      const double d = data[i * dim + j] - sum[c * dim + j] / double(counts[c]);
      sse += d * d;
    }
  }
  const double d = double(dim);
  const double var = std::max(sse / (d * double(n - kk)), 1e-6);
  double ll = 0;
  for (std::size_t c : counts) {
    if (c > 0) ll += double(c) * std::log(double(c) / double(n));
  }
  ll -= double(n) * d / 2 * std::log(2 * kPiValue * var);
  ll -= d * double(n - kk) / 2;
  const double params = double(k) * d + double(k);
  return ll - params / 2 * std::log(double(n));
}

// Mean silhouette (Rousseeuw 1987) of a labelling: for each point, (b - a) / max(a, b) with a
// its mean distance to its own cluster and b the smallest mean distance to another one.
double silhouette(const std::vector<double>& data, std::size_t dim,
                  const std::vector<std::uint32_t>& labels, int k) {
  const std::size_t n = labels.size();
  if (k < 2 || n < 3) return 0;
  std::vector<std::size_t> counts(std::size_t(k), 0);
  for (std::uint32_t l : labels) ++counts[l];
  std::vector<double> dsum(static_cast<std::size_t>(k), 0.0);
  double total = 0;
  for (std::size_t i = 0; i < n; ++i) {
    std::fill(dsum.begin(), dsum.end(), 0.0);
    for (std::size_t j = 0; j < n; ++j) {
      if (j != i)
        dsum[labels[j]] +=
            std::sqrt(squared_distance(data.data() + i * dim, data.data() + j * dim, dim));
    }
    const std::uint32_t own = labels[i];
    if (counts[own] < 2) continue;  // a singleton scores 0
    const double a = dsum[own] / double(counts[own] - 1);
    double b = std::numeric_limits<double>::infinity();
    for (int c = 0; c < k; ++c) {
      if (std::uint32_t(c) != own && counts[std::size_t(c)] > 0)
        b = std::min(b, dsum[std::size_t(c)] / double(counts[std::size_t(c)]));
    }
    const double m = std::max(a, b);
    total += m > 0 ? (b - a) / m : 0;
  }
  return total / double(n);
}

namespace {

// Below this mean silhouette a split is not taken (Kaufman & Rousseeuw: 0.5 and above is a
// reasonable structure); one cluster is then the model.
constexpr double kMinSilhouette = 0.5;
constexpr std::size_t kSilhouetteSample = 800;

int select_k(const std::vector<double>& data, std::size_t dim, int kmax, std::uint64_t seed,
             double& score) {
  // k-means on the sample, scored by silhouette on an evenly strided subsample (quadratic).
  const std::size_t n = data.size() / dim;
  const std::size_t stride = (n + kSilhouetteSample - 1) / kSilhouetteSample;
  std::vector<double> sub;
  for (std::size_t i = 0; i < n; i += stride) {
    sub.insert(sub.end(), data.begin() + std::ptrdiff_t(i * dim),
               data.begin() + std::ptrdiff_t((i + 1) * dim));
  }
  double best = kMinSilhouette;
  int best_k = 1;
  score = 0;
  for (int k = 2; k <= kmax; ++k) {
    double sse = 0;
    const auto labels = kmeans(data, dim, k, seed, sse);
    std::vector<std::uint32_t> sub_labels;
    for (std::size_t i = 0; i < n; i += stride) sub_labels.push_back(labels[i]);
    const double s = silhouette(sub, dim, sub_labels, k);
    if (s > best) best = s, best_k = k, score = s;
  }
  return best_k;
}

}  // namespace

void recluster_group(const BranchRules& rules, RuleGroup& group, int k,
                     const ClusterOptions& options) {
  const GroupData g = group_features(rules, group, options);
  double sse = 0;
  const auto labels = kmeans(g.features, g.dim, k, options.seed, sse);
  fit_group(rules, group, g, labels, k, options.branching_child_lengths);
}

bool ends_axis(const BranchRules& rules, const NodeRule& rule) {
  return rule.child_count > 0 && rules.rules[rules.begin(rule)->internode].child_count == 0;
}

std::vector<RuleGroup> cluster_rules(const BranchRules& rules, const ClusterOptions& options) {
  // A group is split by ends_axis only when both parts have kMinSplitRules rules: a rule or two
  // alone says little about how the axes end, and takes rules from the rest.
  std::map<std::tuple<std::uint16_t, std::uint32_t, bool>, std::size_t> counts;
  for (const NodeRule& r : rules.rules) {
    if (rules.internodes[r.internode].parent == kNone) continue;
    const auto order =
        std::uint16_t(std::min<int>(rules.internodes[r.internode].order, options.max_order));
    ++counts[{order, r.child_count, options.split_last && ends_axis(rules, r)}];
  }
  for (auto it = counts.begin(); it != counts.end();) {
    const auto [order, arity, last] = it->first;
    const auto other = counts.find({order, arity, !last});
    if (!last || (other != counts.end() && other->second >= kMinSplitRules &&
                  it->second >= kMinSplitRules)) {
      ++it;
      continue;
    }
    counts[{order, arity, false}] += it->second;
    it = counts.erase(it);
  }
  std::vector<RuleGroup> groups;
  for (const auto& [key, count] : counts) {
    RuleGroup group;
    group.order = std::get<0>(key);
    group.arity = std::get<1>(key);
    group.last = std::get<2>(key);
    group.split = counts.count({group.order, group.arity, !group.last}) != 0;
    group.count = count;
    const GroupData g = group_features(rules, group, options);
    const std::size_t n = g.members.size();
    int best_k = 1;
    std::vector<std::uint32_t> labels;
    if (g.dim > 0 && n >= 20 && options.max_clusters > 1) {
      // Model selection on an evenly strided sample.
      const std::size_t stride = (n + options.selection_sample - 1) / options.selection_sample;
      std::vector<double> sample;
      for (std::size_t i = 0; i < n; i += stride) {
        sample.insert(sample.end(), g.features.begin() + std::ptrdiff_t(i * g.dim),
                      g.features.begin() + std::ptrdiff_t((i + 1) * g.dim));
      }
      const std::size_t m = sample.size() / g.dim;
      const int kmax = int(std::min<std::size_t>(std::size_t(options.max_clusters), m / 10));
      double score = 0, sse = 0;
      best_k = select_k(sample, g.dim, kmax, options.seed, score);
      group.silhouette = score;
      if (best_k > 1) labels = kmeans(g.features, g.dim, best_k, options.seed, sse);
    }
    fit_group(rules, group, g, labels, best_k, options.branching_child_lengths);
    groups.push_back(std::move(group));
  }
  return groups;
}

}  // namespace ramus::skeleton_infer
