#include "compiler/driver/build_binary.h"

#include <cstdio>
#include <filesystem>

#include "compiler/rmb_codec.h"
#include "compiler/rmb_paths.h"
#include "compiler/rmb_voxels.h"
#include "core/atomic_file.h"
#include "grammar/loader.h"

namespace ramus::cli {

void add_binary_build_options(CLI::App* sub, BinaryBuildArgs& args) {
  sub->add_option("--tolerance", args.tolerance,
                  "--target binary: store reals quantized within this absolute tolerance "
                  "(lossy; default: exact)")
      ->check(CLI::PositiveNumber);
  sub->add_flag("--zstd", args.zstd, "--target binary: compress the sections with zstd");
  sub->add_flag("--strip", args.strip,
                "--target binary: leave out source locations and production texts (errors "
                "then name productions by index)");
}

int build_binary(const GrowArgs& a, const BinaryBuildArgs& binary, const std::string& output,
                 bool quiet) {
  if (std::filesystem::path(output).extension() != ".rmb") {
    throw UserError("--target binary writes an .rmb file, not " + output);
  }
  std::optional<ir::Grammar> lowered = lower_for_cli(a);
  if (!lowered) return 1;
  ir::Grammar& g = *lowered;
  if (a.steps) g.settings.derive = *a.steps;
  // The same bytes from any working directory and any checkout (compiler/rmb_paths.h).
  make_locations_portable(g, a.file, default_stdlib_dirs());
  RmbEncodeOptions options;
  options.tolerance = binary.tolerance;
  options.zstd = binary.zstd;
  options.strip = binary.strip;
  // The voxels blocks of the root file go along as voxel rule tables (section 11).
  SourceManager sm;
  DiagnosticSink diags;
  const Program program = load_program(a.file, sm, diags);
  std::vector<RmbVoxelTable> voxels;
  std::string bytes;
  try {
    if (!program.files.empty()) voxels = voxel_tables_of(program.files[0], g);
    bytes = encode_rmb(g, voxels, options);
  } catch (const RmbError& e) {
    throw UserError(a.file + ": " + e.what());
  }
  write_file_atomically(output, bytes);
  if (!quiet) {
    std::fprintf(stderr, "ramus: wrote %s (%zu bytes: %zu symbols, %zu productions)\n",
                 output.c_str(), bytes.size(), g.symbols.size(), g.productions.size());
  }
  return 0;
}

}  // namespace ramus::cli
