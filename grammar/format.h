// The canonical layout of .ramus files (docs/formatting.md): what `ramus fmt` writes.
// Idempotent (format(parse(format(x))) == format(x)), keeps every comment, and never changes the
// AST (parse(format(x)) == parse(x) under ast::File::operator==).
#pragma once

#include <string>

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

}  // namespace ramus
