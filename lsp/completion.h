// textDocument/completion: every name that may be written at the cursor's place in the program:
// the formal parameters of the production around it, the consts and params (with values), the
// module names, the builtin functions, the turtle symbols, the settings and the keywords; on a
// line that starts with `import`, the standard library's modules and the files beside the
// document instead. The client filters by what has been typed (the specification lets it).
#pragma once

#include <vector>

#include "lsp/analysis.h"

namespace ramus::lsp {

std::vector<CompletionItem> completion_at(const Analysis& analysis, const Position& position);

}  // namespace ramus::lsp
