// The canonical layout of .ramus files (docs/formatting.md): what `ramus fmt` writes.
// Idempotent (format(parse(format(x))) == format(x)), keeps every comment, and never changes the
// AST (parse(format(x)) == parse(x) under ast::File::operator==).
#pragma once

#include <string>
#include <vector>

#include "grammar/ast.h"
#include "grammar/source.h"

namespace ramus {

// Formats a parsed file. `sources` holds its text (file.file_id), used for the comments'
// places and the blank lines between declarations.
std::string format_file(const ast::File& file, const SourceManager& sources);

// Formats a file that has no source text (e.g. a grammar built by inference): no comments;
// blocks are set apart by blank lines.
std::string format_file(const ast::File& file);

// One expression, with the fewest parentheses its structure needs plus those written.
std::string format_expr(const ast::Expr& expr);

// A module sequence laid out as `ramus fmt` lays out axioms and successors: modules on one line
// up to column 100, continuation lines indented by 8; `[` sticks to the module after it and `]`
// to the module before it; a line that would overflow breaks before its last `[`, else before
// the module that does not fit. `prefix` is the text before the first module (a space follows
// it when there is one), `suffix` follows the last; the result ends with a newline. Inference
// writes productions with it directly, without parsing them again (wrap_modules.cpp).
std::string wrap_modules(const std::string& prefix, const std::vector<std::string>& modules,
                         const std::string& suffix);

}  // namespace ramus
