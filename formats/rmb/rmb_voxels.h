// `voxels` blocks (docs/language.md) <-> the voxel rule tables of an .rmb (section 11,
// docs/binary-format.md). Kept apart from the codec because it needs the grammar front end
// (the AST and constant folding), which the embeddable runtime does not link.
#pragma once

#include <vector>

#include "compiler/ir.h"
#include "formats/rmb/rmb_codec.h"
#include "grammar/ast.h"

namespace ramus {

// The `voxels` blocks of a checked file, in file order. Classes, weights and settings are
// folded with the grammar's constants (a block may write `classes N` with `const N`). Throws
// RmbError (offset 0) for what the format cannot carry: more than 256 classes, levels above
// 64, a class above 255, a weight that is not an integer in 1..2^32-1.
std::vector<RmbVoxelTable> voxel_tables_of(const ast::File& file, const ir::Grammar& g);

// The block again: settings in the order levels, classes, seed, axiom, then the rules.
ast::Voxels voxels_to_ast(const RmbVoxelTable& table);

}  // namespace ramus
