// Decompiling a grammar back to .ramus text (`ramus decompile`, docs/binary-format.md,
// Decompiling): ir::Grammar -> ast::File -> the formatter's canonical text.
//
// The result checks cleanly, `ramus fmt` leaves it unchanged (it is the formatter's own output),
// and lowering it again gives bytecode that computes the same values in the same order, so it
// derives the same string for the same seed. Expressions are rebuilt from the stack bytecode
// into trees (the short-circuit and conditional jump patterns of compiler/expr_compile.cpp back
// to `&&`, `||` and `?:`); the formatter then prints them with the fewest parentheses.
//
// What the bytecode no longer holds is chosen, not guessed: formal parameter names come from
// the stored production text when it is well formed (else p0, p1, ...); a constant from the
// pool is written as the name of a `const`/`param` only when exactly one of them has that
// value, it is not an integer, and no formal parameter of the production has that name (the
// name then compiles to the same number). Comments and the original layout are gone.
#pragma once

#include <string>

#include "compiler/ir.h"
#include "formats/rmb/rmb_codec.h"
#include "formats/rmb/rmb_decompiled_number.h"
#include "grammar/ast.h"

namespace ramus {

ast::File decompile_to_ast(const ir::Grammar& g);

// The formatted text of decompile_to_ast (grammar/format.h).
std::string decompile(const ir::Grammar& g);

// A whole .rmb: the lsystem block (none for a file built from pieces blocks alone), its
// `pieces` blocks (formats/rmb/rmb_pieces_ast.h; an embedded mesh is named by its file name in
// contents.pieces.meshes, which the caller writes beside the text), then its `voxels` blocks
// (formats/rmb/rmb_voxels.h).
std::string decompile(const RmbContents& contents);

// What a whole .rmb holds that grammar text cannot spell, for the caller to say: the
// placed-pieces stream (section 12) is a built tree, not a rule, so the text leaves it out.
// Empty when nothing is left out.
std::string decompile_left_out(const RmbContents& contents);

}  // namespace ramus
