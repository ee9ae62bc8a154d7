// textDocument/documentSymbol: the outline of the document: imports, consts, params, module
// declarations, and the blocks with their items (an lsystem's axiom and productions, a pieces
// block's rims and pieces).
#pragma once

#include <vector>

#include "lsp/analysis.h"

namespace ramus::lsp {

std::vector<DocumentSymbol> document_symbols(const Analysis& analysis);

}  // namespace ramus::lsp
