// A forest as one Skeleton and back: the skeleton files of a plot (truth of a simulated scan,
// the trees of a tile, a merged forest) hold one root per tree (parent -1), and the tools that
// place, keep or match trees work on them one at a time.
#pragma once

#include <vector>

#include "core/skeleton.h"

namespace ramus {

// The trees one after another in one Skeleton: node and organ indices are shifted by the nodes
// before them; the organ kinds are the first tree's (every producer uses {"leaf"}).
Skeleton join_trees(const std::vector<Skeleton>& trees);

// One Skeleton per root, in root order; each keeps the nodes reachable from its root (in their
// order) and the organs hanging from them. Requires a valid skeleton (Skeleton::validate).
std::vector<Skeleton> split_trees(const Skeleton& forest);

}  // namespace ramus
