// Skeleton reconstruction of a leafy scan: the foliage found by separate_wood() is removed before
// the pipeline of Livny et al. 2010 runs, which assumes wood points (docs/wood-separation.md).
#pragma once

#include "reconstruct/reconstruct.h"

namespace ramus {

// reconstruct() for options.leaves_in_scan = kRemove or kAuto: separates the cloud, reconstructs
// its wood points (or, for kAuto when fewer than WoodOptions::auto_leaf_fraction of them are
// leaf, all points), and maps the segmentation back to every input point (leaf points belong to
// no tree). A note says how many points were removed and why.
ReconstructResult reconstruct_without_leaves(const PointCloud& cloud,
                                             const ReconstructOptions& options);

}  // namespace ramus
