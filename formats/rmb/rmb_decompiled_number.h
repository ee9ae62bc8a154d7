// Numbers as decompiled .ramus text writes them, and the error of text the language cannot
// spell. Shared by the lsystem decompiler (rmb_decompile.cpp) and the pieces section's
// decompiler (rmb_pieces_ast.cpp), which both build ast::Expr numbers from stored doubles.
#pragma once

#include <stdexcept>

#include "grammar/ast.h"

namespace ramus {

// A grammar the language cannot express: a non-finite number, a slot no pattern binds, bytecode
// that is not in the shapes the expression compiler emits.
struct DecompileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A number as the decompiled text writes it: the shortest text that reads back as the same
// double, a negative value as unary minus of its magnitude (literals have no sign). Throws
// DecompileError for a value that is not finite.
ast::Expr decompiled_number(double v);

}  // namespace ramus
