// Branch merging: lightweighting of a skeleton (thesis draft section 4.3.2, Alg. 6-7).
//
// Vertical merging (Alg. 6) removes the middle node of a chain N -> N' -> N'' when N' has exactly
// one child and the turn at N' is below alpha: N'' is re-attached to N. Horizontal merging (Alg. 7)
// replaces two leaf siblings whose directions from their parent differ by less than beta with one
// leaf at their midpoint carrying the larger radius. Both keep the skeleton a valid forest with
// parents stored before children.
#pragma once

#include <cstddef>

#include "core/skeleton.h"

namespace ramus::merge {

struct MergeOptions {
  // Vertical merge threshold (degrees): a single-child node whose turn angle is below it is
  // removed.
  double alpha_deg = 10.0;
  // Horizontal merge threshold (degrees): two leaf siblings closer than it in angle become one.
  double beta_deg = 15.0;
};

struct MergeStats {
  std::size_t nodes_before = 0, nodes_after = 0, vertical_merges = 0, horizontal_merges = 0;
};

// Merges branches of `s` in place (Alg. 6 on every root, then Alg. 7 on every root) and compacts
// the node array. Organ anchors of removed nodes move to the node that absorbed them. Angles are
// in degrees; negative or non-finite thresholds throw std::invalid_argument.
MergeStats merge_branches(Skeleton& s, const MergeOptions& o);

}  // namespace ramus::merge
