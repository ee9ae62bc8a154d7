// Character-level helpers of the parser that need no Spirit: the pre-scan that runs before X3
// (text validity, comments, bracket depth), trivia skipping shared with the X3 skipper, and the
// skipping used for error recovery.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "grammar/ast.h"

namespace ramus::detail {

// Brackets ( [ { and expressions nested deeper than this are rejected with E0004: the parser
// recurses once per nested expression and later stages recurse over the AST, so the depth must
// stay far below what a stack holds. (One level of X3 recursion costs about 3 KB of stack in a
// release build and up to 25 KB under AddressSanitizer; 128 levels fit a 4 MB thread stack.)
inline constexpr int kMaxNesting = 128;

// Skips whitespace, `// line` and `/* block */` comments (an unterminated block comment runs to
// the end of the text).
const char* skip_trivia(const char* p, const char* end);
std::size_t skip_trivia(std::string_view text, std::size_t p);

struct ScanResult {
  std::vector<ast::Comment> comments;
  std::optional<std::size_t> bad_byte;              // first NUL byte or invalid UTF-8 sequence
  std::optional<std::size_t> unterminated_comment;  // offset of its `/*`
  std::optional<std::size_t> too_deep;              // offset of a `[` or `{` beyond kMaxNesting
  std::size_t start = 0;                            // 3 when the text starts with a UTF-8 BOM
};

// One pass over the text before parsing: text validity, comments, and the depth of `[` and `{`
// (parentheses are bounded by the parser itself). Strings are skipped, so `"//"` is no comment.
ScanResult prescan(std::string_view text, std::uint32_t file);

// Error recovery inside a block: from `p`, skips to just after the next `;` or to the `}` that
// closes the block (not consumed), at the nesting level of `p`; strings and comments are skipped.
std::size_t recover_in_block(std::string_view text, std::size_t p);

// Error recovery between declarations: skips past the next `;` outside braces, or past the `}`
// that closes a block opened after `p` (so a broken block header skips the whole block), or
// stops before a declaration keyword that starts a line (so a missing `;` costs one error).
std::size_t recover_at_file_level(std::string_view text, std::size_t p);

// The offset just after the last non-whitespace character before `p` (where a missing `;`
// belongs).
std::size_t end_of_previous_token(std::string_view text, std::size_t p);

// The length of the token starting at `p` (identifier, number, or one character; 0 at the end
// or at a line break), for the width of a caret.
std::size_t token_length(std::string_view text, std::size_t p);

}  // namespace ramus::detail
