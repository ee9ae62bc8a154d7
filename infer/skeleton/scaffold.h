// The scaffold of a tree: its trunk and the limbs that carry a noticeable share of its length.
//
// A grammar inferred from one tree should regrow *that* tree: its height, its lean, its crown
// outline, where its main limbs go. Statistics of internodes cannot say where the limbs are, so
// the scaffold is kept as measured (the inferred grammar's axiom draws it) and only what hangs
// from it -- the finer shoots -- grows from species-level rules. Each axis is a chain of
// continuation internodes (each the child that carries the most); a lateral axis joins the
// scaffold when the internodes it carries (its subtree) hold at least `min_share` of the tree's
// length, the largest first, until `max_axes` axes are taken.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "infer/skeleton/branch_rules.h"

namespace ramus::skeleton_infer {

struct ScaffoldOptions {
  double min_share = 0.01;      // share of the tree's length a lateral axis must carry
  std::size_t max_axes = 1000;  // axes in the scaffold, the trunk included
};

struct Scaffold {
  std::uint32_t tree = 0;            // the tree (index into rules.tree_first) with most length
  std::vector<std::uint32_t> roots;  // the tree's root internodes, the trunk first
  std::vector<std::uint32_t> continuation;  // per internode: its continuation child, or kNone
  std::vector<double> carried;    // per internode: path length of it and of all it carries
  std::vector<char> in_scaffold;  // per internode: drawn as measured
  std::size_t axes = 0;
  double tree_length = 0;
};

Scaffold select_scaffold(const BranchRules& rules, const ScaffoldOptions& options = {});

}  // namespace ramus::skeleton_infer
