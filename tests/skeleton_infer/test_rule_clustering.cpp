// Clustering of per-node rules: planted clusters are recovered, one cluster is not split, the
// fitted distributions match the planted ones; k-means and BIC on their own.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "core/rng.h"
#include "infer/skeleton/rule_clustering.h"

using namespace ramus;
using namespace ramus::skeleton_infer;

namespace {

struct Planted {
  double theta0, phi0, a0, b0;  // continuation
  double theta1, phi1, a1, b1;  // lateral
  std::size_t count;
};

// Rules of arity 2 at order 0 drawn around the planted centres (sd 2 degrees, 0.02 in ratios).
BranchRules plant(const std::vector<Planted>& clusters, std::uint64_t seed) {
  Rng rng(seed);
  BranchRules r;
  auto add_internode = [&](std::uint32_t parent, bool cont, std::uint16_t order) {
    Internode in;
    in.parent = parent;
    in.continuation = cont;
    in.order = order;
    in.length = 1;
    r.internodes.push_back(in);
    r.rules.push_back({});
    return std::uint32_t(r.internodes.size() - 1);
  };
  std::vector<std::pair<std::uint32_t, std::array<ChildRule, 2>>> made;
  // A root internode: the rules planted below hang from it (root rules are not clustered).
  const std::uint32_t root = add_internode(kNone, false, 0);
  for (const Planted& p : clusters) {
    for (std::size_t k = 0; k < p.count; ++k) {
      const std::uint32_t parent = add_internode(root, true, 0);
      const std::uint32_t c0 = add_internode(parent, true, 0);
      const std::uint32_t c1 = add_internode(parent, false, 1);
      ChildRule x{rng.normal(p.theta0, 2), std::fmod(rng.normal(p.phi0, 2) + 360, 360),
                  rng.normal(p.a0, 0.02), rng.normal(p.b0, 0.02), c0};
      ChildRule y{rng.normal(p.theta1, 2), std::fmod(rng.normal(p.phi1, 2) + 360, 360),
                  rng.normal(p.a1, 0.02), rng.normal(p.b1, 0.02), c1};
      made.push_back({parent, {x, y}});
    }
  }
  for (auto& [parent, kids] : made) {
    r.rules[parent].child_begin = std::uint32_t(r.children.size());
    r.rules[parent].child_count = 2;
    r.children.push_back(kids[0]);
    r.children.push_back(kids[1]);
  }
  for (std::uint32_t i = 0; i < r.rules.size(); ++i) {
    r.rules[i].internode = i;
    if (r.rules[i].child_count == 0) r.rules[i].child_begin = std::uint32_t(r.children.size());
  }
  return r;
}

const RuleGroup& group(const std::vector<RuleGroup>& g, std::uint16_t order, std::uint32_t arity) {
  for (const RuleGroup& x : g) {
    if (x.order == order && x.arity == arity) return x;
  }
  FAIL("no group " << order << "/" << arity);
  return g.front();
}

}  // namespace

TEST_CASE("clustering: recovers three planted clusters over many seeds", "[skeleton_infer]") {
  const std::vector<Planted> planted = {
      {5, 180, 0.9, 0.85, 40, 90, 0.5, 0.5, 300},
      {15, 0, 0.7, 0.7, 70, 270, 0.3, 0.4, 200},
      {2, 90, 0.95, 0.9, 25, 200, 0.8, 0.6, 100},
  };
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    const BranchRules r = plant(planted, seed);
    ClusterOptions o;
    o.max_clusters = 6;
    o.seed = seed;
    const auto groups = cluster_rules(r, o);
    const RuleGroup& g = group(groups, 0, 2);
    CHECK(g.clusters.size() == 3);
    if (g.clusters.size() != 3) continue;
    CHECK(g.silhouette > 0.5);
    // Sorted by count: 300, 200, 100, each with its planted means.
    for (std::size_t k = 0; k < 3; ++k) {
      const RuleCluster& c = g.clusters[k];
      CHECK(c.count == planted[k].count);
      CHECK(c.children[0].theta.mean == Approx(planted[k].theta0).margin(0.6));
      CHECK(c.children[1].theta.mean == Approx(planted[k].theta1).margin(0.6));
      CHECK(c.children[1].theta.sd == Approx(2).margin(0.5));
      CHECK(std::exp(c.children[1].log_a.mean) == Approx(planted[k].a1).margin(0.01));
      CHECK(std::exp(c.children[1].log_b.mean) == Approx(planted[k].b1).margin(0.01));
      const double dphi = std::abs(std::remainder(c.children[1].phi.mean - planted[k].phi1, 360));
      CHECK(dphi < 1);
      CHECK(c.children[1].phi.sd == Approx(2).margin(0.5));
      CHECK_FALSE(c.children[1].phi.uniform);
    }
    // The tips (arity 0) are one group of their own per order.
    CHECK(group(groups, 0, 0).clusters.size() == 1);
  }
}

