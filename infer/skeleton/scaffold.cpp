#include "infer/skeleton/scaffold.h"

#include <algorithm>
#include <numeric>
#include <queue>
#include <utility>

namespace ramus::skeleton_infer {

namespace {

// A child continues its parent's axis only if it carries at least this share of what the
// heaviest child carries.
constexpr double kContinuationWeight = 0.5;

}  // namespace

Scaffold select_scaffold(const BranchRules& rules, const ScaffoldOptions& options) {
  Scaffold s;
  const std::size_t n = rules.internodes.size();
  s.continuation.assign(n, kNone);
  s.carried.assign(n, 0.0);
  s.in_scaffold.assign(n, 0);
  if (n == 0) return s;
  // Children before parents: by decreasing depth (ties by index, so the order is fixed).
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return rules.internodes[a].depth > rules.internodes[b].depth;
  });
  for (std::uint32_t i : order) {
    const Internode& in = rules.internodes[i];
    s.carried[i] += in.length;
    if (in.parent != kNone) s.carried[in.parent] += s.carried[i];
  }
  // An axis goes on into its straightest child among those that carry at least half as much as
  // the heaviest. The straightest alone let a conifer's trunk leave its leader for a stub the
  // reconstruction left at a whorl (the top metre became a shoot, regrown as a bush); the
  // heaviest alone makes a sideways limb the trunk's continuation and the leader its lateral,
  // so that branch_angle (scaffold_grammar.h) would turn the leader outwards.
  for (std::size_t i = 0; i < n; ++i) {
    const NodeRule& r = rules.rules[i];
    double heaviest = 0;
    for (const ChildRule* c = rules.begin(r); c != rules.end(r); ++c)
      heaviest = std::max(heaviest, s.carried[c->internode]);
    double straightest = 1e300;
    for (const ChildRule* c = rules.begin(r); c != rules.end(r); ++c) {
      if (s.carried[c->internode] < kContinuationWeight * heaviest) continue;
      if (c->theta < straightest) straightest = c->theta, s.continuation[i] = c->internode;
    }
  }
  for (std::size_t t = 1; t < rules.tree_length.size(); ++t) {
    if (rules.tree_length[t] > rules.tree_length[s.tree]) s.tree = std::uint32_t(t);
  }
  const std::uint32_t tree_id = rules.internodes[rules.tree_first[s.tree]].tree;
  for (std::uint32_t i = 0; i < n; ++i) {
    const Internode& in = rules.internodes[i];
    if (in.tree == tree_id && in.parent == kNone) s.roots.push_back(i);
  }
  // The trunk: the root internode carrying the most (a reconstructed root often has short side
  // branches beside the trunk).
  std::stable_sort(s.roots.begin(), s.roots.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return s.carried[a] > s.carried[b]; });
  for (std::uint32_t r : s.roots) s.tree_length += s.carried[r];

  // Largest-first growth of the scaffold from the trunk axis.
  using Candidate = std::pair<double, std::uint32_t>;  // carried length, first internode
  auto smaller = [](const Candidate& a, const Candidate& b) {
    return a.first < b.first || (a.first == b.first && a.second > b.second);
  };
  std::priority_queue<Candidate, std::vector<Candidate>, decltype(smaller)> candidates(smaller);
  auto take_axis = [&](std::uint32_t first) {
    ++s.axes;
    for (std::uint32_t i = first; i != kNone; i = s.continuation[i]) {
      s.in_scaffold[i] = 1;
      const NodeRule& r = rules.rules[i];
      for (const ChildRule* c = rules.begin(r); c != rules.end(r); ++c) {
        if (c->internode != s.continuation[i])
          candidates.push({s.carried[c->internode], c->internode});
      }
    }
  };
  take_axis(s.roots.front());
  for (std::size_t k = 1; k < s.roots.size(); ++k)
    candidates.push({s.carried[s.roots[k]], s.roots[k]});
  const double least = options.min_share * s.tree_length;
  while (!candidates.empty() && s.axes < options.max_axes) {
    const Candidate c = candidates.top();
    candidates.pop();
    if (c.first < least) break;
    take_axis(c.second);
  }
  return s;
}

}  // namespace ramus::skeleton_infer
