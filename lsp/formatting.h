// textDocument/formatting: the document in the canonical layout of `ramus fmt`
// (grammar/format.h), as one edit replacing the whole text (none when it is already formatted).
// A document with syntax errors is not formatted, as `ramus fmt` leaves such a file unchanged.
#pragma once

#include <string>
#include <variant>
#include <vector>

#include "lsp/position.h"
#include "lsp/protocol.h"

namespace ramus::lsp {

struct FormatFailure {
  std::string message;
};

std::variant<std::vector<TextEdit>, FormatFailure> format_document(const std::string& name,
                                                                   const std::string& text,
                                                                   PositionEncoding encoding);

}  // namespace ramus::lsp
