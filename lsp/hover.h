// textDocument/hover: what the name under the cursor is. A const or param: its declaration,
// folded value and comment; a formal parameter: the pattern that binds it; a module: its
// signature, comment and productions; a turtle symbol: its meaning; a builtin function: its
// signature; a setting or keyword: its meaning; an import: the file it reads.
#pragma once

#include <optional>

#include "lsp/analysis.h"

namespace ramus::lsp {

std::optional<Hover> hover_at(const Analysis& analysis, const Position& position);

}  // namespace ramus::lsp
