// Generalizing per-node rules: the answer to the thesis draft's section 4.3.1.3.
//
// Rules of Eq. 4.11 are never exactly equal in a real tree, so one rule per node does not
// generalize, and binning the parameters into intervals gives thousands of rules. Instead the
// rules are grouped by branch order and arity (the production's shape), and inside a group they
// are clustered in (theta, phi, a, b) space by k-means, the number of clusters chosen by the
// mean silhouette (Rousseeuw 1987): the k >= 2 of largest silhouette if it reaches 0.5 (a
// reasonable structure, Kaufman & Rousseeuw), else one cluster.
// Each cluster becomes one stochastic alternative whose parameters are the cluster's fitted
// distributions; docs/skeleton-inference.md justifies the choice.
#pragma once

#include <cstdint>
#include <vector>

#include "infer/skeleton/branch_rules.h"

namespace ramus::skeleton_infer {

// A fitted one-dimensional distribution: normal(mean, sd), clamped to [min, max] when drawn.
// For the length ratio the mean may depend on the parent's log-length x:
// mean + slope (x - centre), with sd the residual spread (see fit_log_ratio in the .cpp).
struct Fitted {
  double mean = 0, sd = 0, min = 0, max = 0;
  double slope = 0, centre = 0;
  bool regression() const { return slope != 0; }
  // Values on at most two exact points: at least kAtomShare of them equal (to 1e-6) atom0 or
  // atom1, as the ratios of a grammar-grown tree do (0.7, 0.85). Drawn as atom0, or atom1 with
  // probability atom_p (0: always atom0), since a normal fitted to them cannot match them.
  bool atoms = false;
  double atom0 = 0, atom1 = 0, atom_p = 0;
};
inline constexpr double kAtomShare = 0.95;

// The azimuth is circular: mean direction and circular standard deviation sqrt(-2 ln R) (degrees);
// `uniform` when the directions are spread so evenly that a normal around a mean would mislead.
struct FittedAngle {
  double mean = 0, sd = 0;
  bool uniform = false;
};

// theta in degrees; the ratios as their natural logarithms (log-normal), so that products of
// ratios along an axis keep the observed geometric mean instead of drifting upwards.
struct ChildDistribution {
  Fitted theta, log_a, log_b;
  FittedAngle phi;
};

struct RuleCluster {
  std::size_t count = 0;                    // rules in the cluster
  std::vector<std::uint32_t> members;       // their internodes (BranchRules indices)
  std::vector<ChildDistribution> children;  // continuation first, then laterals (arity of group)
};

// The rules of one branch order (orders >= max_order pooled) and one arity.
struct RuleGroup {
  std::uint16_t order = 0;
  std::uint32_t arity = 0;
  bool last = false;   // the axis's last branch node: its continuation is a tip (split_last)
  bool split = false;  // with split_last, the group of `last` rules stands beside this one
  std::size_t count = 0;
  double silhouette = 0;  // mean silhouette of the chosen clustering (0 when k = 1)
  std::vector<RuleCluster> clusters;
};

struct ClusterOptions {
  int max_clusters = 4;                 // k is chosen by silhouette in 1..max_clusters per group
  int max_order = 3;                    // orders >= this are pooled into one group
  std::uint64_t seed = 1;               // k-means++ seeding (ramus::Rng)
  std::size_t selection_sample = 4000;  // k is selected on at most this many rules per group
  // Fit every child's length ratio on the children that branch again (their rule has children),
  // when a slot has at least kMinBranchingLengths of them. With axis budgets a tip's length is
  // what is left of its axis's budget, so the drawn length only matters for internodes that
  // carry more; pooled with the tips, a tree whose axes end in long shoots (a weeping tree's
  // whips, 5 times their parent) would draw its inner internodes far too long.
  bool branching_child_lengths = false;
  // Group the rules of the last branch node of every axis (ends_axis) apart from the others.
  // A tree's axes often end differently from how they go on: a weeping tree's thin scaffold
  // apex forks into three whips, a conifer's leader into its last whorl.
  bool split_last = false;
};
inline constexpr std::size_t kMinSplitRules = 5;
inline constexpr std::size_t kMinBranchingLengths = 3;

// k-means on rows of `data` (n x dim, row-major): k-means++ seeding, Lloyd iterations, the best
// of a few restarts. Returns the label of every row; `sse` receives the within-cluster sum of
// squares. Deterministic for a given seed.
std::vector<std::uint32_t> kmeans(const std::vector<double>& data, std::size_t dim, int k,
                                  std::uint64_t seed, double& sse);

// BIC of a k-means labelling of `data` under identical spherical Gaussians (larger is better).
// Reported for comparison; k is chosen by silhouette (see docs/skeleton-inference.md).
double kmeans_bic(const std::vector<double>& data, std::size_t dim,
                  const std::vector<std::uint32_t>& labels, int k);

// Mean silhouette of a labelling of `data` (n x dim); 0 for fewer than two clusters.
double silhouette(const std::vector<double>& data, std::size_t dim,
                  const std::vector<std::uint32_t>& labels, int k);

// True when `rule` branches and its continuation child is a tip.
bool ends_axis(const BranchRules& rules, const NodeRule& rule);

// Groups the rules by (min(order, max_order), arity, and with split_last ends_axis) and clusters
// each group. The rules of the
// internodes that start at a root are left out: the grammar's axiom writes them as observed. Groups
// are sorted by order, then arity.
std::vector<RuleGroup> cluster_rules(const BranchRules& rules, const ClusterOptions& options);

// Reclusters one group with exactly `k` clusters (used to meet a rule budget).
void recluster_group(const BranchRules& rules, RuleGroup& group, int k,
                     const ClusterOptions& options);

}  // namespace ramus::skeleton_infer
