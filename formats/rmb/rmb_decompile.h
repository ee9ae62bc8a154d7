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

#include <stdexcept>
#include <string>

#include "compiler/ir.h"
#include "compiler/rmb_codec.h"
#include "grammar/ast.h"

namespace ramus {

// A grammar the language cannot express: a non-finite number, a slot no pattern binds, bytecode
// that is not in the shapes the expression compiler emits.
struct DecompileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

ast::File decompile_to_ast(const ir::Grammar& g);

// A number as the decompiled text writes it: the shortest text that reads back as the same
// double, a negative value as unary minus of its magnitude. Throws DecompileError for a value
// that is not finite.
ast::Expr decompiled_number(double v);

// The formatted text of decompile_to_ast (grammar/format.h).
std::string decompile(const ir::Grammar& g);

// A whole .rmb: the lsystem block (none for a file built from pieces blocks alone), its
// `pieces` blocks (compiler/rmb_pieces_ast.h; an embedded mesh is named by its file name in
// contents.pieces.meshes, which the caller writes beside the text), then its `voxels` blocks
// (compiler/rmb_voxels.h).
std::string decompile(const RmbContents& contents);

}  // namespace ramus
