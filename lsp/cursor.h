// What the cursor is on: the innermost name of the document's AST whose span holds a byte
// offset (a constant in an expression, a module, a function, an import, a setting, a piece),
// with the production around it so that formal parameters resolve to their pattern.
#pragma once

#include <cstdint>
#include <string>

#include "grammar/ast.h"

namespace ramus::lsp {

struct CursorTarget {
  enum class Kind {
    None,
    Name,      // a constant, param or formal parameter in an expression, or a binding's name
    Module,    // a module in an axiom, successor, pattern, symbol set or module declaration
    Function,  // the callee of a call
    Import,
    Setting,  // the key of an lsystem setting
    Piece,    // a piece or rim name in a pieces block
    Block,    // the name of an lsystem, pieces or voxels block
  };
  Kind kind = Kind::None;
  std::string name;
  SourceSpan span;                              // the name's own span
  const ast::Production* production = nullptr;  // the production around a Name or Module
  const ast::Import* import = nullptr;          // Import
};

// The target at `offset`; when nothing starts there, the name that ends there (a cursor just
// after a word, as after typing it).
CursorTarget target_at(const ast::File& file, std::uint32_t offset);

// The production (rewriting, interpret or decompose) whose span holds `offset`, if any.
const ast::Production* production_at(const ast::File& file, std::uint32_t offset);

}  // namespace ramus::lsp
