#include "core/skeleton_trees.h"

namespace ramus {

Skeleton join_trees(const std::vector<Skeleton>& trees) {
  Skeleton out;
  if (!trees.empty()) out.organ_kinds = trees.front().organ_kinds;
  for (const Skeleton& t : trees) {
    const auto base = std::uint32_t(out.nodes.size());
    for (SkeletonNode n : t.nodes) {
      if (n.parent != kNoParent) n.parent += base;
      out.nodes.push_back(n);
    }
    for (OrganAnchor a : t.organs) {
      if (a.node != kNoParent) a.node += base;
      out.organs.push_back(a);
    }
  }
  return out;
}

std::vector<Skeleton> split_trees(const Skeleton& forest) {
  // The root of every node: parents may come after their children in a valid skeleton, so walk
  // up with memoization instead of relying on order.
  const auto n = std::uint32_t(forest.nodes.size());
  std::vector<std::uint32_t> root(n, kNoParent);
  std::vector<std::uint32_t> path;
  for (std::uint32_t i = 0; i < n; ++i) {
    std::uint32_t j = i;
    while (root[j] == kNoParent && forest.nodes[j].parent != kNoParent) {
      path.push_back(j);
      j = forest.nodes[j].parent;
    }
    const std::uint32_t r = root[j] == kNoParent ? j : root[j];
    root[j] = r;
    for (std::uint32_t k : path) root[k] = r;
    path.clear();
  }
  std::vector<std::uint32_t> tree_of_root(n, kNoParent), local(n, kNoParent);
  std::vector<Skeleton> trees;
  for (std::uint32_t r : forest.roots()) {
    tree_of_root[r] = std::uint32_t(trees.size());
    trees.emplace_back();
    trees.back().organ_kinds = forest.organ_kinds;
  }
  for (std::uint32_t i = 0; i < n; ++i) {
    local[i] = std::uint32_t(trees[tree_of_root[root[i]]].nodes.size());
    trees[tree_of_root[root[i]]].nodes.push_back(forest.nodes[i]);
  }
  for (Skeleton& t : trees) {
    for (SkeletonNode& node : t.nodes) {
      if (node.parent != kNoParent) node.parent = local[node.parent];
    }
  }
  for (OrganAnchor a : forest.organs) {
    if (a.node == kNoParent) continue;  // an organ on no node belongs to no tree
    Skeleton& t = trees[tree_of_root[root[a.node]]];
    a.node = local[a.node];
    t.organs.push_back(a);
  }
  return trees;
}

}  // namespace ramus
