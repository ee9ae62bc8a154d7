// The file an `import` names, found as the loader finds it (grammar/loader.h): a quoted path
// relative to the importing file, or a.b as <stdlib>/a/b.ramus in the first stdlib directory
// that has it. Go-to-definition and hover use it to name the file.
#pragma once

#include <optional>
#include <string>

#include "grammar/ast.h"

namespace ramus::lsp {

// The normalized path of the imported file, or nullopt when it does not exist.
std::optional<std::string> resolve_import(const ast::Import& import, const std::string& importer);

}  // namespace ramus::lsp
