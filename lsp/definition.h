// textDocument/definition: where the name under the cursor is defined. A formal parameter: its
// place in the pattern; a const or param: its binding (in an imported file too); a module: its
// `module` declaration, else the first production that rewrites it; an import: the file; a
// piece or rim: its declaration. Empty when there is nothing to go to (a turtle symbol with no
// production, a builtin).
#pragma once

#include <vector>

#include "lsp/analysis.h"

namespace ramus::lsp {

std::vector<Location> definition_at(const Analysis& analysis, const Position& position);

}  // namespace ramus::lsp