TEST_CASE("clustering: one planted cluster is not split", "[skeleton_infer]") {
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    const BranchRules r = plant({{10, 30, 0.8, 0.8, 50, 120, 0.5, 0.5, 400}}, seed);
    ClusterOptions o;
    o.max_clusters = 6;
    o.seed = seed;
    const auto groups = cluster_rules(r, o);
    const RuleGroup& g = group(groups, 0, 2);
    CHECK(g.clusters.size() == 1);
    CHECK(g.clusters[0].count == 400);
  }
}

TEST_CASE("clustering: azimuths spread around the circle fit as uniform", "[skeleton_infer]") {
  std::vector<Planted> ring;
  for (int k = 0; k < 12; ++k) ring.push_back({5, 0, 0.9, 0.9, 45, 30.0 * k, 0.5, 0.5, 30});
  const BranchRules r = plant(ring, 3);
  ClusterOptions o;
  o.max_clusters = 1;
  const auto groups = cluster_rules(r, o);
  const RuleGroup& g = group(groups, 0, 2);
  REQUIRE(g.clusters.size() == 1);
  CHECK(g.clusters[0].children[1].phi.uniform);
  // A circle-crossing cluster has its mean near 0, not near 180.
  const BranchRules r2 = plant({{5, 90, 0.9, 0.9, 45, 359.5, 0.5, 0.5, 200}}, 4);
  const auto groups2 = cluster_rules(r2, o);
  const RuleGroup& g2 = group(groups2, 0, 2);
  const double m = g2.clusters[0].children[1].phi.mean;
  CHECK(std::min(m, 360 - m) < 1.5);
}

TEST_CASE("clustering: k-means is deterministic and BIC prefers the true k", "[skeleton_infer]") {
  Rng rng(11);
  std::vector<double> data;
  for (int c = 0; c < 4; ++c) {
    for (int i = 0; i < 100; ++i) {
      data.push_back(10.0 * c + rng.normal(0, 1));
      data.push_back(-5.0 * c + rng.normal(0, 1));
    }
  }
  double sse1 = 0, sse2 = 0;
  const auto l1 = kmeans(data, 2, 4, 5, sse1);
  const auto l2 = kmeans(data, 2, 4, 5, sse2);
  CHECK(l1 == l2);
  CHECK(sse1 == sse2);
  // Every planted block has one label.
  for (int c = 0; c < 4; ++c) {
    for (int i = 1; i < 100; ++i) CHECK(l1[std::size_t(c * 100 + i)] == l1[std::size_t(c * 100)]);
  }
  int best = 0;
  double best_bic = -1e300;
  for (int k = 1; k <= 7; ++k) {
    double sse = 0;
    const auto lab = kmeans(data, 2, k, 5, sse);
    const double bic = kmeans_bic(data, 2, lab, k);
    if (bic > best_bic) best_bic = bic, best = k;
  }
  CHECK(best == 4);
  // Fewer points than clusters: no crash, every point labelled.
  double sse = 0;
  const std::vector<double> two = {0, 0, 1, 1};
  CHECK(kmeans(two, 2, 5, 1, sse).size() == 2);
}
