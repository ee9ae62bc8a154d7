// One side of `ramus compare`, loaded once and shared by the branch statistics, the shape
// measures and the picture: its trees with a label each, and for a scan its points as well.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cli/skeleton_source.h"
#include "core/point_cloud.h"
#include "core/skeleton.h"

namespace ramus::cli {

struct CompareSide {
  std::string path;
  SourceKind kind = SourceKind::Scan;
  std::vector<Skeleton> trees;
  std::vector<std::string> labels;  // per tree: "seed 3", "skeleton" or "reconstruction"
  std::optional<PointCloud> cloud;  // scans only
};

// Grammars grow options.seeds trees, a skeleton file is one tree, a scan is read and
// reconstructed. Errors are UserErrors.
CompareSide load_compare_side(const std::string& path, const SkeletonSourceOptions& options);

}  // namespace ramus::cli
