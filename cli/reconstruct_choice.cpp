#include "cli/reconstruct_choice.h"

#include "reconstruct/flood/flood_skeleton.h"

namespace ramus::cli {

void add_reconstruct_choice_options(CLI::App& cmd, ReconstructChoice& choice,
                                    const std::string& method_flag, const std::string& scope) {
  cmd.add_option(method_flag, choice.method,
                 scope +
                     "bsg: branch-structure graph (Livny et al.); flood: voxel flood fill "
                     "(faster, no leaves)")
      ->check(CLI::IsMember({"bsg", "flood"}));
  cmd.add_option("--voxel", choice.voxel,
                 scope + "voxel size of the graph (default: from the data)")
      ->check(CLI::NonNegativeNumber);
}

ReconstructOptions reconstruct_options(const ReconstructChoice& choice, ReconstructOptions base) {
  base.voxel_size = choice.voxel;
  return base;
}

ReconstructResult run_reconstruction(const PointCloud& cloud, const ReconstructChoice& choice,
                                     const ReconstructOptions& base) {
  if (choice.method == "flood") {
    flood::FloodOptions fo;
    fo.voxel_size = choice.voxel;
    fo.remove_stray = base.remove_stray;
    fo.stray_cluster = base.stray_cluster;
    return flood::flood_reconstruct(cloud, fo);
  }
  return reconstruct(cloud, reconstruct_options(choice, base));
}

}  // namespace ramus::cli
