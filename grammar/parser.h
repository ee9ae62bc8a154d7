// The ramus parser: source text -> ast::File (docs/language.md).
//
// Always returns an AST. Syntax errors are reported to the sink as E0003 "expected X" at the
// offending line:col; the parser then skips to the next `;` or `}` at the same nesting and
// continues, so every error of a file is reported in one run (the AST keeps what parsed).
// A file that is not UTF-8 text (NUL bytes, invalid sequences) gives E0002 and an empty AST;
// brackets or expressions nested deeper than 128 levels give E0004. An empty file parses to an
// empty File. Comments are collected into File::comments for the formatter.
#pragma once

#include <cstdint>

#include "grammar/ast.h"
#include "grammar/diagnostic.h"
#include "grammar/source.h"

namespace ramus {

ast::File parse(SourceManager& sm, std::uint32_t file_id, DiagnosticSink& diags);

}  // namespace ramus
