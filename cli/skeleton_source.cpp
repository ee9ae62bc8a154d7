#include "cli/skeleton_source.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "cli/command.h"
#include "cli/grow_args.h"
#include "formats/point_cloud_io.h"
#include "formats/skeleton_json.h"
#include "reconstruct/reconstruct.h"

namespace ramus::cli {

namespace {

std::vector<Skeleton> grow_seeds(const std::string& path, const SkeletonSourceOptions& o) {
  std::vector<Skeleton> out;
  for (int s = 0; s < std::max(o.seeds, 1); ++s) {
    GrowArgs args;
    args.file = path;
    args.seed = o.first_seed + std::uint64_t(s);
    std::optional<Skeleton> sk = grow_for_cli(args);
    if (!sk) throw UserError(path + " has errors");
    out.push_back(std::move(*sk));
  }
  return out;
}

}  // namespace

ScanSource load_scan_source(const std::string& path, const SkeletonSourceOptions& o) {
  ScanSource out;
  PointCloud& cloud = out.cloud;
  try {
    cloud = read_point_cloud(path);
  } catch (const FormatError& e) {
    throw UserError(e.what());
  }
  ReconstructOptions ro;
  ro.leaves = false;
  ReconstructResult r;
  try {
    r = run_reconstruction(cloud, o.reconstruct, ro);
  } catch (const ReconstructError& e) {
    throw UserError(path + ": " + e.what());
  }
  if (r.trees.empty()) {
    throw UserError(path + ": " + (r.notes.empty() ? "no tree found" : r.notes.back()));
  }
  std::size_t pick = 0;
  if (o.tree_index >= 0) {
    if (std::size_t(o.tree_index) >= r.trees.size()) {
      throw UserError(path + ": --tree-index " + std::to_string(o.tree_index) +
                      " but the scan has " + std::to_string(r.trees.size()) + " tree(s)");
    }
    pick = std::size_t(o.tree_index);
  } else {
    for (std::size_t t = 1; t < r.trees.size(); ++t) {
      if (r.trees[t].total_length() > r.trees[pick].total_length()) pick = t;
    }
  }
  if (!o.quiet) {
    std::fprintf(stderr, "ramus: %s: tree %zu of %zu (%zu nodes) reconstructed (%s) in %.2f s\n",
                 path.c_str(), pick, r.trees.size(), r.trees[pick].size(),
                 o.reconstruct.method.c_str(), r.timings.total);
  }
  out.tree = std::move(r.trees[pick]);
  return out;
}

SourceKind source_kind(const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  if (ext == ".ramus" || ext == ".rmb" || is_binary_grammar(path)) return SourceKind::Grammar;
  if (ext == ".json") return SourceKind::SkeletonFile;
  return SourceKind::Scan;
}

std::vector<Skeleton> load_skeleton_source(const std::string& path,
                                           const SkeletonSourceOptions& options) {
  const SourceKind kind = source_kind(path);
  if (kind == SourceKind::Grammar) return grow_seeds(path, options);
  if (kind == SourceKind::SkeletonFile) {
    try {
      return {read_skeleton_json(path)};
    } catch (const FormatError& e) {
      throw UserError(e.what());
    }
  }
  return {load_scan_source(path, options).tree};
}

}  // namespace ramus::cli
