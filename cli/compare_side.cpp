#include "cli/compare_side.h"

namespace ramus::cli {

CompareSide load_compare_side(const std::string& path, const SkeletonSourceOptions& options) {
  CompareSide side;
  side.path = path;
  side.kind = source_kind(path);
  if (side.kind == SourceKind::Scan) {
    ScanSource scan = load_scan_source(path, options);
    side.cloud = std::move(scan.cloud);
    side.trees.push_back(std::move(scan.tree));
    side.labels.push_back("reconstruction");
    return side;
  }
  side.trees = load_skeleton_source(path, options);
  for (std::size_t i = 0; i < side.trees.size(); ++i) {
    side.labels.push_back(side.kind == SourceKind::Grammar
                              ? "seed " + std::to_string(options.first_seed + i)
                              : std::string("skeleton"));
  }
  return side;
}

}  // namespace ramus::cli
