// Positions in a document: byte offsets (what the front end's SourceSpans hold) to and from the
// LSP's line/character pairs. The specification counts characters in UTF-16 code units unless
// client and server agree on another encoding (`positionEncoding`, LSP 3.17); ramus offers
// UTF-8 when the client lists it, else converts. Lines end at "\n", "\r\n" or "\r", as the
// specification says.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "lsp/protocol.h"

namespace ramus::lsp {

enum class PositionEncoding { Utf16, Utf8 };

// "utf-16" or "utf-8", as the specification spells them.
const char* encoding_name(PositionEncoding e);

class LineIndex {
 public:
  LineIndex(std::string_view text, PositionEncoding encoding);

  // The position of byte `offset` (clamped to the text). An offset inside a UTF-8 sequence
  // counts as the start of that character.
  Position position(std::uint32_t offset) const;
  // The byte offset of `p`. A line past the end gives the end of the text; a character past the
  // end of its line gives the end of the line (as the specification asks); a character in the
  // middle of a surrogate pair gives the offset of that character.
  std::uint32_t offset(const Position& p) const;
  Range range(std::uint32_t begin, std::uint32_t end) const;

  std::size_t line_count() const { return starts_.size(); }

 private:
  std::uint32_t line_end(std::size_t line) const;  // before its terminator

  std::string_view text_;
  PositionEncoding encoding_;
  std::vector<std::uint32_t> starts_;  // the byte offset of each line
};

}  // namespace ramus::lsp
