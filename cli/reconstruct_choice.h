// The reconstruction a subcommand runs on a scan: method (BSG of Livny et al. or the voxel flood
// fill) and voxel size. `ramus reconstruct`, `ramus infer --method skeleton` and
// `ramus compare` share these options and this code, so the same flags give the same skeleton.
#pragma once

#include <string>

#include "cli/command.h"
#include "core/point_cloud.h"
#include "reconstruct/reconstruct.h"

namespace ramus::cli {

struct ReconstructChoice {
  std::string method = "bsg";  // bsg (Livny et al.) or flood (voxel flood fill)
  double voxel = 0;            // 0: from the data
};

// Adds the method option under the name `method_flag` ("--method" for `ramus reconstruct`,
// "--reconstruct" where --method means something else) and --voxel. `scope` prefixes
// the help texts (e.g. "scans: ").
void add_reconstruct_choice_options(CLI::App& cmd, ReconstructChoice& choice,
                                    const std::string& method_flag, const std::string& scope);

// `base` with the choice applied (its voxel size).
ReconstructOptions reconstruct_options(const ReconstructChoice& choice,
                                       ReconstructOptions base = {});

// Runs the chosen method on `cloud`: reconstruct(cloud, reconstruct_options(choice, base)) for
// bsg, the flood fill with the choice's voxel size for flood. Throws ReconstructError as they do.
ReconstructResult run_reconstruction(const PointCloud& cloud, const ReconstructChoice& choice,
                                     const ReconstructOptions& base = {});

}  // namespace ramus::cli
