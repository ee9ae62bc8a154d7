// Skeleton sources of `ramus infer --method skeleton` and `ramus compare`: a grammar (.ramus,
// grown over several seeds), a skeleton file (.json) or a laser scan (reconstructed by the BSG
// method of Livny et al. or the voxel flood fill, reconstruct_choice.h).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cli/reconstruct_choice.h"
#include "core/point_cloud.h"
#include "core/skeleton.h"

namespace ramus::cli {

struct SkeletonSourceOptions {
  int seeds = 1;  // trees grown from a grammar: seeds first_seed, first_seed + 1, ...
  std::uint64_t first_seed = 1;
  int tree_index = -1;            // scans: the tree to use; -1: the one with the most length
  ReconstructChoice reconstruct;  // scans: how they are reconstructed
  bool quiet = false;
};

// What a path names: .ramus or a binary grammar (.rmb, sniffed) a grammar, .json a skeleton,
// anything else a scan.
enum class SourceKind { Grammar, SkeletonFile, Scan };
SourceKind source_kind(const std::string& path);

// A scan and its chosen reconstructed tree, for callers that need the points as well.
struct ScanSource {
  PointCloud cloud;
  Skeleton tree;
};
ScanSource load_scan_source(const std::string& path, const SkeletonSourceOptions& options);

// One skeleton per grown grammar seed; one for a skeleton file; the chosen tree of a scan.
// Errors (unreadable files, grammars with errors, scans without a tree) are UserErrors.
std::vector<Skeleton> load_skeleton_source(const std::string& path,
                                           const SkeletonSourceOptions& options);

}  // namespace ramus::cli
