// The methods of `ramus infer`. cmd_infer.cpp owns the subcommand and the options every method
// shares; each method adds its own options to the same subcommand and returns what to run.
// Option names must not clash between methods (CLI11 rejects a duplicate when the CLI starts).
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "cli/command.h"

namespace ramus::cli {

struct InferCommonArgs {
  std::string input;   // a scan (.ply .xyz .txt .asc .las .pcd) or, where a method allows, a skeleton
  std::string output;  // the .ramus file to write (atomically)
  std::string method;  // "wavelet" or "skeleton"
  std::uint64_t seed = 1;
};

using InferRunner = std::function<int(const InferCommonArgs&)>;

// Friedman & Stamos 2013: voxel grammar and L-rules from the wavelet progression (infer_wavelet.cpp).
InferRunner add_infer_wavelet_options(CLI::App& cmd, const GlobalOptions& global);
// Skeleton -> clustered parametric L-system (infer_skeleton.cpp).
InferRunner add_infer_skeleton_options(CLI::App& cmd, const GlobalOptions& global);

}  // namespace ramus::cli
