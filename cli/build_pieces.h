// `ramus build FILE --target pieces -o OUT.glb [--flatten | --gpu-instancing] [--poses K]
// [--lod N] [--wind] [--instance-buffer OUT.bin] [--preview OUT.png]`: the grammar's pieces
// block assembled into skinned piece instances (docs/pieces.md) instead of grown into a mesh.
#pragma once

#include <optional>
#include <string>

#include "backends/pieces/pieces.h"
#include "cli/grow_args.h"
#include "formats/rmb/rmb_piece_stream.h"

namespace ramus::cli {

struct PiecesBuildArgs {
  bool flatten = false;
  bool gpu_instancing = false;
  int poses = 1;  // trees of the same topology, each in its own seeded pose
  int lod = 0;    // which tessellation level the piece meshes are written at
  bool wind = false;
  std::string instance_buffer;  // also write the engine-ready instance buffer here
  std::string preview;          // also draw the posed trees into this .png/.svg
  std::string block;            // the pieces block (default: the first)
  std::string bark;             // --bark: a tile set atlas; empty for the bundled set
  int bark_edges = 2;
};

// Adds --flatten, --gpu-instancing, --poses, --wind, --instance-buffer, --preview and --pieces
// to `sub` (build's --lod is shared with the mesh target).
void add_pieces_build_options(CLI::App* sub, PiecesBuildArgs& args);

// Loads and checks the grammar, lowers its pieces block, assembles (or fits to the grown
// skeleton), poses the copies and writes the outputs. Returns the exit code: 1 after printing
// the grammar's diagnostics.
int build_pieces(const GrowArgs& grow, const PiecesBuildArgs& args, const std::string& output,
                 bool quiet);

// What build_pieces writes: the lowered set, the forest (with the poses the placed-pieces
// stream stores) and that stream. `ramus build --target binary --placed-pieces` stores the
// stream, so its expansion equals the instance buffer of a pieces build with the same
// arguments. nullopt after printing the grammar's diagnostics.
struct GrownPieces {
  pieces::PieceSet set;
  pieces::Forest forest;
  RmbPieceStream stream;
};
std::optional<GrownPieces> grow_pieces(const GrowArgs& grow, const PiecesBuildArgs& args);

}  // namespace ramus::cli
