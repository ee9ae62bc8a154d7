// `pieces` blocks (docs/pieces.md) <-> the piece-set section of an .rmb (section 10,
// docs/binary-format.md). Kept apart from the section's codec (formats/rmb/rmb_pieces.h) because it
// needs the grammar front end (the AST and constant folding), which the embeddable runtime does
// not link; and apart from backends/pieces, which builds meshes from a block: this maps the
// block as written, with its numbers folded, and never builds a piece.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "formats/rmb/rmb_pieces.h"
#include "grammar/ast.h"
#include "grammar/loader.h"

namespace ramus {

struct RmbPiecesOptions {
  // -D name=value: params as the block is lowered with (compiler/grow.h GrowOptions::defines).
  std::vector<std::pair<std::string, double>> defines;
  // Keep mesh("file") pieces as their paths instead of embedding the files: the .rmb is then
  // smaller but no longer self-contained (the files must sit where the paths point, relative
  // to the decompiled grammar).
  bool mesh_paths = false;
};

// The `pieces` blocks of the root file of a checked program, in file order. Arguments,
// weights, the rim radius, twist and depth are folded with the program's constants (imports
// first, -D for params), as backends/pieces lowers them. A mesh("file") piece's file is read
// (relative to the root file) and embedded, once per distinct file; two different files of
// one name are told apart as name_2.ext, ... Throws RmbError (offset 0) for what the section
// cannot carry: an argument a kind does not have, a rim other than hexagon, a twist outside
// 0..5, a depth outside 0..4096, a file that cannot be read, a .gltf that refers to files
// beside it (embed a .glb, or keep paths).
RmbPieces piece_sets_of(const Program& program, const std::string& root_file,
                        const RmbPiecesOptions& options = {});

// The block again, in the layout of docs/pieces.md: rim, pieces (named arguments in each kind's
// order), root, attach rules, twist, depth. An embedded mesh is referred to by its file name in
// `pieces.meshes`, which the caller writes next to the grammar (`ramus decompile` does).
ast::Pieces pieces_to_ast(const RmbPieceSet& set, const RmbPieces& pieces);

}  // namespace ramus
