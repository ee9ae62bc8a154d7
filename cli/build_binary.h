// `ramus build FILE --target binary -o OUT.rmb`: the grammar compiled to the binary format
// (docs/binary-format.md) instead of grown into a mesh.
#pragma once

#include <optional>
#include <string>

#include "cli/build_pieces.h"
#include "cli/grow_args.h"

namespace ramus::cli {

// The options only --target binary reads.
struct BinaryBuildArgs {
  std::optional<double> tolerance;  // lossy: reals within this absolute tolerance
  bool zstd = false;                // compress the sections with zstd
  bool strip = false;               // leave out source locations and production texts
  bool mesh_paths = false;          // keep mesh("file") pieces as paths, not embedded files
  int version = 2;                  // the .rmb format version to write
  bool placed_pieces = false;       // also store the pieces tree as a placed-pieces stream
};

void add_binary_build_options(CLI::App* sub, BinaryBuildArgs& args);

// Lowers the grammar (-D, --seed, --system apply; -n sets the stored derivation length) and
// writes its .rmb, with the root file's `pieces` blocks (section 10) and `voxels` blocks
// (section 11). A file with pieces blocks and no lsystem block gives an .rmb whose grammar is
// empty and unnamed. Returns the exit code: 1 after printing the grammar's diagnostics.
// With --placed-pieces, also the tree the pieces block assembles (or fits), --pieces and --poses
// as for --target pieces, as a placed-pieces stream (section 12).
int build_binary(const GrowArgs& args, const BinaryBuildArgs& binary, const PiecesBuildArgs& pieces,
                 const std::string& output, bool quiet);

}  // namespace ramus::cli
