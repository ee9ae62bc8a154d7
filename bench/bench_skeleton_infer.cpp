// Skeleton -> L-system inference benchmark (docs/skeleton-inference.md): extraction of the
// per-node rules (Eq. 4.11) and their clustering for a large skeleton.
//   bench_skeleton_infer [NODES] [SEED]   a random tree of NODES nodes (default 100000): chains of
//                                         1-6 segments between forks of 2-3 children
// Prints the time of each stage (best of 3 runs) and the rule counts.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "compiler/infer/skeleton/branch_rules.h"
#include "compiler/infer/skeleton/rule_clustering.h"
#include "compiler/infer/skeleton/skeleton_grammar.h"
#include "core/rng.h"

using namespace ramus;
using namespace ramus::skeleton_infer;

namespace {

// A tree grown breadth-first: every apex draws a chain of segments, then forks.
Skeleton random_tree(std::size_t nodes, std::uint64_t seed) {
  Rng rng(seed);
  Skeleton s;
  SkeletonNode root;
  root.radius = 0.3;
  s.add(root);
  struct Apex {
    std::uint32_t node;
    Vec3 dir;
    double len, radius;
  };
  std::vector<Apex> apices{{0, {0, 0, 1}, 1.0, 0.3}}, next;
  while (s.size() < nodes && !apices.empty()) {
    next.clear();
    for (const Apex& a : apices) {
      std::uint32_t n = a.node;
      const int segments = 1 + int(rng.below(6));
      for (int k = 0; k < segments && s.size() < nodes; ++k) {
        SkeletonNode c;
        c.parent = n;
        c.radius = a.radius;
        c.position = s.nodes[n].position + a.dir * (a.len / segments);
        n = s.add(c);
      }
      const int kids = 2 + int(rng.below(2));
      for (int k = 0; k < kids; ++k) {
        const Vec3 jitter{rng.normal(0, k == 0 ? 0.1 : 0.6), rng.normal(0, k == 0 ? 0.1 : 0.6),
                          rng.normal(0, 0.2)};
        next.push_back({n, normalized(a.dir + jitter), a.len * rng.uniform(0.6, 0.95),
                        a.radius * (k == 0 ? 0.8 : 0.6)});
      }
    }
    std::swap(apices, next);
  }
  return s;
}

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t nodes = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 100000;
  const std::uint64_t seed = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 1;
  const Skeleton s = random_tree(nodes, seed);
  double t_extract = 1e300, t_cluster = 1e300, t_grammar = 1e300;
  BranchRules rules;
  std::vector<RuleGroup> groups;
  InferredGrammar g;
  for (int run = 0; run < 3; ++run) {
    auto t = std::chrono::steady_clock::now();
    rules = extract_branch_rules(s);
    t_extract = std::min(t_extract, seconds_since(t));
    t = std::chrono::steady_clock::now();
    groups = cluster_rules(rules, ClusterOptions{});
    t_cluster = std::min(t_cluster, seconds_since(t));
    t = std::chrono::steady_clock::now();
    g = infer_grammar(rules, GrammarOptions{});
    t_grammar = std::min(t_grammar, seconds_since(t));
  }
  std::size_t clusters = 0;
  for (const RuleGroup& x : groups) clusters += x.clusters.size();
  std::printf("skeleton: %zu nodes, %zu internodes, %zu branch nodes\n", s.size(),
              rules.internodes.size(), g.branch_nodes);
  std::printf("extract:  %.3f s\n", t_extract);
  std::printf("cluster:  %.3f s (%zu groups, %zu clusters)\n", t_cluster, groups.size(), clusters);
  std::printf(
      "grammar (extract + cluster + budget + write): %.3f s, %zu productions, %zu alternatives\n",
      t_grammar, g.productions, g.alternatives);
  return 0;
}
